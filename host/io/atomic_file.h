// Write a whole output file or nothing, so a crash, a full disk or an exception in the middle
// of writing a mesh never leaves a half-written file where a good one (or none) was before.
#pragma once
#include <functional>
#include <ostream>
#include <string>

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
//   for any newly created file. A symbolic link at `path` is replaced, not followed.
// After the rename the directory is fsynced too (best effort), so the new name survives a
// power loss.
void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& writer);

}  // namespace tessera
