#pragma once

#include <algorithm>
#include <vector>

namespace termshade {

/// The median of a sample (the mean of the middle two for an even count); 0 when empty.
template <typename T>
double Median(std::vector<T> values) {
  if (values.empty()) return 0.0;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  const double upper = static_cast<double>(values[middle]);
  if (values.size() % 2 == 1) return upper;
  const double lower = static_cast<double>(
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle)));
  return (lower + upper) / 2.0;
}

}  // namespace termshade
