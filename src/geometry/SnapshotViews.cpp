#include "geometry/SnapshotViews.h"

#include <array>
#include <numbers>

namespace termshade {

std::span<const std::string_view> SnapshotViewNames() {
  static constexpr std::array<std::string_view, 4> kNames = {"default", "opposite", "top",
                                                             "bottom"};
  return kNames;
}

std::optional<SnapshotView> SnapshotViewFor(std::string_view name, double theta, double phi) {
  constexpr double kPi = std::numbers::pi;
  if (name == "default") return SnapshotView{std::string(name), theta, phi};
  if (name == "opposite") return SnapshotView{std::string(name), theta + kPi, kPi - phi};
  if (name == "top") return SnapshotView{std::string(name), theta, kSnapshotTopPhi};
  if (name == "bottom") return SnapshotView{std::string(name), theta + kPi, kPi - kSnapshotTopPhi};
  return std::nullopt;
}

}  // namespace termshade
