#include "io/FrameFormats.h"

#include <charconv>

#include "geometry/ViewingTransform.h"
#include "shade/CellColour.h"
#include "shade/Utf8.h"

namespace termshade {
namespace {

template <typename Number>
void AppendNumber(Number value, std::string& out) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
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

void AppendForegroundSgr(const TermColour& colour, std::string& out) {
  switch (colour.kind) {
    case TermColour::Kind::kDefault:
      out += "\x1b[39m";
      return;
    case TermColour::Kind::kIndexed:
      out += "\x1b[38;5;";
      AppendNumber(static_cast<int>(colour.index), out);
      break;
    case TermColour::Kind::kRgb:
      out += "\x1b[38;2;";
      AppendNumber(static_cast<int>(colour.rgb.r), out);
      out += ';';
      AppendNumber(static_cast<int>(colour.rgb.g), out);
      out += ';';
      AppendNumber(static_cast<int>(colour.rgb.b), out);
      break;
  }
  out += 'm';
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

}  // namespace

std::optional<FrameFormat> ParseFrameFormat(std::string_view name) {
  if (name == "text") return FrameFormat::kText;
  if (name == "ansi") return FrameFormat::kAnsi;
  if (name == "json") return FrameFormat::kJson;
  return std::nullopt;
}

void AppendTextFrame(const CellBuffer& cells, std::string& out) {
  for (int row = 0; row < cells.HeightCells(); ++row) {
    out += cells.RowText(row);
    out += '\n';
  }
}

void AppendAnsiFrame(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                     ColourMode mode, std::string& out) {
  CellColourMap colours(faceColours, levelCount, mode);
  for (int row = 0; row < cells.HeightCells(); ++row) {
    TermColour current;  // the terminal's default until a face sets one
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const int level = cells.Level(col, row);
      if (level >= 0 && mode != ColourMode::kNone) {  // the background keeps the default
        const TermColour wanted = colours.ForFace(cells.FaceNumber(col, row), level);
        if (!(wanted == current)) AppendForegroundSgr(wanted, out);
        current = wanted;
      }
      AppendUtf8(out, cells.Glyph(col, row));
    }
    if (!(current == TermColour{})) out += "\x1b[0m";
    out += '\n';
  }
}

void AppendJsonFrame(const CellBuffer& cells, const DepthBuffer& depth, const Scene& scene,
                     const Camera& camera, const RenderOptions& options, std::string& out) {
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
  for (size_t i = 0; i < eyeFromFile.m.size(); ++i) {
    if (i > 0) out += ", ";
    AppendNumber(eyeFromFile.m[i], out);
  }
  out += "], \"d\": ";
  AppendNumber(camera.projection.d, out);
  out += ", \"center\": [";
  AppendNumber(camera.projection.cx, out);
  out += ", ";
  AppendNumber(camera.projection.cy, out);
  out += "]}, \"glyphs\": [";
  for (int row = 0; row < cells.HeightCells(); ++row) {
    if (row > 0) out += ", ";
    AppendJsonString(cells.RowText(row), out);
  }
  out += ']';
  AppendGrid(
      cells, "faces", [&](size_t i) { AppendNumber(cells.FaceNumbers()[i], out); }, out);
  AppendGrid(
      cells, "depth",
      [&](size_t i) {
        const float w = depth.At(i);
        AppendNumber(w > 0.0F ? 1.0F / w : 0.0F, out);
      },
      out);
  out += "}\n";
}

}  // namespace termshade
