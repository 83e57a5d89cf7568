#pragma once

#include <string_view>

namespace termshade {

/// The .dat text of the scene the viewer opens when no model is given
/// (data/sphere_cone.dat, embedded at build time).
std::string_view DemoSceneText();
constexpr std::string_view kDemoSceneName = "demo";

}  // namespace termshade
