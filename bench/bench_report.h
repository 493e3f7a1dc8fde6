// What every benchmark reports, in one shape: tables of cases (work size, min and median time
// over ≥ 5 timed runs, throughput, ratio to the table's first case, and where it applies the
// fraction of the host-memory bandwidth cap), printed as Markdown and, with `--json <file>`,
// written as JSON for scripts/bench.sh to merge into bench/results/latest.json.
#pragma once
#include <nlohmann/json.hpp>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "bench_common.h"

namespace tessera::vk {
class Context;
}

namespace tessera::bench {

struct Case {
  std::string path;          // what ran, e.g. "Vulkan grid evaluation"
  double workSize = 0;       // items of work (points, leaves, triangles, frames)
  Timing timing;             // seconds for the whole work
  double throughput = 0;     // items per second (from timing.minSeconds unless set)
  // Vertices (32 bytes each) written per second, when the case is bounded by host memory
  // bandwidth: reported as a fraction of the measured and of the assumed cap.
  std::optional<double> verticesPerSecond;
  nlohmann::json extra = nlohmann::json::object();  // per-case details (split of times, ...)
};

struct Table {
  std::string name;      // e.g. "evaluation"
  std::string workUnit;  // what workSize counts: "points", "leaves", ...
  std::string title;     // one line above the Markdown table
  std::string rateUnit;  // unit of Case::throughput; "" = workUnit per second
  std::vector<Case> cases;  // the first is the baseline of the ratios
};

// Host memory copy bandwidth, measured now (memcpy of 64 MiB, best of 5): what caps a
// device whose "device memory" is host memory (lavapipe). Bytes per second.
double measureHostCopyBandwidth();

// The assumption: ~5 GB/s host copies, so 32-byte vertices cap at ~156 M/s.
constexpr double kAssumedCopyBytesPerSecond = 5e9;
constexpr double kVertexBytes = 32;

class Report {
 public:
  // Takes `--json <file>` out of argv (argc adjusted); the remaining arguments are the
  // benchmark's own. `usage` is its arguments' synopsis ("[patches=1024] [--json file]"):
  // -h or --help prints it and exits 0; `--json` without a file is a usage error.
  Report(std::string benchName, const char* usage, int& argc, char** argv);

  // Prints "<program>: <why>" and the usage to stderr and exits 2: a bad argument.
  [[noreturn]] void usageError(const std::string& why) const;

  void setDevice(const vk::Context& context);
  void note(const std::string& key, const nlohmann::json& value) { notes_[key] = value; }
  Table& table(const std::string& name, const std::string& workUnit, const std::string& title);

  // Prints one table as Markdown (call as soon as a table is complete, so long runs show
  // progress), then, at the end, writes the JSON file if asked.
  void print(const Table& table) const;
  void finish();

 private:
  double capVerticesPerSecond() const;

  std::string name_;
  std::string program_;  // argv[0]'s file name, for messages
  std::string usage_;
  std::string jsonPath_;
  nlohmann::json notes_ = nlohmann::json::object();
  std::deque<Table> tables_;  // deque: table() hands out references
  mutable std::optional<double> bandwidth_;
};

}  // namespace tessera::bench
