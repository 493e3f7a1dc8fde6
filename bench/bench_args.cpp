#include "bench_args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "bench_report.h"

namespace tessera::bench {

void atMostArguments(const Report& report, int argc, char** argv, int most) {
  if (argc - 1 > most)
    report.usageError(std::string("unexpected argument '") + argv[most + 1] + "'");
}

long integerArg(const Report& report, const std::string& text, const char* what, long min,
                long max) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < min || value > max)
    report.usageError(std::string(what) + " '" + text + "': expected a whole number from " +
                      std::to_string(min) + " to " + std::to_string(max));
  return value;
}

double numberArg(const Report& report, const std::string& text, const char* what, double min) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value < min) {
    std::ostringstream expected;
    expected << what << " '" << text << "': expected a number ≥ " << min;
    report.usageError(expected.str());
  }
  return value;
}

std::vector<double> numberListArg(const Report& report, const std::string& text, const char* what,
                                  double min) {
  std::vector<double> values;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');)
    values.push_back(numberArg(report, item, what, min));
  if (values.empty()) report.usageError(std::string(what) + ": expected at least one number");
  return values;
}

}  // namespace tessera::bench
