#include "cli/number_checks.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

namespace angio {

namespace {

// What is wrong with `text` as a number that `accepts`, or "" when nothing is. A text that is no
// number at all is left to the option's own conversion, which names it.
std::string numberProblem(const std::string& text, const std::function<bool(double)>& accepts,
                          const std::string& wanted) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return "";
  if (!std::isfinite(value)) return text + " is not a finite number";
  if (!accepts(value)) return text + " is not " + wanted;
  return "";
}

std::string shortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

CLI::Validator numberCheck(std::function<bool(double)> accepts, const std::string& wanted) {
  return CLI::Validator(
      [accepts, wanted](std::string& text) { return numberProblem(text, accepts, wanted); }, wanted);
}

}  // namespace

CLI::Validator finiteNumber() {
  return numberCheck([](double) { return true; }, "a finite number");
}
CLI::Validator numberAbove(double bound) {
  return numberCheck([bound](double v) { return v > bound; }, "a number > " + shortNumber(bound));
}
CLI::Validator numberAtLeast(double bound) {
  return numberCheck([bound](double v) { return v >= bound; }, "a number >= " + shortNumber(bound));
}
CLI::Validator numberBetween(double lo, double hi) {
  return numberCheck([lo, hi](double v) { return v >= lo && v <= hi; },
                     "a number in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]");
}

void requireFiniteNumbers(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finiteNumber());
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) requireFiniteNumbers(*sub);
}

std::string oneLineFailure(const CLI::App*, const CLI::Error& error) {
  std::string message = error.what();
  for (char& c : message)
    if (c == '\n') c = ' ';
  return "angioray: error: " + message + " (--help lists the options)\n";
}

}  // namespace angio
