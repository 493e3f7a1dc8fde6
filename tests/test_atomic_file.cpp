// writeFileAtomically (host/io/atomic_file.h): the whole file or nothing, no temporary files
// left behind, and I/O failures reported as InputError naming the path.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/errors.h"
#include "scratch_dir.h"

using namespace tessera;
namespace fs = std::filesystem;
using test::ScratchDir;

namespace {

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// More than the writer's internal buffer, so a failure happens after real bytes hit the disk.
const std::string kLargeChunk(300000, 'x');

}  // namespace

TEST_CASE("atomic file: writes the whole content and leaves nothing else", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path target = dir.path / "out.txt";
  writeFileAtomically(target.string(), [](std::ostream& out) { out << "hello\n" << 42 << '\n'; });
  CHECK(test::readWholeFile(target) == "hello\n42\n");
  CHECK(entries(dir.path) == std::vector<std::string>{"out.txt"});
}

TEST_CASE("atomic file: binary bytes and large blocks pass unchanged", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path target = dir.path / "out.bin";
  std::string bytes;
  for (int k = 0; k < 200000; ++k) bytes += static_cast<char>(k * 7 % 256);  // '\0', '\r', '\n' …
  writeFileAtomically(target.string(), [&](std::ostream& out) {
    out.write(bytes.data(), 10);                                      // through the buffer
    out.write(bytes.data() + 10, std::streamsize(bytes.size() - 10));  // around it
  });
  CHECK(test::readWholeFile(target) == bytes);
}

TEST_CASE("atomic file: a relative path in the current directory", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path previous = fs::current_path();
  fs::current_path(dir.path);
  try {
    writeFileAtomically("plain.txt", [](std::ostream& out) { out << "x"; });
  } catch (...) {
    fs::current_path(previous);
    throw;
  }
  fs::current_path(previous);
  CHECK(test::readWholeFile(dir.path / "plain.txt") == "x");
  CHECK(entries(dir.path) == std::vector<std::string>{"plain.txt"});
}

TEST_CASE("atomic file: replacing an existing file keeps its permissions", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path target = dir.path / "mesh.obj";
  std::ofstream(target) << "old";
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  writeFileAtomically(target.string(), [](std::ostream& out) { out << "new"; });
  CHECK(test::readWholeFile(target) == "new");
  CHECK(fs::status(target).permissions() ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  CHECK(entries(dir.path) == std::vector<std::string>{"mesh.obj"});
}

TEST_CASE("atomic file: a writer throwing midway leaves the target untouched", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path target = dir.path / "mesh.ply";
  auto failingWriter = [](std::ostream& out) {
    out << kLargeChunk;
    throw std::runtime_error("writer gave up");
  };

  SECTION("an existing target keeps its old content") {
    std::ofstream(target) << "the old mesh";
    CHECK_THROWS_WITH(writeFileAtomically(target.string(), failingWriter), "writer gave up");
    CHECK(test::readWholeFile(target) == "the old mesh");
    CHECK(entries(dir.path) == std::vector<std::string>{"mesh.ply"});
  }
  SECTION("a missing target stays missing") {
    CHECK_THROWS_AS(writeFileAtomically(target.string(), failingWriter), std::runtime_error);
    CHECK_FALSE(fs::exists(target));
    CHECK(entries(dir.path).empty());
  }
}

TEST_CASE("atomic file: a failed stream is an Io error and nothing is written", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path target = dir.path / "out.txt";
  std::ofstream(target) << "keep";
  try {
    writeFileAtomically(target.string(), [](std::ostream& out) {
      out << kLargeChunk;
      out.setstate(std::ios::badbit);
    });
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(e.file() == target.string());
    CHECK(std::string(e.what()).find("stream failed") != std::string::npos);
  }
  CHECK(test::readWholeFile(target) == "keep");
  CHECK(entries(dir.path) == std::vector<std::string>{"out.txt"});
}

TEST_CASE("atomic file: a nonexistent directory is a clear Io error", "[io][atomic]") {
  ScratchDir dir("atomic");
  const std::string target = (dir.path / "no" / "such" / "dir" / "mesh.obj").string();
  bool writerCalled = false;
  try {
    writeFileAtomically(target, [&](std::ostream&) { writerCalled = true; });
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(e.file() == target);
    CHECK(e.line() == 0);
    const std::string what = e.what();
    INFO(what);
    CHECK(what.rfind(target + ": ", 0) == 0);
    CHECK(what.find("cannot create a temporary file in directory") != std::string::npos);
    CHECK(what.find("No such file or directory") != std::string::npos);
  }
  CHECK_FALSE(writerCalled);
  CHECK(entries(dir.path).empty());
}

TEST_CASE("atomic file: a directory in the way is an Io error", "[io][atomic]") {
  ScratchDir dir("atomic");
  const fs::path target = dir.path / "taken";
  fs::create_directory(target);
  try {
    writeFileAtomically(target.string(), [](std::ostream& out) { out << "data"; });
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    INFO(e.what());
    // Found before the writer runs, not at the rename after all the bytes were written.
    CHECK(std::string(e.what()).find("is a directory, not a file") != std::string::npos);
  }
  CHECK(fs::is_directory(target));
  CHECK(entries(dir.path) == std::vector<std::string>{"taken"});

  // A path that names no file at all is refused before anything is created.
  CHECK_THROWS_AS(writeFileAtomically(dir.path.string() + "/", [](std::ostream&) {}), InputError);
  CHECK(entries(dir.path) == std::vector<std::string>{"taken"});
}
