#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string_view>

namespace termshade {

/// A CLI11 check for a finite number in [low, high]: CLI::Range lets NaN
/// through (every comparison with it is false).
CLI::Validator FiniteIn(double low, double high);

/// A CLI11 check for a finite number above zero, with a short message
/// (CLI::PositiveNumber prints the largest double in full).
CLI::Validator FinitePositive();

/// A duration such as 300ms, 1.5s or 2s, in seconds: finite, above zero,
/// at most a day; nothing for anything else (a bare number too).
std::optional<double> ParseDurationSeconds(std::string_view text);

}  // namespace termshade
