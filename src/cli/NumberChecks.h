#pragma once

#include <CLI/CLI.hpp>

namespace termshade {

/// A CLI11 check for a finite number in [low, high]: CLI::Range lets NaN
/// through (every comparison with it is false).
CLI::Validator FiniteIn(double low, double high);

/// A CLI11 check for a finite number above zero, with a short message
/// (CLI::PositiveNumber prints the largest double in full).
CLI::Validator FinitePositive();

}  // namespace termshade
