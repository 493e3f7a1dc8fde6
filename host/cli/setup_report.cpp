#include "cli/setup_report.h"

namespace tessera::cli {

nlohmann::json setupToJson(const vk::Context* context) {
  if (!context) return nullptr;
  const vk::ContextTimings t = context->timings();
  return {{"contextMs", t.contextMs()},
          {"instanceMs", t.instanceMs},
          {"deviceMs", t.deviceMs},
          {"pipelineCacheMs", t.pipelineCacheMs},
          {"pipelineCacheBytes", context->pipelineCacheLoadedBytes()},
          {"pipelinesMs", t.pipelinesMs},
          {"pipelines", t.pipelines},
          {"firstSubmitMs", t.firstSubmitMs},
          {"submitsMs", t.submitsMs},
          {"submits", t.submits}};
}

void printSetup(FILE* to, const vk::ContextTimings& t) {
  std::fprintf(to,
               "vulkan setup: context %.1f ms (instance %.1f, device %.1f, pipeline cache %.1f), "
               "%u pipelines %.1f ms, first dispatch %.1f ms, %u dispatches %.1f ms\n",
               t.contextMs(), t.instanceMs, t.deviceMs, t.pipelineCacheMs, t.pipelines,
               t.pipelinesMs, t.firstSubmitMs, t.submits, t.submitsMs);
}

}  // namespace tessera::cli
