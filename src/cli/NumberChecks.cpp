#include "cli/NumberChecks.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace termshade {
namespace {

std::string Shortest(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The option's text as a number, or nothing.
bool ParseNumber(const std::string& text, double& value) {
  return CLI::detail::lexical_cast(text, value);
}

}  // namespace

CLI::Validator FiniteIn(double low, double high) {
  const std::string range = Shortest(low) + " to " + Shortest(high);
  return {[low, high, range](std::string& text) -> std::string {
            double value = 0.0;
            if (!ParseNumber(text, value)) return "expected a number, not '" + text + "'";
            if (!(value >= low && value <= high)) return "must be a number from " + range;
            return {};
          },
          "NUMBER in " + range};
}

CLI::Validator FinitePositive() {
  return {[](std::string& text) -> std::string {
            double value = 0.0;
            if (!ParseNumber(text, value)) return "expected a number, not '" + text + "'";
            if (!(value > 0.0 && std::isfinite(value))) return "must be finite and positive";
            return {};
          },
          "POSITIVE"};
}

}  // namespace termshade
