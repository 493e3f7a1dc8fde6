#include "bench_report.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"
#include "vk/context.h"

namespace tessera::bench {

double measureHostCopyBandwidth() {
  // 64 MiB: well beyond the last-level cache, like the outputs that the cap is about.
  const size_t bytes = size_t(64) << 20;
  std::vector<char> from(bytes, 1), to(bytes, 0);
  Timing t = timeRepeated(kMinRuns, [&] {
    std::memcpy(to.data(), from.data(), bytes);
    from[to[bytes / 2] & 1023] ^= 1;  // the copies depend on each other: none is elided
  });
  return double(bytes) / t.minSeconds;
}

Report::Report(std::string benchName, const char* usage, int& argc, char** argv)
    : name_(std::move(benchName)), usage_(usage) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // tables appear as they finish, also in a pipe
  const char* slash = argc > 0 ? std::strrchr(argv[0], '/') : nullptr;
  program_ = argc > 0 ? (slash ? slash + 1 : argv[0]) : name_;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
      std::printf("usage: %s %s\n", program_.c_str(), usage_.c_str());
      std::exit(0);
    }
    if (std::strcmp(argv[i], "--json") == 0) {
      if (i + 1 >= argc) usageError("--json needs a file name");
      jsonPath_ = argv[++i];
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
}

void Report::usageError(const std::string& why) const {
  std::fprintf(stderr, "%s: %s\nusage: %s %s\n", program_.c_str(), why.c_str(), program_.c_str(),
               usage_.c_str());
  std::exit(2);
}

void Report::setDevice(const vk::Context& context) {
  const vk::DeviceInfo& info = context.info();
  notes_["device"] = {{"name", info.name},
                      {"type", info.typeName()},
                      {"driver", info.driverName},
                      {"driverInfo", info.driverInfo}};
  std::printf("%s on %s (%s %s)\n", name_.c_str(), info.name.c_str(), info.driverName.c_str(),
              info.driverInfo.c_str());
}

Table& Report::table(const std::string& name, const std::string& workUnit,
                     const std::string& title) {
  tables_.push_back({name, workUnit, title, "", {}});
  return tables_.back();
}

double Report::capVerticesPerSecond() const {
  if (!bandwidth_) bandwidth_ = measureHostCopyBandwidth();
  return *bandwidth_ / kVertexBytes;
}

namespace {
double throughputOf(const Case& c) {
  return c.throughput > 0 ? c.throughput
                          : (c.timing.minSeconds > 0 ? c.workSize / c.timing.minSeconds : 0);
}
}  // namespace

void Report::print(const Table& table) const {
  bool anyCap = false;
  for (const Case& c : table.cases) anyCap |= c.verticesPerSecond.has_value();
  const std::string rate = table.rateUnit.empty() ? table.workUnit + "/s" : table.rateUnit;
  std::printf("\n### %s\n\n| path | %s | min s | median s | runs | %s | ratio |%s\n"
              "|---|---|---|---|---|---|---|%s\n",
              table.title.c_str(), table.workUnit.c_str(), rate.c_str(),
              anyCap ? " of cap (measured / 5 GB/s) |" : "", anyCap ? "---|" : "");
  double base = table.cases.empty() ? 0 : throughputOf(table.cases.front());
  for (const Case& c : table.cases) {
    double rate = throughputOf(c);
    std::printf("| %s | %.0f | %.4f | %.4f | %d | %.3g | %.2f |", c.path.c_str(), c.workSize,
                c.timing.minSeconds, c.timing.medianSeconds, c.timing.runs, rate,
                base > 0 ? rate / base : 0.0);
    if (c.verticesPerSecond)
      std::printf(" %.0f %% / %.0f %% |", 100 * *c.verticesPerSecond / capVerticesPerSecond(),
                  100 * *c.verticesPerSecond / (kAssumedCopyBytesPerSecond / kVertexBytes));
    else if (anyCap)
      std::printf(" — |");
    std::printf("\n");
  }
  std::fflush(stdout);
}

void Report::finish() {
  bool anyCap = false;
  for (const Table& t : tables_)
    for (const Case& c : t.cases) anyCap |= c.verticesPerSecond.has_value();
  if (anyCap) {
    std::printf("\nbandwidth cap: host memcpy %.2f GB/s measured now → %.0f M vertices/s of %d "
                "bytes (the issue assumes 5 GB/s → %.0f M/s)\n",
                capVerticesPerSecond() * kVertexBytes / 1e9, capVerticesPerSecond() / 1e6,
                int(kVertexBytes), kAssumedCopyBytesPerSecond / kVertexBytes / 1e6);
  }
  if (jsonPath_.empty()) return;
  nlohmann::json doc = {{"bench", name_}, {"notes", notes_}, {"tables", nlohmann::json::array()}};
  if (anyCap)
    doc["bandwidthCap"] = {{"hostCopyBytesPerSecond", capVerticesPerSecond() * kVertexBytes},
                           {"vertexBytes", kVertexBytes},
                           {"capVerticesPerSecond", capVerticesPerSecond()},
                           {"assumedCopyBytesPerSecond", kAssumedCopyBytesPerSecond},
                           {"assumedCapVerticesPerSecond",
                            kAssumedCopyBytesPerSecond / kVertexBytes}};
  for (const Table& t : tables_) {
    nlohmann::json cases = nlohmann::json::array();
    double base = t.cases.empty() ? 0 : throughputOf(t.cases.front());
    for (const Case& c : t.cases) {
      double rate = throughputOf(c);
      nlohmann::json j = {{"path", c.path},
                          {"workSize", c.workSize},
                          {"minSeconds", c.timing.minSeconds},
                          {"medianSeconds", c.timing.medianSeconds},
                          {"runs", c.timing.runs},
                          {"throughput", rate},
                          {"ratioToBaseline", base > 0 ? rate / base : 0.0},
                          {"extra", c.extra}};
      if (c.verticesPerSecond) {
        j["verticesPerSecond"] = *c.verticesPerSecond;
        j["fractionOfCap"] = *c.verticesPerSecond / capVerticesPerSecond();
        j["fractionOfAssumedCap"] =
            *c.verticesPerSecond / (kAssumedCopyBytesPerSecond / kVertexBytes);
      }
      cases.push_back(j);
    }
    doc["tables"].push_back({{"name", t.name},
                             {"workUnit", t.workUnit},
                             {"rateUnit", t.rateUnit.empty() ? t.workUnit + "/s" : t.rateUnit},
                             {"title", t.title},
                             {"baseline", t.cases.empty() ? "" : t.cases.front().path},
                             {"cases", cases}});
  }
  writeFileAtomically(jsonPath_, [&](std::ostream& out) { out << doc.dump(2) << "\n"; });
}

}  // namespace tessera::bench
