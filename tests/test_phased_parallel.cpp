// runPhases (common/phased_parallel.h): phases in order, each item once, each `then` once after
// its phase's items and before the next phase's count; the lowest failing item's exception and
// nothing after it; the same inside a part of another fan-out, where no worker is free.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/parallel_for.h"
#include "common/phased_parallel.h"

using namespace tessera;

namespace {

long long sumOfSquaresBelow(size_t count) {
  const long long n = (long long)count;
  return (n - 1) * n * (2 * n - 1) / 6;
}

// Three phases: the first squares its items, its `then` sums them and sets the second's count
// to that sum modulo 97 (decided only then); the second's items each read the sum; the third
// has no items, its `then` records that it ran. Returns a summary the caller compares.
struct ChainResult {
  long long sum = 0;
  size_t secondCount = 0;
  bool secondSawSum = true;
  bool thirdThenRan = false;
  std::vector<int> visits;  // per first-phase item
};

ChainResult runChain(size_t firstCount, unsigned threads) {
  ChainResult result;
  std::vector<long long> squares(firstCount);
  std::vector<std::atomic<int>> visits(firstCount);
  std::atomic<bool> secondSawSum{true};
  std::atomic<size_t> secondRan{0};
  const std::vector<ParallelPhase> phases = {
      {[&] { return firstCount; }, 3,
       [&](size_t i) {
         squares[i] = (long long)(i * i);
         ++visits[i];
       },
       [&] {
         for (long long s : squares) result.sum += s;
         result.secondCount = size_t(result.sum % 97) + 1;
       }},
      {[&] { return result.secondCount; }, 1,
       [&](size_t) {
         if (result.sum != sumOfSquaresBelow(firstCount))
           secondSawSum = false;
         ++secondRan;
       },
       [&] { secondSawSum = secondSawSum && secondRan == result.secondCount; }},
      {[] { return size_t(0); }, 1, [](size_t) {}, [&] { result.thirdThenRan = true; }},
  };
  runPhases(phases, threads);
  result.secondSawSum = secondSawSum;
  for (auto& v : visits) result.visits.push_back(v);
  return result;
}

}  // namespace

TEST_CASE("runPhases runs every item once, each phase after the step before", "[common]") {
  for (unsigned threads : {1u, 2u, 0u}) {
    for (size_t count : {size_t(1), size_t(7), size_t(500)}) {
      const ChainResult r = runChain(count, threads);
      CHECK(r.sum == sumOfSquaresBelow(count));
      CHECK(r.secondSawSum);
      CHECK(r.thirdThenRan);
      CHECK(std::count(r.visits.begin(), r.visits.end(), 1) == long(count));
    }
  }
}

TEST_CASE("runPhases rethrows the lowest failing item's exception and runs nothing after", "[common]") {
  for (unsigned threads : {1u, 2u}) {
    bool thenRan = false, laterRan = false;
    const std::vector<ParallelPhase> phases = {
        {[] { return size_t(200); }, 4,
         [](size_t i) {
           if (i == 37 || i == 150) throw std::runtime_error("item " + std::to_string(i));
         },
         [&] { thenRan = true; }},
        {[&] {
           laterRan = true;
           return size_t(1);
         },
         1, [](size_t) {}, nullptr},
    };
    try {
      runPhases(phases, threads);
      FAIL("no exception");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "item 37");
    }
    CHECK_FALSE(thenRan);
    CHECK_FALSE(laterRan);
  }
  const std::vector<ParallelPhase> failingStep = {
      {[] { return size_t(10); }, 1, [](size_t) {}, [] { throw std::runtime_error("step"); }},
  };
  CHECK_THROWS_WITH(runPhases(failingStep, 2), "step");
}

TEST_CASE("runPhases inside a part of another fan-out finishes", "[common]") {
  // The outer parts hold the workers: each inner run may find none free and run alone.
  std::vector<std::atomic<int>> ok(6);
  parallelParts(6, [&](unsigned part) {
    const ChainResult r = runChain(50 + part, 2);
    if (r.thirdThenRan && r.secondSawSum) ++ok[part];
  });
  for (auto& v : ok) CHECK(v == 1);
}
