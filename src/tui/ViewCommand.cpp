#include "tui/ViewCommand.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>

#include "shade/GlyphMode.h"
#include "shade/ShadeRamp.h"
#include "shade/Utf8.h"
#include "tui/ShellQuote.h"

namespace termshade {
namespace {

// "--name value", or "--name=value" for a value CLI11 could take for an option.
std::string Option(std::string_view name, const std::string& value) {
  std::string text(" ");
  text.append(name).append(value.starts_with('-') ? "=" : " ").append(value);
  return text;
}

std::string RampText(const ShadeRamp& ramp) {
  std::string text;
  for (int level = 0; level < ramp.LevelCount(); ++level) AppendUtf8(text, ramp.Glyph(level));
  return text;
}

}  // namespace

std::string ExactNumber(double value) {
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  if (error == std::errc{}) {
    *end = '\0';
    if (std::strtod(text, nullptr) == value &&
        static_cast<double>(std::strtold(text, nullptr)) == value)
      return text;
  }
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string RenderCommandFor(const ViewToReproduce& shown) {
  std::string command = "termshade render " + ShellQuote(shown.modelPath);
  command +=
      Option("--size", std::to_string(shown.widthCells) + "x" + std::to_string(shown.heightCells));
  command += Option("--theta", ExactNumber(shown.view.theta));
  command += Option("--phi", ExactNumber(shown.view.phi));
  command += Option("--rho", ExactNumber(shown.view.rho));
  command += " --fit";
  if (shown.fitRho > 0.0) command += Option("--fit-rho", ExactNumber(shown.fitRho));
  command += Option("--up", std::string(UpAxisName(shown.upAxis)));
  command += Option("--cell-aspect", ExactNumber(shown.cellAspect));
  command += Option("--method", std::string(MethodName(shown.render.method)));
  command += Option("--shade", std::string(ShadeModeName(shown.render.shade)));
  command += Option("--glyphs", std::string(GlyphModeName(shown.render.glyphs)));
  if (const std::string ramp = RampText(shown.render.ramp); ramp != ShadeRamp::kDefaultGlyphs)
    command += Option("--ramp", ShellQuote(ramp));
  if (!shown.render.cullBackFaces) command += " --no-cull";
  if (!shown.render.textures) command += " --textures off";
  if (shown.sunAzimuthRadians != 0.0 || shown.sunElevationRadians != 0.0) {
    command += Option("--light", ExactNumber(shown.sunAzimuthRadians) + "," +
                                     ExactNumber(shown.sunElevationRadians));
  }
  if (shown.levelOfDetail) command += " --lod auto";
  command += Option("--color", std::string(ColourModeName(shown.colour)));
  command += Option("--background", std::string(BackgroundName(shown.background)));
  if (shown.colour != ColourMode::kNone) command += " --format ansi";
  return command;
}

}  // namespace termshade
