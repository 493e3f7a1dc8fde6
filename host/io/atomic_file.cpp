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
};

// O_EXCL makes the name ours alone; pid + a process-wide counter keeps collisions rare, and a
// stale file left by a crashed process with a recycled pid just moves us to the next number.
TempFile createTempNextTo(const fs::path& target, const fs::path& dir) {
  static std::atomic<unsigned long> counter{0};
  // Keep the name within NAME_MAX (255) even for very long target names.
  std::string stem = target.filename().string().substr(0, 200);
  for (int attempt = 0; attempt < 100; ++attempt) {
    fs::path candidate = dir / ("." + stem + ".tmp-" + std::to_string(::getpid()) + "-" +
                                std::to_string(counter.fetch_add(1)));
    int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {candidate.string(), fd};
    if (errno != EEXIST)
      ioFail(target.string(), "cannot create a temporary file in directory '" + dir.string() + "'",
             errno);
  }
  ioFail(target.string(),
         "cannot find an unused temporary file name in directory '" + dir.string() + "'", EEXIST);
}

// rename() replaces the inode, so carry the old file's permission bits over explicitly.
void keepPermissions(const std::string& target, int fd) {
  struct stat st;
  if (::stat(target.c_str(), &st) == 0 && S_ISREG(st.st_mode))
    if (::fchmod(fd, st.st_mode & 07777) != 0) ioFail(target, "cannot set permissions", errno);
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

void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer) {
  const fs::path target(path);
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == "..")
    ioFail(path, "names a directory, not a file", 0);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");

  TempFile temp = createTempNextTo(target, dir);
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
    keepPermissions(path, temp.fd);
    if (::fsync(temp.fd) != 0)
      ioFail(path, "cannot flush temporary file '" + temp.path + "' to disk", errno);
    const int fd = temp.fd;
    temp.fd = -1;
    // close() can report a deferred write error (NFS, quotas): it must be checked too.
    if (::close(fd) != 0) ioFail(path, "cannot close temporary file '" + temp.path + "'", errno);
    if (::rename(temp.path.c_str(), path.c_str()) != 0)
      ioFail(path, "cannot rename temporary file '" + temp.path + "' over it", errno);
  } catch (...) {
    if (temp.fd >= 0) ::close(temp.fd);
    ::unlink(temp.path.c_str());
    throw;
  }
  syncDirectory(dir);
}

}  // namespace tessera
