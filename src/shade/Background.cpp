#include "shade/Background.h"

#include <charconv>

namespace termshade {

std::optional<Background> ParseBackground(std::string_view name) {
  if (name == "dark") return Background::kDark;
  if (name == "light") return Background::kLight;
  return std::nullopt;
}

std::string_view BackgroundName(Background background) {
  return background == Background::kLight ? "light" : "dark";
}

std::optional<Background> BackgroundFromColorFgBg(std::string_view colorFgBg) {
  const size_t separator = colorFgBg.rfind(';');
  if (separator == std::string_view::npos) return std::nullopt;
  const std::string_view field = colorFgBg.substr(separator + 1);
  int colour = -1;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), colour);
  if (error != std::errc() || end != field.data() + field.size() || colour < 0 || colour > 15)
    return std::nullopt;
  // The 16 colours: 7 (light grey) and 9-15 are light; 0-6 and 8 are dark.
  return colour == 7 || colour >= 9 ? Background::kLight : Background::kDark;
}

}  // namespace termshade
