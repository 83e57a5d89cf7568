#pragma once

#include <optional>
#include <string_view>

namespace termshade {

/// The terminal's background: shades run from close to it (their darkest on
/// a dark one, their brightest on a light one) to the far end, and keep a
/// minimum contrast against it so silhouettes stay visible.
enum class Background { kDark, kLight };

/// `dark` or `light`.
std::optional<Background> ParseBackground(std::string_view name);
std::string_view BackgroundName(Background background);

/// The background a terminal's COLORFGBG ("15;0", "0;default;15": the last
/// field is the background's colour number) says; nullopt when it says nothing.
std::optional<Background> BackgroundFromColorFgBg(std::string_view colorFgBg);

}  // namespace termshade
