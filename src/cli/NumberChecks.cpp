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

std::optional<double> ParseDurationSeconds(std::string_view text) {
  double scale = 1.0;
  if (text.ends_with("ms")) {
    scale = 1e-3;
    text.remove_suffix(2);
  } else if (text.ends_with('s')) {
    text.remove_suffix(1);
  } else {
    return std::nullopt;
  }
  double value = 0.0;
  if (text.empty() || !ParseNumber(std::string(text), value)) return std::nullopt;
  const double seconds = value * scale;
  if (!(seconds > 0.0 && seconds <= 86400.0)) return std::nullopt;
  return seconds;
}

}  // namespace termshade
