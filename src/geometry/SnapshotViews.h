#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace termshade {

/// One view of a snapshot: its name and eye angles (SPEC 2, radians).
struct SnapshotView {
  std::string name;
  double theta = 0.3;
  double phi = 1.3;
};

/// The views a snapshot may hold, in the order they are drawn: `default`
/// (theta, phi), `opposite` (the eye through the center: theta + pi,
/// pi - phi), `top` (theta, kSnapshotTopPhi) and `bottom` (theta + pi,
/// pi - kSnapshotTopPhi). Together they see most of a model's surface.
std::span<const std::string_view> SnapshotViewNames();

/// Polar angle of the top view: a little off the axis, so sides facing
/// straight up are not seen edge-on at a fill-rule tie.
constexpr double kSnapshotTopPhi = 0.25;

/// The named view about (theta, phi); nullopt for a name not in SnapshotViewNames().
std::optional<SnapshotView> SnapshotViewFor(std::string_view name, double theta, double phi);

}  // namespace termshade
