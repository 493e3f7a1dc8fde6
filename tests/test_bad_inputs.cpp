// The bad-input corpus (tests/bad_inputs/, listed in its MANIFEST.tsv): every file must be
// refused with the InputError kind, file, line and reason the manifest states — never
// accepted, never another exception. Surface files go through readSurfaceFile (what the CLI
// reads), OBJ meshes through readObj and validateManifold.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/errors.h"
#include "io/obj_reader.h"
#include "io/surface_reader.h"

using namespace tessera;

namespace {

const std::string kCorpus = TESSERA_SOURCE_DIR "/tests/bad_inputs/";

struct ManifestRow {
  std::string file, badClass, kind, reason;
  int line = 0;
  int manifestLine = 0;
};

std::vector<ManifestRow> readManifest() {
  std::ifstream in(kCorpus + "MANIFEST.tsv");
  REQUIRE(in);
  std::vector<ManifestRow> rows;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    if (text.empty() || text[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream split(text);
    for (std::string field; std::getline(split, field, '\t');) fields.push_back(field);
    INFO("MANIFEST.tsv line " << n << ": " << text);
    REQUIRE(fields.size() == 5);
    ManifestRow row{fields[0], fields[1], fields[2], fields[4], std::stoi(fields[3]), n};
    rows.push_back(row);
  }
  return rows;
}

void readAsTheCliOrMeshUserWould(const std::string& path) {
  if (std::filesystem::path(path).extension() == ".obj") {
    const PolygonMesh mesh = readObj(path);
    validateManifold(mesh, path);
    validateNoIsolatedVertices(mesh, path);
  } else {
    readSurfaceFile(path);
  }
}

}  // namespace

TEST_CASE("every bad input is refused with the manifest's error kind, file, line and reason",
          "[io][bad-inputs]") {
  const std::vector<ManifestRow> rows = readManifest();
  std::map<std::string, int> perClass, perReader;
  for (const ManifestRow& row : rows) {
    const std::string path = kCorpus + row.file;
    INFO("MANIFEST.tsv line " << row.manifestLine << ": " << row.file);
    bool refused = false;
    try {
      readAsTheCliOrMeshUserWould(path);
    } catch (const InputError& e) {
      refused = true;
      INFO("message: " << e.what());
      CHECK(inputErrorKindName(e.kind()) == row.kind);
      CHECK(e.file() == path);
      CHECK(e.line() == row.line);
      CHECK(e.reason().find(row.reason) != std::string::npos);
      // The printed form names all three: "<file>:<line>: <reason>".
      const std::string where = path + (row.line > 0 ? ":" + std::to_string(row.line) : "") + ": ";
      CHECK(std::string(e.what()).rfind(where + e.reason(), 0) == 0);
    }
    CHECK(refused);
    ++perClass[row.badClass];
    ++perReader[std::filesystem::path(row.file).extension().string()];
  }
  std::cout << "bad inputs: " << rows.size() << " files refused as expected; by class:";
  for (const auto& [name, n] : perClass) std::cout << " " << name << " " << n << ",";
  std::cout << " by reader:";
  for (const auto& [ext, n] : perReader) std::cout << " " << ext << " " << n << ",";
  std::cout << "\n";
  REQUIRE(rows.size() >= 80);
}

TEST_CASE("the manifest lists every file of the corpus exactly once", "[io][bad-inputs]") {
  std::set<std::string> listed;
  for (const ManifestRow& row : readManifest()) {
    INFO(row.file);
    CHECK(listed.insert(row.file).second);
    CHECK(std::filesystem::is_regular_file(kCorpus + row.file));
  }
  for (const auto& entry : std::filesystem::directory_iterator(kCorpus)) {
    const std::string name = entry.path().filename().string();
    if (name == "MANIFEST.tsv") continue;
    INFO("corpus file not in MANIFEST.tsv: " << name);
    CHECK(listed.count(name) == 1);
  }
}
