#include "experiments/reduction_table.h"

#include <cmath>
#include <cstdio>

#include "common/stopwatch.h"
#include "reduction/fast.h"

namespace tessera {

namespace {

double isoCurvature(const SurfaceDerivatives& d, bool alongU) {
  const glm::dvec3& t1 = alongU ? d.pu : d.pv;
  const glm::dvec3& t2 = alongU ? d.puu : d.pvv;
  const double speed = glm::length(t1);
  return speed > 0.0 ? glm::length(glm::cross(t1, t2)) / (speed * speed * speed) : 0.0;
}

std::string stops(const ReductionResult& r) {
  std::string out;
  for (const PassReport& pass : r.passes) {
    if (!out.empty()) out += ", ";
    out += std::string(directionName(pass.direction)) + ": " + stopReasonName(pass.stop);
  }
  return out;
}

}  // namespace

double waviness(const BSplineSurface& s, int isoCurves, int samples) {
  const double u0 = s.knotsU[static_cast<size_t>(s.degreeU)], u1 = s.knotsU[static_cast<size_t>(s.countU)];
  const double v0 = s.knotsV[static_cast<size_t>(s.degreeV)], v1 = s.knotsV[static_cast<size_t>(s.countV)];
  double total = 0.0;
  for (int dir = 0; dir < 2; ++dir) {
    const bool alongU = dir == 0;
    for (int c = 0; c < isoCurves; ++c) {
      const double fixed = (c + 0.5) / isoCurves;
      double previous = 0.0;
      for (int k = 0; k <= samples; ++k) {
        const double t = static_cast<double>(k) / samples;
        const double u = alongU ? u0 + t * (u1 - u0) : u0 + fixed * (u1 - u0);
        const double v = alongU ? v0 + fixed * (v1 - v0) : v0 + t * (v1 - v0);
        const double kappa = isoCurvature(surfaceDerivatives(s, u, v), alongU);
        if (k > 0) total += std::abs(kappa - previous);
        previous = kappa;
      }
    }
  }
  return total / (2.0 * isoCurves);
}

std::vector<ReductionTableRow> reductionTable(const BSplineSurface& surface,
                                              const std::vector<double>& thresholds,
                                              const ReductionOptions& base,
                                              CurveProduct* product,
                                              const std::vector<KnotChoice>& choices) {
  std::vector<ReductionTableRow> rows;
  for (double threshold : thresholds) {
    for (KnotChoice choice : choices) {
      ReductionOptions o = base;
      o.threshold = threshold;
      o.choice = choice;
      ReductionTableRow row;
      row.threshold = threshold;
      row.choice = choice;
      const Stopwatch stopwatch;
      row.result = reduceSurface(surface, o, product);
      row.seconds = stopwatch.elapsedSeconds();
      row.waviness = waviness(row.result.surface);
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::string formatReductionTable(const std::vector<ReductionTableRow>& rows,
                                 double originalWaviness) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "%-9s  %-9s  %13s  %9s  %10s  %10s  %10s  %7s  %s\n",
                "threshold", "knots", "kept", "ratio %", "waviness", "mean err", "max err",
                "time s", "stopped by");
  out += line;
  for (const ReductionTableRow& r : rows) {
    const std::string kept = std::to_string(r.result.surface.countU) + "x" +
                             std::to_string(r.result.surface.countV);
    std::snprintf(line, sizeof line, "%-9g  %-9s  %13s  %9.3f  %10.4f  %10.3g  %10.3g  %7.2f  %s\n",
                  r.threshold, knotChoiceName(r.choice),
                  kept.c_str(), r.result.compressionPercent(), r.waviness, r.result.error.mean,
                  r.result.error.max, r.seconds, stops(r.result).c_str());
    out += line;
  }
  std::snprintf(line, sizeof line, "original waviness %.4f (1/mm: total variation of curvature along iso-curves)\n",
                originalWaviness);
  out += line;
  return out;
}

}  // namespace tessera
