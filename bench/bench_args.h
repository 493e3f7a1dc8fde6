// A benchmark's own arguments, checked: a number where a number is asked, within its range,
// so a typo ends with what was wrong and the usage (exit 2), never with an uncaught exception
// or a run at a silently wrong size. bench::Report handles -h / --help and --json.
#pragma once
#include <string>
#include <vector>

namespace tessera::bench {

class Report;

// More than `most` positional arguments (argv after Report took its own) is a usage error.
void atMostArguments(const Report& report, int argc, char** argv, int most);
// `text` as an integer in [min, max]; `what` names it in the error ("patches").
long integerArg(const Report& report, const std::string& text, const char* what, long min,
                long max);
// `text` as a finite number ≥ min.
double numberArg(const Report& report, const std::string& text, const char* what, double min);
// A comma-separated list of finite numbers ≥ min, at least one ("0.01,0.001").
std::vector<double> numberListArg(const Report& report, const std::string& text, const char* what,
                                  double min);

}  // namespace tessera::bench
