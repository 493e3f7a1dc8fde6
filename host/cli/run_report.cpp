#include "cli/run_report.h"

#include <cstdio>

#include "cli/stdio.h"
#include "io/stats_report.h"

namespace tessera::cli {

nlohmann::json runToJson(const std::string& input, const std::string& output,
                         const std::string& backend, const vk::Context* context) {
  return {{"input", input},
          {"output", output.empty() ? nlohmann::json() : nlohmann::json(output)},
          {"backend", backend},
          {"device", context ? nlohmann::json(context->info().name) : nlohmann::json()}};
}

void emitReport(const nlohmann::json& report, AtomicFileGroup& files, const std::string& statsPath,
                bool printJson) {
  const bool toStdout = statsPath == kStdioPath;
  if (!statsPath.empty() && !toStdout)
    files.stage(statsPath, [&](std::ostream& out) { writeStats(out, report); });
  // Invalid UTF-8 in a file name must not abort the report: it is replaced, not thrown.
  if (printJson || toStdout)
    std::printf("%s\n",
                report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
}

}  // namespace tessera::cli
