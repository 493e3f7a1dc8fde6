// Damaged STEP and IGES files (host/cad/exchange_checks.h, occt_signals.h, docs/cad.md): one
// reference or number changed in a model of FreeCAD's IDF library. Each used to crash Open
// CASCADE's transfer (SIGSEGV), lose a face without a word, end as an internal error or say only
// "RetFail"; each is now an InputError naming the file and the entity or the line. And the read
// leaves the process's signal handlers as they were.
#include <catch2/catch.hpp>

#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include "cad/cad_file.h"
#include "cad/mesh_cad_file.h"
#include "cad/to_trimmed.h"
#include "mesh/tessellate.h"
#include "scratch_dir.h"
#include "tessera/errors.h"

using namespace tessera;

namespace {

const std::string kIdf = "/usr/share/freecad/Mod/Idf/Idflibs/";

// `text` with its first occurrence of `from` replaced by `to`, written to `dir`/`name`.
std::string writeReplaced(const test::ScratchDir& dir, const std::string& name, std::string text,
                          const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  const std::string path = (dir.path / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

void requireMeshRefused(const std::string& path, const std::string& expected) {
  Backend backend = makeMirrorBackend();
  try {
    meshCadFile(path, ToleranceSpec{}, false, "", backend, nullptr);
    FAIL("meshed " << path);
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(e.file() == path);
    CHECK(std::string(e.what()).find(expected) != std::string::npos);
  }
}

// The IDF model `model` with its one occurrence of `from` replaced by `to`, written to `dir`.
std::string damagedCopy(const test::ScratchDir& dir, const std::string& model,
                        const std::string& from, const std::string& to) {
  const std::string text = test::readWholeFile(kIdf + model);
  REQUIRE(text.find(from) != std::string::npos);  // freecad-common (scripts/deps.sh installs it)
  REQUIRE(text.find(from, text.find(from) + 1) == std::string::npos);
  return writeReplaced(dir, "damaged_" + model, text, from, to);
}

void requireRefused(const std::string& path, const std::string& expected) {
  try {
    readCadFile(path);
    FAIL("the damaged file was read");
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(e.file() == path);
    CHECK(std::string(e.what()).find(expected) != std::string::npos);
  }
}

// readCadFile(path) in a child process: "InputError <file>|<message>", or what else happened.
// For a crash inside OCCT: the longjmp that turns it into OCCT's exception skips the destructors
// of what the aborted transfer held (the file's entities), which LeakSanitizer would report at
// the exit of the sanitizer run's test process; the child leaves by _exit, before that check.
std::string readInChild(const std::string& path) {
  int pipeEnds[2];
  REQUIRE(pipe(pipeEnds) == 0);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    close(pipeEnds[0]);
    std::string said = "no error";
    try {
      readCadFile(path);
    } catch (const InputError& e) {
      said = "InputError " + e.file() + "|" + e.what();
    } catch (const std::exception& e) {
      said = std::string("another exception: ") + e.what();
    }
    const ssize_t written = write(pipeEnds[1], said.data(), said.size());
    _exit(written == ssize_t(said.size()) ? 0 : 1);
  }
  close(pipeEnds[1]);
  std::string said;
  char chunk[4096];
  for (ssize_t n; (n = read(pipeEnds[0], chunk, sizeof chunk)) > 0;) said.append(chunk, size_t(n));
  close(pipeEnds[0]);
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  INFO("the child said: " << said);
  REQUIRE(WIFEXITED(status));  // not killed by a signal: no crash
  REQUIRE(WEXITSTATUS(status) == 0);
  return said;
}

}  // namespace

TEST_CASE("cad: a STEP face whose bound is not in the file is refused naming it", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  // Before: OCCT's transfer dereferenced the missing bound (SIGSEGV in StepShape_FaceBound).
  requireRefused(damagedCopy(dir, "SOT23.stp", "#1089 = ADVANCED_FACE('',(#1090)",
                             "#1089 = ADVANCED_FACE('',(#999999)"),
                 "the STEP file is damaged: entity #1089 ADVANCED_FACE does not load: ");
}

TEST_CASE("cad: a STEP entity whose transfer crashed Open CASCADE is refused naming it", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  // A pcurve's 2D curve replaced by a 3D point: it loads (a reference of a known type), and
  // OCCT's transfer crashed in StepToGeom::MakeCurve2d. Under OcctSignalsAsExceptions the crash
  // is OCCT's exception, which its transfer catches for the shell that holds the face.
  const std::string path =
      damagedCopy(dir, "SOT23.stp", "DEFINITIONAL_REPRESENTATION('',(#9859),#9863)",
                  "DEFINITIONAL_REPRESENTATION('',(#9854),#9863)");
  const std::string said = readInChild(path);
  INFO(said);
  CHECK(said.rfind("InputError " + path + "|", 0) == 0);
  CHECK(said.find("the STEP file is damaged: entity #9836 SHELL_BASED_SURFACE_MODEL did not "
                  "transfer: Exception is raised. Entity was not translated.") !=
        std::string::npos);
}

TEST_CASE("cad: an IGES surface that does not load is refused naming it, not dropped", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  // One count of the first B-spline surface made 9: its parameters no longer parse (OCCT reads
  // an integer where a real belongs), OCCT dropped the face, and the import went on with 72 of
  // 73 faces, saying nothing.
  requireRefused(damagedCopy(dir, "SOT23.igs", "128,1,1,1,1,0,0,1,0,0,-4.163336342E-17",
                             "128,1,1,9,1,0,0,1,0,0,-4.163336342E-17"),
                 "the IGES file is damaged: entity 2 (128 0 BSplineSurface) does not load: ");
}

// The STEP parser's syntax errors name their line: the InputError carries it (file:line:).
TEST_CASE("cad: a STEP syntax error is refused naming its line", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  const std::string whole = test::readWholeFile(kIdf + "SOT23.stp");
  // Cut in the middle of a line: the parser meets the end of the file there.
  const std::string cut = whole.substr(0, whole.size() / 2);
  const int cutLine = int(std::count(cut.begin(), cut.end(), '\n')) + 1;
  const std::string truncated = (dir.path / "truncated.stp").string();
  std::ofstream(truncated, std::ios::binary) << cut;
  // Junk after an entity on line 1349: the parser goes on, the file's check names the line.
  const std::string junk =
      damagedCopy(dir, "SOT23.stp", "#1089 = ADVANCED_FACE('',(#1090),#1104,.T.);",
                  "#1089 = ADVANCED_FACE('',(#1090),#1104,.T.) junk (;");
  const struct {
    std::string path, text;
    int line;
  } cases[] = {
      {truncated, "the STEP reader could not read it: incorrect syntax: unexpected end of file",
       cutLine},
      {junk,
       "the STEP file is damaged: the file does not load: Undefined Parsing: Line 1350: "
       "Incorrect syntax",
       1349}};
  for (const auto& c : cases) {
    try {
      readCadFile(c.path);
      FAIL("read " << c.path);
    } catch (const InputError& e) {
      INFO(e.what());
      CHECK(e.file() == c.path);
      CHECK(std::string(e.what()).find(c.text) != std::string::npos);
      // OCCT counts the line after the one it stopped on where it met the next token there.
      CHECK(e.line() >= c.line);
      CHECK(e.line() <= c.line + 1);
      CHECK(std::string(e.what()).rfind(c.path + ":" + std::to_string(e.line()) + ": ", 0) == 0);
    }
  }
}

TEST_CASE("cad: a model whose bounding box is not finite is refused naming the file", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  // One control point of a B-spline surface at 10³⁰⁰: the box's diagonal overflows, and the
  // relative δ taken from it was infinite (an ArgumentError deep in the import: exit 70).
  const std::string path =
      damagedCopy(dir, "CAP_50SGV_8_10.stp", "#1769 = CARTESIAN_POINT('',(-3.041885108155,",
                  "#1769 = CARTESIAN_POINT('',(1.E+300,");
  // The diagonal every caller takes δ from (meshCadFile and `tessera info`, which also ended
  // as an internal error).
  CHECK_THROWS_WITH(cadModelDiagonal(readCadFile(path)),
                    Catch::StartsWith(path + ": its bounding box is not finite"));
  Backend backend = makeMirrorBackend();
  for (const bool relative : {true, false}) {
    ToleranceSpec tolerance;
    if (!relative) tolerance.value = 0.01, tolerance.relative = false;
    try {
      meshCadFile(path, tolerance, false, "", backend, nullptr);
      FAIL("meshed");
    } catch (const InputError& e) {
      INFO(e.what());
      CHECK(e.file() == path);
      CHECK(std::string(e.what()).find("its bounding box is not finite") != std::string::npos);
    }
  }
}

// Open CASCADE's own format, one number changed (found by changing numbers of .brep files at
// random, 2026-11-29): each used to hang, abort or end as an internal error.
TEST_CASE("cad: damaged .brep files are refused naming the file", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  const std::string cylinderPath = (dir.path / "cylinder.brep").string();
  REQUIRE(BRepTools::Write(BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape(), cylinderPath.c_str()));
  const std::string cylinder = test::readWholeFile(cylinderPath);
  // An edge's curve representation of an unknown kind: BRepTools::Read read past the end of the
  // file for ever, its stream failing at every number.
  requireRefused(
      writeReplaced(dir, "unknown_kind.brep", cylinder, "\n2  1 1 0 0 ", "\n7  1 1 0 0 "),
      "BRepTools::Read could not read it: the file ends or breaks where it expected more");
  // A vertex at 10³⁰⁰: the mesher's distance measure met NaN (exit 70).
  requireMeshRefused(
      writeReplaced(dir, "far_vertex.brep", cylinder, "Ve\n1e-07\n1 ", "Ve\n1e-07\n1e+300 "),
      "vertex 0: a point (1e+300, ");
  // CAP_50SGV_8_10 as .brep with a circle's range from 3.93 to 10⁻³⁰⁰: BRepBndLib::Add threw
  // Standard_ConstructionError, which is no std::exception: std::terminate (SIGABRT).
  const std::string capPath = (dir.path / "cap.brep").string();
  REQUIRE(BRepTools::Write(readCadFile(kIdf + "CAP_50SGV_8_10.stp").shape, capPath.c_str()));
  requireMeshRefused(writeReplaced(dir, "reversed_range.brep", test::readWholeFile(capPath),
                                   "\n1  6 0 3.92699081698724 7.06858347057703\n",
                                   "\n1  6 0 3.92699081698724 1e-300\n"),
                     "Open CASCADE failed measuring its bounding box: Standard_ConstructionError");
}

namespace {
void sentinelHandler(int) {}
}  // namespace

TEST_CASE("cad: reading a file leaves the process's signal handlers as they were", "[cad]") {
  const test::ScratchDir dir("cad_damaged");
  const int signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGINT, SIGTERM};
  struct sigaction sentinel {
  }, saved[std::size(signals)];
  sentinel.sa_handler = sentinelHandler;
  sigemptyset(&sentinel.sa_mask);
  for (size_t k = 0; k < std::size(signals); ++k) sigaction(signals[k], &sentinel, &saved[k]);
  CHECK_NOTHROW(readCadFile(kIdf + "SOT23.stp"));
  CHECK_THROWS_AS(readCadFile(damagedCopy(dir, "SOT23.stp", "#1089 = ADVANCED_FACE('',(#1090)",
                                          "#1089 = ADVANCED_FACE('',(#999999)")),
                  InputError);
  for (size_t k = 0; k < std::size(signals); ++k) {
    struct sigaction now {};
    sigaction(signals[k], &saved[k], &now);  // back to what the test found
    INFO("signal " << signals[k]);
    CHECK(now.sa_handler == sentinelHandler);
  }
}

// What Open CASCADE's transfer warns of while it goes on (its shape healing skipping a wire,
// say) is told, one line per message with the entities that gave it; a clean file tells none.
TEST_CASE("cad read: the transfer's warnings are told, naming the entities", "[cad][damaged]") {
  const CadFile sod = readCadFile(kIdf + "SOD_323.igs");
  REQUIRE(sod.readerWarnings.size() == 1);
  INFO(sod.readerWarnings[0]);
  CHECK(sod.readerWarnings[0].find(kIdf + "SOD_323.igs: Open CASCADE's IGES transfer: null area "
                                          "wire detected, wire skipped (entity 218 (142 0 "
                                          "CurveOnSurface), entity 235, ") == 0);
  CHECK(sod.readerWarnings[0].find("; and 3 more entities)") != std::string::npos);
  CHECK(readCadFile(kIdf + "0603_SMD.stp").readerWarnings.empty());
  Backend backend = makeMirrorBackend();
  CHECK(meshCadFile(kIdf + "SOD_323.igs", ToleranceSpec{}, false, "", backend, nullptr)
            .readerWarnings == sod.readerWarnings);
}
