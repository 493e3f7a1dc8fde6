#include "common/memory_budget.h"

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace tessera {
namespace {

constexpr uint64_t kUnlimited = std::numeric_limits<uint64_t>::max();

// The first number on the line of /proc/meminfo that starts with `key`, in bytes (the file
// gives kB).
uint64_t meminfoBytes(const char* key) {
  std::ifstream in("/proc/meminfo");
  std::string name;
  uint64_t kib = 0;
  std::string unit;
  while (in >> name >> kib) {
    std::getline(in, unit);
    if (name == key) return saturatingMultiply(kib, 1024);
  }
  return 0;
}

// A cgroup limit file's value; "max" or a v1 "no limit" (close to 2^63) count as unlimited.
uint64_t cgroupFileBytes(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return 0;
  try {
    const unsigned long long value = std::stoull(text);
    return value >= (uint64_t(1) << 62) ? 0 : uint64_t(value);
  } catch (const std::exception&) {
    return 0;
  }
}

std::mutex budgetMutex;
uint64_t budgetBytes = 0;  // 0: not set yet

}  // namespace

MachineMemory queryMachineMemory() {
  MachineMemory m;
  m.available = meminfoBytes("MemAvailable:");
  m.cgroupLimit = cgroupFileBytes("/sys/fs/cgroup/memory.max");
  if (m.cgroupLimit == 0) m.cgroupLimit = cgroupFileBytes("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    m.addressSpace = uint64_t(limit.rlim_cur);
  return m;
}

uint64_t defaultMemoryBudget(const MachineMemory& machine) {
  uint64_t smallest = kUnlimited;
  for (const uint64_t limit : {machine.available, machine.cgroupLimit, machine.addressSpace})
    if (limit != 0 && limit < smallest) smallest = limit;
  if (smallest == kUnlimited) return uint64_t(4) << 30;
  return std::max<uint64_t>(smallest / 2, uint64_t(1) << 20);
}

uint64_t memoryBudget() {
  std::lock_guard<std::mutex> lock(budgetMutex);
  if (budgetBytes == 0) budgetBytes = defaultMemoryBudget(queryMachineMemory());
  return budgetBytes;
}

void setMemoryBudget(uint64_t bytes) {
  std::lock_guard<std::mutex> lock(budgetMutex);
  budgetBytes = bytes;
}

void requireWithinMemoryBudget(uint64_t bytes, const std::string& what) {
  const uint64_t budget = memoryBudget();
  if (bytes <= budget) return;
  const std::string needs = bytes == kUnlimited ? "more than 16 EiB" : "about " + formatByteSize(bytes);
  throw MemoryLimitError(what + " needs " + needs + " (estimate), more than the memory budget of " +
                         formatByteSize(budget) + " (raise it with --memory-budget SIZE)");
}

uint64_t saturatingMultiply(uint64_t a, uint64_t b) {
  if (a != 0 && b > kUnlimited / a) return kUnlimited;
  return a * b;
}

uint64_t saturatingAdd(uint64_t a, uint64_t b) { return b > kUnlimited - a ? kUnlimited : a + b; }

uint64_t parseByteSize(const std::string& text) {
  const auto bad = [&](const char* why) {
    return std::invalid_argument("'" + text + "' is not a size (" + why +
                                 "; e.g. 1048576, 512K, 512M, 4G)");
  };
  size_t k = 0;
  while (k < text.size() && (std::isdigit(static_cast<unsigned char>(text[k])) || text[k] == '.')) ++k;
  if (k == 0) throw bad("it must start with a number");
  double number = 0;
  try {
    size_t used = 0;
    number = std::stod(text.substr(0, k), &used);
    if (used != k) throw bad("a malformed number");
  } catch (const std::logic_error&) {
    throw bad("a malformed number");
  }
  std::string unit;
  for (size_t i = k; i < text.size(); ++i) unit += char(std::toupper(static_cast<unsigned char>(text[i])));
  int shift = 0;
  if (!unit.empty() && unit != "B") {
    const std::string prefixes = "KMGT";
    const size_t p = prefixes.find(unit[0]);
    const std::string rest = unit.substr(1);
    if (p == std::string::npos || !(rest.empty() || rest == "B" || rest == "IB"))
      throw bad("unknown unit; use K, M, G or T");
    shift = 10 * int(p + 1);
  }
  const double bytes = std::ldexp(number, shift);
  if (!(bytes >= 1)) throw bad("it must be at least one byte");
  if (bytes > std::ldexp(1.0, 63)) throw bad("more than 2^63 bytes");
  return uint64_t(bytes);
}

std::string formatByteSize(uint64_t bytes) {
  const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  double value = double(bytes);
  int u = -1;
  while (value >= 1024 && u < 5) {
    value /= 1024;
    ++u;
  }
  char text[32];
  std::snprintf(text, sizeof text, value < 10 ? "%.2f %s" : value < 100 ? "%.1f %s" : "%.0f %s",
                value, units[u]);
  return text;
}

}  // namespace tessera
