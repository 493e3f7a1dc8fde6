#include "common/worker_pool.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include <unistd.h>

namespace tessera::worker_pool {
namespace {

std::atomic<size_t> workerParts{0};  // partsRunByWorkers()

// One runParts call: its parts are handed out one at a time under the pool's lock.
struct Job {
  const std::function<void(unsigned)>* body;
  unsigned parts;
  unsigned nextPart = 1;  // part 0 is the caller's
  unsigned finished = 0;
  std::condition_variable allFinished;
};

class Pool {
 public:
  // Never destroyed: its workers sleep until the process ends. Destroying the condition
  // variable at exit would wait for its waiters, which in a forked child never come.
  static Pool& instance() {
    static Pool* pool = new Pool;
    return *pool;
  }

  void run(unsigned parts, const std::function<void(unsigned)>& body) {
    // A forked child must not touch the lock or the condition variable, whose waiters are
    // the parent's threads: its calls run every part themselves.
    if (::getpid() != owner_) {
      for (unsigned part = 0; part < parts; ++part) body(part);
      return;
    }
    Job job{&body, parts};
    {
      std::lock_guard<std::mutex> lock(mutex_);
      startWorkers(parts - 1);
      jobs_.push_back(&job);
    }
    // One wake per part offered: a worker that finds them all taken sleeps again.
    for (unsigned k = 1; k < parts; ++k) wake_.notify_one();
    body(0);
    std::unique_lock<std::mutex> lock(mutex_);
    // Parts no worker has taken yet are the caller's: it never waits for a sleeping thread.
    while (job.nextPart < parts) {
      const unsigned part = take(job);
      lock.unlock();
      body(part);
      lock.lock();
      ++job.finished;
    }
    // Workers notify under the lock, so the job outlives every touch of it.
    job.allFinished.wait(lock, [&] { return job.finished + 1 == parts; });
  }

 private:
  // Up to `wanted` workers in all, at most one fewer than the hardware threads (the caller
  // is one). A thread that cannot start leaves its parts to the caller.
  void startWorkers(unsigned wanted) {
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    wanted = std::min(wanted, hardware - 1);
    while (workers_.size() < wanted) {
      try {
        workers_.emplace_back([this] { work(); });
      } catch (...) {
        return;
      }
    }
  }

  // The job's next part, under the lock; a job leaves the queue with its last part, so every
  // job in it has a part to give.
  unsigned take(Job& job) {
    const unsigned part = job.nextPart++;
    if (job.nextPart == job.parts) jobs_.erase(std::find(jobs_.begin(), jobs_.end(), &job));
    return part;
  }

  void work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return !jobs_.empty(); });
      Job& job = *jobs_.front();
      const unsigned part = take(job);
      lock.unlock();
      (*job.body)(part);
      workerParts.fetch_add(1, std::memory_order_relaxed);
      lock.lock();
      if (++job.finished + 1 == job.parts) job.allFinished.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Job*> jobs_;  // the jobs with parts not yet taken, oldest first
  std::vector<std::thread> workers_;
  const pid_t owner_ = ::getpid();  // the process whose threads workers_ are
};

}  // namespace

void runParts(unsigned parts, const std::function<void(unsigned part)>& body) {
  if (parts == 0) return;
  if (parts == 1) return body(0);
  Pool::instance().run(parts, body);
}

size_t partsRunByWorkers() { return workerParts.load(std::memory_order_relaxed); }

}  // namespace tessera::worker_pool
