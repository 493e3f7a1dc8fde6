// Output files written together (AtomicFileGroup), through symbolic links, checked before the
// work (validateWritable), and temporary files removed on SIGINT and SIGTERM
// (host/io/atomic_file.h, host/io/pending_temp_files.h). Issue 18.
#include <catch2/catch.hpp>
#include <signal.h>
#include <sys/wait.h>
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
#include "io/pending_temp_files.h"
#include "scratch_dir.h"

using namespace tessera;
namespace fs = std::filesystem;
using test::ScratchDir;

namespace {

void put(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::function<void(std::ostream&)> text(const std::string& t) {
  return [t](std::ostream& out) { out << t; };
}

}  // namespace

TEST_CASE("atomic group: commit writes every file, nothing else is left", "[io][atomic]") {
  ScratchDir dir("group");
  put(dir.path / "a.txt", "old a");
  AtomicFileGroup group;
  group.stage((dir.path / "a.txt").string(), text("new a"));
  group.stage((dir.path / "b.txt").string(), text("new b"));
  CHECK(test::readWholeFile(dir.path / "a.txt") == "old a");  // staged, not yet visible
  group.commit();
  CHECK(test::readWholeFile(dir.path / "a.txt") == "new a");
  CHECK(test::readWholeFile(dir.path / "b.txt") == "new b");
  CHECK(entries(dir.path) == std::vector<std::string>{"a.txt", "b.txt"});
}

TEST_CASE("atomic group: a failure after one file is staged leaves every target as it was",
          "[io][atomic]") {
  ScratchDir dir("group");
  put(dir.path / "mesh.obj", "old mesh");
  SECTION("the second writer throws") {
    AtomicFileGroup group;
    group.stage((dir.path / "mesh.obj").string(), text("new mesh"));
    REQUIRE_THROWS_AS(group.stage((dir.path / "stats.json").string(),
                                  [](std::ostream&) { throw std::runtime_error("boom"); }),
                      std::runtime_error);
  }
  SECTION("the second target cannot be written") {
    fs::create_directory(dir.path / "stats.json");
    AtomicFileGroup group;
    group.stage((dir.path / "mesh.obj").string(), text("new mesh"));
    REQUIRE_THROWS_AS(group.stage((dir.path / "stats.json").string(), text("{}")), InputError);
  }
  SECTION("never committed") {
    AtomicFileGroup group;
    group.stage((dir.path / "mesh.obj").string(), text("new mesh"));
  }
  CHECK(test::readWholeFile(dir.path / "mesh.obj") == "old mesh");
  std::vector<std::string> left = entries(dir.path);
  left.erase(std::remove(left.begin(), left.end(), "stats.json"), left.end());
  CHECK(left == std::vector<std::string>{"mesh.obj"});  // no temporary file
}

TEST_CASE("atomic file: a symbolic link is written through, and stays a link", "[io][atomic]") {
  ScratchDir dir("group");
  fs::create_directory(dir.path / "real");
  put(dir.path / "real" / "mesh.obj", "old");
  fs::create_symlink("real/mesh.obj", dir.path / "link.obj");
  fs::create_symlink("link.obj", dir.path / "chain.obj");
  fs::create_symlink("real/new.obj", dir.path / "dangling.obj");
  writeFileAtomically((dir.path / "chain.obj").string(), text("through two links"));
  writeFileAtomically((dir.path / "dangling.obj").string(), text("made"));
  CHECK(fs::is_symlink(dir.path / "link.obj"));
  CHECK(fs::is_symlink(dir.path / "chain.obj"));
  CHECK(fs::is_symlink(dir.path / "dangling.obj"));
  CHECK(test::readWholeFile(dir.path / "real" / "mesh.obj") == "through two links");
  CHECK(test::readWholeFile(dir.path / "real" / "new.obj") == "made");
  CHECK(entries(dir.path / "real") == std::vector<std::string>{"mesh.obj", "new.obj"});
}

TEST_CASE("validateWritable: a missing folder or a directory in the way, before the work",
          "[io][atomic]") {
  ScratchDir dir("group");
  const std::string missing = (dir.path / "missing" / "out.obj").string();
  try {
    validateWritable(missing);
    FAIL("no error for " << missing);
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Io);
    CHECK(e.file() == missing);
  }
  fs::create_directory(dir.path / "taken");
  REQUIRE_THROWS_AS(validateWritable((dir.path / "taken").string()), InputError);
  validateWritable((dir.path / "fine.obj").string());
  CHECK(entries(dir.path) == std::vector<std::string>{"taken"});  // the probe is gone
}

// A child process stages a file (its temporary exists and is pending), tells the parent, and
// waits; the parent sends the signal. The child must die of that signal (the handler re-raises
// it) and leave no temporary file.
TEST_CASE("atomic file: SIGINT and SIGTERM remove pending temporary files", "[io][atomic]") {
  for (const int signal : {SIGINT, SIGTERM}) {
    INFO("signal " << signal);
    ScratchDir dir("group");
    int ready[2];
    REQUIRE(::pipe(ready) == 0);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      removePendingTempFilesOnSignals();
      AtomicFileGroup group;
      group.stage((dir.path / "mesh.obj").string(), text("staged"));
      group.stage((dir.path / "stats.json").string(), text("staged"));
      // In the middle of a second write: its temporary is open too.
      writeFileAtomically((dir.path / "picture.png").string(), [&](std::ostream& out) {
        out << "partial";
        out.flush();
        const char byte = 1;
        (void)!::write(ready[1], &byte, 1);
        for (;;) ::pause();
      });
      ::_exit(0);
    }
    ::close(ready[1]);
    char byte = 0;
    REQUIRE(::read(ready[0], &byte, 1) == 1);
    ::close(ready[0]);
    const std::vector<std::string> before = entries(dir.path);
    CHECK(before.size() == 3);  // three temporaries, no target yet
    REQUIRE(::kill(child, signal) == 0);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal);
    CHECK(entries(dir.path).empty());
  }
}

TEST_CASE("pending temp files: a full table and a long path are not tracked, not an error",
          "[io][atomic]") {
  std::vector<int> slots;
  for (size_t i = 0; i < kMaxPendingTempFiles + 2; ++i)
    slots.push_back(registerPendingTempFile("/nonexistent/tessera_test_slot"));
  size_t tracked = 0;
  for (const int slot : slots) tracked += slot >= 0;
  CHECK(tracked <= kMaxPendingTempFiles);
  CHECK(slots.back() == -1);
  for (const int slot : slots) forgetPendingTempFile(slot);
  CHECK(registerPendingTempFile(std::string(kMaxPendingTempPath, 'x').c_str()) == -1);
  const int again = registerPendingTempFile("/nonexistent/tessera_test_slot");
  CHECK(again >= 0);  // forgotten slots are free again
  forgetPendingTempFile(again);
}
