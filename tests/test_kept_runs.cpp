// KeptRuns (mesh/detail/kept_runs.h): the leaf runs' arrays kept from one triangulation to the
// next give empty runs that keep their room, and a huge mesh's are not kept.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "mesh/detail/kept_runs.h"

using namespace tessera::triangulate_detail;

TEST_CASE("kept runs come back empty, with their room", "[triangulate][kept_runs]") {
  KeptRuns kept;
  std::vector<LeafRun>& runs = kept.take(3);
  REQUIRE(runs.size() == 3);
  runs[1].vertices.resize(100);
  runs[1].border.push_back(7);
  runs[1].triangles.resize(200);
  runs[1].droppedTriangles = 2;
  runs[1].diagonalFans = 1;
  const size_t room = runs[1].triangles.capacity();
  kept.release();  // far below kKeptBytes: kept

  std::vector<LeafRun>& again = kept.take(2);
  REQUIRE(again.size() == 2);
  for (const LeafRun& run : again) {
    CHECK(run.vertices.empty());
    CHECK(run.border.empty());
    CHECK(run.triangles.empty());
    CHECK(run.droppedTriangles == 0);
    CHECK(run.diagonalFans == 0);
  }
  CHECK(again[1].triangles.capacity() == room);

  // More room than kKeptBytes: freed after the call.
  again[0].triangles.reserve(KeptRuns::kKeptBytes / sizeof(RunTriangle) + 1);
  kept.release();
  CHECK(kept.take(2)[0].triangles.capacity() == 0);
}

TEST_CASE("kept runs past their room are freed when a call ends by an exception",
          "[triangulate][kept_runs]") {
  KeptRuns kept;
  try {
    const KeptRuns::ReleaseAtEnd releaseRuns{kept};
    kept.take(1)[0].triangles.reserve(KeptRuns::kKeptBytes / sizeof(RunTriangle) + 1);
    throw std::runtime_error("the walk failed");
  } catch (const std::runtime_error&) {
  }
  CHECK(kept.take(1)[0].triangles.capacity() == 0);
}
