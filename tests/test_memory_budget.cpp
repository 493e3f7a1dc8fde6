// The memory budget (host/common/memory_budget.h) and the input-size limit
// (host/io/input_limit.h): sizes parse as documented and refuse the rest, the default follows
// the machine's smallest limit, an estimate over the budget throws a LimitError naming both,
// and a BoundedInput stops at the limit. The CLI cases: tests/cli_memory_tests.cmake.
#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>
#include <string>

#include "common/memory_budget.h"
#include "io/errors.h"
#include "io/input_limit.h"
#include "io/text_lines.h"
#include "loop/stencils.h"

using namespace tessera;

TEST_CASE("parseByteSize reads plain and binary-unit sizes", "[common][memory]") {
  const struct { const char* text; uint64_t bytes; } cases[] = {
      {"1", 1},          {"1048576", 1048576},     {"512K", 512ull << 10},
      {"512k", 512ull << 10}, {"512M", 512ull << 20}, {"4G", 4ull << 30},
      {"4GiB", 4ull << 30},   {"4gb", 4ull << 30},    {"1.5G", 3ull << 29},
      {"2T", 2ull << 40},     {"100B", 100}};
  for (const auto& c : cases) {
    INFO(c.text);
    CHECK(parseByteSize(c.text) == c.bytes);
  }
}

TEST_CASE("parseByteSize refuses what is not a size", "[common][memory]") {
  for (const char* bad : {"", "0", "0.4", "-5", "M", "12Q", "1.5.2", "1e3", "nan", "4 G", "4GG",
                          "9999999T", " 4G"}) {
    INFO(bad);
    CHECK_THROWS_AS(parseByteSize(bad), std::invalid_argument);
  }
}

TEST_CASE("the default budget is half the smallest known limit", "[common][memory]") {
  MachineMemory m;
  CHECK(defaultMemoryBudget(m) == (4ull << 30));  // nothing known
  m.available = 8ull << 30;
  CHECK(defaultMemoryBudget(m) == (4ull << 30));
  m.cgroupLimit = 2ull << 30;
  CHECK(defaultMemoryBudget(m) == (1ull << 30));
  m.addressSpace = 1ull << 30;
  CHECK(defaultMemoryBudget(m) == (512ull << 20));
  CHECK(queryMachineMemory().available > 0);  // Linux has MemAvailable
}

TEST_CASE("an estimate over the budget is a LimitError naming both and the option",
          "[common][memory]") {
  const uint64_t saved = memoryBudget();
  setMemoryBudget(64ull << 20);
  CHECK_NOTHROW(requireWithinMemoryBudget(64ull << 20, "exactly the budget"));
  try {
    requireWithinMemoryBudget(3ull << 30, "the test's array");
    FAIL("no MemoryLimitError");
  } catch (const LimitError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("the test's array needs about 3.00 GiB") != std::string::npos);
    CHECK(message.find("memory budget of 64.0 MiB") != std::string::npos);
    CHECK(message.find("--memory-budget SIZE") != std::string::npos);
  }
  CHECK_THROWS_AS(requireWithinMemoryBudget(saturatingMultiply(1ull << 40, 1ull << 40), "x"),
                  MemoryLimitError);
  CHECK(saturatingMultiply(1ull << 40, 1ull << 40) == UINT64_MAX);
  CHECK(saturatingAdd(UINT64_MAX - 1, 5) == UINT64_MAX);
  setMemoryBudget(saved);
}

TEST_CASE("the Loop estimate grows as 4^levels and refuses before refining", "[loop][memory]") {
  LoopStencilOptions options;
  options.levels = 3;
  const uint64_t three = estimatedLoopStencilBytes(1000, options);
  options.levels = 4;
  const uint64_t four = estimatedLoopStencilBytes(1000, options);
  INFO("level 3: " << three << " bytes, level 4: " << four);
  CHECK(double(four) / double(three) > 3.9);
  CHECK(double(four) / double(three) < 4.1);
  options.levels = 40;
  CHECK(estimatedLoopStencilBytes(1000, options) == UINT64_MAX);
}

TEST_CASE("a BoundedInput stops at the input-size limit", "[io][memory]") {
  const uint64_t saved = maxInputBytes();
  setMaxInputBytes(100000);
  std::istringstream small(std::string(100000, 'a'));
  BoundedInput fits(small, "small.txt");
  std::string all((std::istreambuf_iterator<char>(fits.stream())), std::istreambuf_iterator<char>());
  CHECK(all.size() == 100000);
  std::istringstream big(std::string(300000, '\n'));
  BoundedInput over(big, "big.txt");
  TextLines lines(over.stream(), "big.txt");
  try {
    while (lines.next()) {
    }
    FAIL("read past the limit");
  } catch (const LimitError& e) {
    CHECK(std::string(e.what()).find("big.txt: the input is larger than the input-size limit of "
                                     "97.7 KiB") != std::string::npos);
  }
  setMaxInputBytes(saved);
}

TEST_CASE("a text line longer than 1 MiB is a Syntax error before it is all read",
          "[io][memory]") {
  std::istringstream endless("1\n" + std::string(kMaxTextLineBytes + 2, '0'));
  TextLines lines(endless, "zeros.bpt");
  REQUIRE(lines.next());
  try {
    lines.next();
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.kind() == InputErrorKind::Syntax);
    CHECK(e.line() == 2);
    CHECK(std::string(e.what()).find("a line longer than 1 MiB") != std::string::npos);
  }
}
