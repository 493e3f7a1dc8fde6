// Write a whole output file or nothing, so a crash, a full disk or an exception in the middle
// of writing a mesh never leaves a half-written file where a good one (or none) was before.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

// Calls `writer` with a stream into a fresh temporary file in the directory of `path`
// (".<name>.tmp-<pid>-<n>", created exclusively, so concurrent writers never share one),
// then flushes and fsyncs it and renames it over `path`. rename() within one directory is
// atomic on POSIX: readers see the old file or the new one, never a mixture.
//
// - The stream is binary (no newline translation) and serves text and binary formats alike.
// - If `writer` throws, its exception propagates unchanged; the temporary file is removed and
//   `path` is untouched.
// - Any I/O failure (directory missing or not writable, write error, disk full, fsync or
//   rename failing), and a writer leaving the stream in a failed state, removes the temporary
//   file and throws InputError (kind Io, host/io/errors.h) naming `path` and the errno text.
// - An existing target keeps its permission bits; a new one gets 0666 minus the umask, as
//   for any newly created file. A symbolic link at `path` is followed (also a chain of them,
//   and one whose target does not exist yet): the file it points to is written, the link stays.
// - The temporary file is registered in host/io/pending_temp_files.h while it exists, so a
//   SIGINT or SIGTERM removes it (once the program called removePendingTempFilesOnSignals).
// After the rename the directory is fsynced too (best effort), so the new name survives a
// power loss.
void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer);

// Several output files written whole or not at all, together: stage() writes each to its
// temporary file (as writeFileAtomically, fsynced), commit() renames them all over their
// targets once every one was written. Until commit(), a failure anywhere (a writer throwing,
// a full disk, an exception in the work between two stage() calls) leaves every target as it
// was: the destructor removes the temporaries not committed. The renames are the only step
// left after the last byte is on disk; one failing after another succeeded (the directory's
// permissions changed meanwhile) throws, naming its path.
class AtomicFileGroup {
 public:
  AtomicFileGroup() = default;
  AtomicFileGroup(const AtomicFileGroup&) = delete;
  AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;
  ~AtomicFileGroup();

  void stage(const std::string& path, const std::function<void(std::ostream&)>& writer);
  void commit();

 private:
  struct Staged {
    std::string path;    // as given, for messages
    std::string target;  // `path` with symbolic links followed: what is replaced
    std::string temp;
    int slot = -1;       // in the pending temp file table
  };
  std::vector<Staged> staged_;
};

// Throws the InputError (kind Io, naming `path`) that writing `path` would end in when its
// directory cannot take a new file (missing, not writable, read-only file system) or `path` is
// a directory, by creating and removing a temporary file there. For checking every output
// before the work, so a long run does not end in "cannot write".
void validateWritable(const std::string& path);

}  // namespace tessera
