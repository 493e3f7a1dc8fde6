#include "cli/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace tessera::cli {

double progressIntervalSeconds() {
  if (const char* env = std::getenv("TESSERA_PROGRESS_INTERVAL"); env && *env) {
    char* end = nullptr;
    const double seconds = std::strtod(env, &end);
    if (*end == '\0' && std::isfinite(seconds) && seconds >= 0) return seconds;
  }
  return 2.0;
}

Progress::Progress(bool enabled, double intervalSeconds)
    : enabled_(enabled), intervalSeconds_(intervalSeconds) {}

void Progress::update(const std::string& message) {
  if (!enabled_) return;
  if (sinceLastLine_.elapsedSeconds() < intervalSeconds_) return;
  sinceLastLine_.restart();
  std::fprintf(stderr, "tessera: %s\n", message.c_str());
  std::fflush(stderr);
}

std::function<void(const LevelStats&)> Progress::treeCallback(size_t patchCount) {
  if (!enabled_ || patchCount == 0) return {};
  return [this, patchCount](const LevelStats& level) {
    // onLevel passes the level's totals so far (a level may come in several batches).
    if (seen_.size() <= level.level) seen_.resize(level.level + 1);
    LevelStats& seen = seen_[level.level];
    settled_ += std::ldexp(double(level.leaves - seen.leaves), -2 * int(level.level));
    classified_ += level.nodes - seen.nodes;
    seen = level;
    // Floored to 0.1%, so 100.0% means done.
    const double percent = std::min(100.0, std::floor(1000.0 * settled_ / patchCount) / 10.0);
    char line[128];
    std::snprintf(line, sizeof line,
                  "quad-tree level %u, %.1f%% of the patches settled, %zu nodes classified",
                  level.level, percent, classified_);
    update(line);
  };
}

}  // namespace tessera::cli
