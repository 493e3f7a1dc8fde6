// Temp file + fsync + rename, on POSIX file descriptors: std::ofstream cannot fsync, and
// errno must be captured at the failing call to say why.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <filesystem>
#include <memory>
#include <streambuf>
#include <system_error>

#include "io/errors.h"
#include "io/pending_temp_files.h"

namespace tessera {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void ioFail(const std::string& path, const std::string& what, int err) {
  std::string reason = what;
  if (err != 0) reason += ": " + std::generic_category().message(err);
  throw InputError(InputErrorKind::Io, path, 0, reason);
}

// A stream buffer over a file descriptor that remembers the errno of the first failed write,
// so the caller can say why (a bare ostream only reports badbit).
class FdStreamBuf : public std::streambuf {
 public:
  explicit FdStreamBuf(int fd) : fd_(fd), buffer_(new char[kBufferSize]) {
    setp(buffer_.get(), buffer_.get() + kBufferSize);
  }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }

  int sync() override { return drain() ? 0 : -1; }

  std::streamsize xsputn(const char* data, std::streamsize n) override {
    // Large blocks (a binary vertex array) go straight to the file instead of through the buffer.
    if (n < kBufferSize) return std::streambuf::xsputn(data, n);
    if (!drain() || !writeAll(data, static_cast<size_t>(n))) return 0;
    return n;
  }

 private:
  static constexpr std::streamsize kBufferSize = 1 << 16;

  bool drain() {
    bool ok = writeAll(pbase(), static_cast<size_t>(pptr() - pbase()));
    setp(buffer_.get(), buffer_.get() + kBufferSize);
    return ok;
  }

  bool writeAll(const char* data, size_t n) {
    if (error_ != 0) return false;
    while (n > 0) {
      ssize_t written = ::write(fd_, data, n);
      if (written < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        return false;
      }
      data += written;
      n -= static_cast<size_t>(written);
    }
    return true;
  }

  int fd_;
  int error_ = 0;
  std::unique_ptr<char[]> buffer_;
};

struct TempFile {
  std::string path;
  int fd = -1;
  int slot = -1;  // in the pending temp file table
};

// `path` with symbolic links at its end followed (up to 40, as the kernel's ELOOP limit), also
// a dangling one: writing a file through a link writes its target and keeps the link.
fs::path followLinks(const fs::path& path) {
  fs::path p = path;
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(p, ec); ++hops) {
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) break;
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  return p;
}

// O_EXCL makes the name ours alone; pid + a process-wide counter keeps collisions rare, and a
// stale file left by a crashed process with a recycled pid just moves us to the next number.
TempFile createTempNextTo(const std::string& path, const fs::path& target, const fs::path& dir) {
  static std::atomic<unsigned long> counter{0};
  // Keep the name within NAME_MAX (255) even for very long target names.
  std::string stem = target.filename().string().substr(0, 200);
  for (int attempt = 0; attempt < 100; ++attempt) {
    fs::path candidate = dir / ("." + stem + ".tmp-" + std::to_string(::getpid()) + "-" +
                                std::to_string(counter.fetch_add(1)));
    // Registered before it exists: a signal between open() and a later registration (a
    // preempted process under load) left the file behind. A signal before open() unlinks a
    // name that is not there, or a stale file of a recycled pid: no harm either way.
    const int slot = registerPendingTempFile(candidate.c_str());
    int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {candidate.string(), fd, slot};
    const int err = errno;
    forgetPendingTempFile(slot);
    if (err != EEXIST)
      ioFail(path, "cannot create a temporary file in directory '" + dir.string() + "'", err);
  }
  ioFail(path,
         "cannot find an unused temporary file name in directory '" + dir.string() + "'", EEXIST);
}

// rename() replaces the inode, so carry the old file's permission bits over explicitly.
void keepPermissions(const std::string& path, const std::string& target, int fd) {
  struct stat st;
  if (::stat(target.c_str(), &st) == 0 && S_ISREG(st.st_mode))
    if (::fchmod(fd, st.st_mode & 07777) != 0) ioFail(path, "cannot set permissions", errno);
}

// Makes the rename itself durable. Best effort: the new file is already in place, and some
// file systems refuse fsync on directories.
void syncDirectory(const fs::path& dir) {
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

namespace {

fs::path directoryOf(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

fs::path checkedTarget(const std::string& path) {
  const fs::path target = followLinks(fs::path(path));
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == "..")
    ioFail(path, "names a directory, not a file", 0);
  std::error_code ec;
  if (fs::is_directory(target, ec)) ioFail(path, "is a directory, not a file", 0);
  return target;
}

void removeTemp(TempFile& temp) {
  if (temp.fd >= 0) ::close(temp.fd);
  temp.fd = -1;
  ::unlink(temp.path.c_str());
  forgetPendingTempFile(temp.slot);
}

// Writes `writer`'s bytes into a new temporary file next to `target`, flushed to disk and
// closed; the caller renames it. On failure the temporary is gone and the error propagates.
TempFile writeTemp(const std::string& path, const fs::path& target,
                   const std::function<void(std::ostream&)>& writer) {
  TempFile temp = createTempNextTo(path, target, directoryOf(target));
  try {
    {
      FdStreamBuf buffer(temp.fd);
      std::ostream out(&buffer);
      writer(out);
      out.flush();
      if (buffer.error() != 0)
        ioFail(path, "cannot write temporary file '" + temp.path + "'", buffer.error());
      if (!out) ioFail(path, "the output stream failed while writing", 0);
    }
    keepPermissions(path, target.string(), temp.fd);
    if (::fsync(temp.fd) != 0)
      ioFail(path, "cannot flush temporary file '" + temp.path + "' to disk", errno);
    const int fd = temp.fd;
    temp.fd = -1;
    // close() can report a deferred write error (NFS, quotas): it must be checked too.
    if (::close(fd) != 0) ioFail(path, "cannot close temporary file '" + temp.path + "'", errno);
  } catch (...) {
    removeTemp(temp);
    throw;
  }
  return temp;
}

void renameOver(const std::string& path, TempFile& temp, const fs::path& target) {
  if (::rename(temp.path.c_str(), target.c_str()) != 0) {
    const int err = errno;
    removeTemp(temp);
    ioFail(path, "cannot rename temporary file '" + temp.path + "' over it", err);
  }
  forgetPendingTempFile(temp.slot);
  syncDirectory(directoryOf(target));
}

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer) {
  const fs::path target = checkedTarget(path);
  TempFile temp = writeTemp(path, target, writer);
  renameOver(path, temp, target);
}

AtomicFileGroup::~AtomicFileGroup() {
  for (Staged& s : staged_) {
    ::unlink(s.temp.c_str());
    forgetPendingTempFile(s.slot);
  }
}

void AtomicFileGroup::stage(const std::string& path,
                            const std::function<void(std::ostream&)>& writer) {
  const fs::path target = checkedTarget(path);
  TempFile temp = writeTemp(path, target, writer);
  staged_.push_back({path, target.string(), temp.path, temp.slot});
}

void AtomicFileGroup::commit() {
  while (!staged_.empty()) {
    Staged s = staged_.front();
    staged_.erase(staged_.begin());
    TempFile temp{s.temp, -1, s.slot};
    renameOver(s.path, temp, fs::path(s.target));
  }
}

void validateWritable(const std::string& path) {
  const fs::path target = checkedTarget(path);
  TempFile probe = createTempNextTo(path, target, directoryOf(target));
  removeTemp(probe);
}

}  // namespace tessera
