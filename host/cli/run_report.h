// The stats report's `run` member and how a finished report leaves the process: the held,
// streamed and CAD `tessera tessellate` jobs share both (cmd_tessellate.cpp,
// streamed_tessellate.cpp, cad_job.cpp).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "vk/context.h"

namespace tessera::cli {

// {input, output (null when none), backend, device (null on the CPU backend)}.
nlohmann::json runToJson(const std::string& input, const std::string& output,
                         const std::string& backend, const vk::Context* context);

// Stages the report into `statsPath` (when a file is named: "-" means standard output), and
// prints it to standard output when `printJson` or `statsPath` is "-".
void emitReport(const nlohmann::json& report, AtomicFileGroup& files, const std::string& statsPath,
                bool printJson);

}  // namespace tessera::cli
