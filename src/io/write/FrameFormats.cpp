#include "io/write/FrameFormats.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <type_traits>

#include "geometry/ViewingTransform.h"
#include "io/write/AnsiCells.h"
#include "shade/CellColour.h"

namespace termshade {
namespace {

// Strict JSON has no inf or nan: a number that is not finite is null.
template <typename Number>
void AppendNumber(Number value, std::string& out) {
  if constexpr (std::is_floating_point_v<Number>) {
    if (!std::isfinite(value)) {
      out += "null";
      return;
    }
  }
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

// Significant digits of the json dump's camera numbers (SPEC 7): the last
// digits of sin and cos differ between the maths library's FMA and plain
// paths (theta 297deg: 0.891006524188368 or 0.8910065241883679), and a dump
// must be the same on every CPU. A number below 1e-12 of `scale` (the
// rounding noise about 0, as cos(pi/2) gives) is 0.
constexpr int kCameraDigits = 12;

void AppendCameraNumber(double value, double scale, std::string& out) {
  if (!(std::abs(value) >= scale * 1e-12)) value = 0.0;  // also -0
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value,
                                    std::chars_format::general, kCameraDigits);
  out.append(buffer, result.ptr);
}

void AppendJsonString(std::string_view text, std::string& out) {
  out += '"';
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
}

}  // namespace

namespace {

// SGR for one colour plane: 38/39 for the foreground, 48/49 for the
// background; the 16 ANSI colours as 30-37 and 90-97 (40-47, 100-107),
// which terminals of 8 or 16 colours know.
void AppendColourSgr(const TermColour& colour, char plane, std::string& out) {
  out += "\x1b[";
  if (colour.kind == TermColour::Kind::kIndexed && colour.index < 16) {
    const int base = plane == '3' ? 30 : 40;
    AppendNumber(colour.index < 8 ? base + colour.index : base + 60 + colour.index - 8, out);
    out += 'm';
    return;
  }
  out += plane;
  switch (colour.kind) {
    case TermColour::Kind::kDefault:
      out += "9m";
      return;
    case TermColour::Kind::kIndexed:
      out += "8;5;";
      AppendNumber(static_cast<int>(colour.index), out);
      break;
    case TermColour::Kind::kRgb:
      out += "8;2;";
      AppendNumber(static_cast<int>(colour.rgb.r), out);
      out += ';';
      AppendNumber(static_cast<int>(colour.rgb.g), out);
      out += ';';
      AppendNumber(static_cast<int>(colour.rgb.b), out);
      break;
  }
  out += 'm';
}

}  // namespace

void AppendForegroundSgr(const TermColour& colour, std::string& out) {
  AppendColourSgr(colour, '3', out);
}

void AppendBackgroundSgr(const TermColour& colour, std::string& out) {
  AppendColourSgr(colour, '4', out);
}

namespace {

template <typename PerCell>
void AppendGrid(const CellBuffer& cells, std::string_view key, PerCell perCell, std::string& out) {
  out += ", \"";
  out += key;
  out += "\": [";
  for (int row = 0; row < cells.HeightCells(); ++row) {
    out += row == 0 ? "[" : ", [";
    for (int col = 0; col < cells.WidthCells(); ++col) {
      if (col > 0) out += ',';
      perCell(cells.Index(col, row));
    }
    out += ']';
  }
  out += ']';
}

// "glyphMode", "samples": [k, m] and "sampleFaces": per cell its k x m faces, row-major.
void AppendSampleFaces(const CellBuffer& cells, const RenderOptions& options,
                       const JsonSamples& samples, std::string& out) {
  const int k = samples.grid.across, m = samples.grid.down;
  out += ", \"glyphMode\": ";
  AppendJsonString(GlyphModeName(options.glyphs), out);
  out += ", \"samples\": [";
  AppendNumber(k, out);
  out += ", ";
  AppendNumber(m, out);
  out += ']';
  AppendGrid(
      cells, "sampleFaces",
      [&](size_t i) {
        const int col = static_cast<int>(i % cells.WidthCells());
        const int row = static_cast<int>(i / cells.WidthCells());
        out += '[';
        for (int j = 0; j < m; ++j) {
          for (int s = 0; s < k; ++s) {
            if (j + s > 0) out += ',';
            AppendNumber(samples.samples.FaceNumber(col * k + s, row * m + j), out);
          }
        }
        out += ']';
      },
      out);
}

}  // namespace

std::optional<FrameFormat> ParseFrameFormat(std::string_view name) {
  if (name == "text") return FrameFormat::kText;
  if (name == "ansi") return FrameFormat::kAnsi;
  if (name == "json") return FrameFormat::kJson;
  if (name == "svg") return FrameFormat::kSvg;
  if (name == "asciicast") return FrameFormat::kAsciicast;
  return std::nullopt;
}

void AppendTextFrame(const CellBuffer& cells, std::string& out) {
  for (int row = 0; row < cells.HeightCells(); ++row) {
    out += cells.RowText(row);
    out += '\n';
  }
}

void AppendAnsiFrame(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                     ColourMode mode, std::string& out, Background background) {
  AnsiCells ansiCells;
  FillAnsiCells(cells, faceColours, levelCount, mode, ansiCells, background);
  AppendAnsiRows(ansiCells, out);
}

void AppendJsonFrame(const CellBuffer& cells, const DepthBuffer& depth, const Scene& scene,
                     const Camera& camera, const RenderOptions& options, std::string& out,
                     const JsonSamples* samples) {
  const Mat4 eyeFromFile = EyeFromWorld(camera.view) * scene.worldFromFile;
  out += "{\"format\": \"termshade-frame/1\", \"cols\": ";
  AppendNumber(cells.WidthCells(), out);
  out += ", \"rows\": ";
  AppendNumber(cells.HeightCells(), out);
  out += ", \"cellAspect\": ";
  AppendNumber(camera.projection.cellAspect, out);
  out += ", \"method\": ";
  AppendJsonString(MethodName(options.method), out);
  out += ", \"shade\": ";
  AppendJsonString(ShadeModeName(options.shade), out);
  out += ", \"camera\": {\"rho\": ";
  AppendNumber(camera.view.rho, out);
  out += ", \"theta\": ";
  AppendNumber(camera.view.theta, out);
  out += ", \"phi\": ";
  AppendNumber(camera.view.phi, out);
  out += ", \"eyeFromFile\": [";
  double matrixScale = 0.0;
  for (const double entry : eyeFromFile.m) matrixScale = std::max(matrixScale, std::abs(entry));
  for (size_t i = 0; i < eyeFromFile.m.size(); ++i) {
    if (i > 0) out += ", ";
    AppendCameraNumber(eyeFromFile.m[i], matrixScale, out);
  }
  out += "], \"d\": ";
  AppendCameraNumber(camera.projection.d, std::abs(camera.projection.d), out);
  out += ", \"center\": [";
  AppendCameraNumber(camera.projection.cx, std::abs(camera.projection.cx), out);
  out += ", ";
  AppendCameraNumber(camera.projection.cy, std::abs(camera.projection.cy), out);
  out += "]}, \"glyphs\": [";
  for (int row = 0; row < cells.HeightCells(); ++row) {
    if (row > 0) out += ", ";
    AppendJsonString(cells.RowText(row), out);
  }
  out += ']';
  const CellBuffer& center = samples ? samples->center : cells;
  const DepthBuffer& centerDepth = samples ? samples->centerDepth : depth;
  AppendGrid(
      cells, "faces", [&](size_t i) { AppendNumber(center.FaceNumbers()[i], out); }, out);
  AppendGrid(
      cells, "depth",
      [&](size_t i) {
        const float w = centerDepth.At(i);
        AppendNumber(w > 0.0F ? 1.0F / w : 0.0F, out);
      },
      out);
  if (samples) AppendSampleFaces(cells, options, *samples, out);
  out += "}\n";
}

}  // namespace termshade
