#include "io/read/SnapshotGoldenReader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>

#include "io/read/RegularFile.h"
#include "shade/Utf8.h"

namespace termshade {
namespace {

// The golden's lines, one at a time, with the number of the current one.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  bool Next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    const size_t end = std::min(text_.find('\n', position_), text_.size());
    line = text_.substr(position_, end - position_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position_ = end + 1;
    ++number_;
    return true;
  }
  int Number() const { return number_; }

 private:
  std::string_view text_;
  size_t position_ = 0;
  int number_ = 0;
};

// Thrown inside the parser, turned into a LoadError at its edge.
struct GoldenProblem {
  int line;
  std::string message;
};

std::vector<std::string_view> Words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && line[i] == ' ') ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

template <typename T>
std::optional<T> Number(std::string_view text) {
  T value{};
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) return std::nullopt;
  }
  return value;
}

// "AxB" with A in 1..maxA, B in 1..maxB.
std::optional<std::pair<int, int>> Dimensions(std::string_view text, int maxA, int maxB) {
  const size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto a = Number<int>(text.substr(0, x)), b = Number<int>(text.substr(x + 1));
  if (!a || !b || *a < 1 || *b < 1 || *a > maxA || *b > maxB) return std::nullopt;
  return std::pair{*a, *b};
}

class GoldenParser {
 public:
  explicit GoldenParser(std::string_view text) : lines_(text) {}

  SnapshotGolden Parse() {
    std::string_view line;
    if (!lines_.Next(line) || line != "termshade-snapshot/1") {
      Fail("not a termshade snapshot golden (the first line must be termshade-snapshot/" +
           std::to_string(kSnapshotFormatVersion) + ")");
    }
    ParseHeader();
    for (const std::string& name : golden_.settings.views) ParseView(name);
    while (lines_.Next(line)) {
      if (!line.empty() && line[0] != '#') Fail("unexpected text after the last view");
    }
    return std::move(golden_);
  }

 private:
  [[noreturn]] void Fail(std::string message) const {
    throw GoldenProblem{lines_.Number(), std::move(message)};
  }

  // The next line that is neither blank nor a comment.
  std::string_view NextContent(const char* what) {
    std::string_view line;
    while (lines_.Next(line)) {
      if (!line.empty() && line[0] != '#') return line;
    }
    Fail(std::string("the file ends before ") + what);
  }

  void ParseHeader() {
    SnapshotSettings& s = golden_.settings;
    std::set<std::string> seen;
    const std::set<std::string, std::less<>> required = {
        "size",   "cell-aspect", "theta", "phi", "method",  "shade",
        "glyphs", "ramp",        "cull",  "up",  "samples", "views"};
    while (seen.size() < required.size()) {
      const std::string_view line = NextContent("the header's `views` line");
      const size_t space = line.find(' ');
      const std::string key(line.substr(0, space));
      const std::string_view value =
          space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
      if (!required.contains(key)) Fail("unknown header line `" + key + "`");
      if (!seen.insert(key).second) Fail("`" + key + "` is given twice");
      if (key == "size") {
        const auto size = Dimensions(value, 4096, 2048);
        if (!size) Fail("size must be COLSxROWS, at most 4096x2048");
        s.widthCells = size->first;
        s.heightCells = size->second;
      } else if (key == "cell-aspect") {
        const auto aspect = Number<double>(value);
        if (!aspect || *aspect < 0.25 || *aspect > 8.0) Fail("cell-aspect must be 0.25 to 8");
        s.cellAspect = *aspect;
      } else if (key == "theta" || key == "phi") {
        const auto angle = Number<double>(value);
        if (!angle || std::abs(*angle) > 1e6) Fail(key + " must be a number of radians");
        (key == "theta" ? s.theta : s.phi) = *angle;
      } else if (key == "method") {
        const auto method = ParseMethod(value);
        if (!method) Fail("method must be zbuffer, painter, cull, wire or auto");
        s.method = *method;
      } else if (key == "shade") {
        const auto shade = ParseShadeMode(value);
        if (!shade) Fail("shade must be contrast or lambert");
        s.shade = *shade;
      } else if (key == "glyphs") {
        const auto glyphs = ParseGlyphMode(value);
        if (!glyphs) Fail("glyphs must be ramp, ascii, blocks, quadrants, sextants or braille");
        s.glyphs = *glyphs;
      } else if (key == "ramp") {
        s.ramp = std::string(value);
        if (const auto problem = ShadeRamp::Problem(s.ramp)) Fail("ramp: " + *problem);
      } else if (key == "cull") {
        if (value != "on" && value != "off") Fail("cull must be on or off");
        s.cullBackFaces = value == "on";
      } else if (key == "up") {
        if (value == "auto") {
          golden_.upAxis.reset();
        } else {
          golden_.upAxis = ParseUpAxis(value);
          if (!golden_.upAxis) Fail("up must be auto, x, y, z, -x, -y or -z");
        }
      } else if (key == "samples") {
        const auto grid = Dimensions(value, 8, 16);
        if (!grid) Fail("samples must be AxB, at most 8x16 a cell");
        s.samples = {grid->first, grid->second};
      } else {  // views
        if (!seen.contains("size") || !seen.contains("samples")) {
          Fail("`views` must come after `size` and `samples`");
        }
        s.views.clear();
        for (const std::string_view name : Words(value)) {
          if (!SnapshotViewFor(name, 0.0, 0.0)) {
            Fail("unknown view `" + std::string(name) + "` (default, opposite, top or bottom)");
          }
          if (std::find(s.views.begin(), s.views.end(), name) != s.views.end()) {
            Fail("view `" + std::string(name) + "` is listed twice");
          }
          s.views.emplace_back(name);
        }
        if (s.views.empty()) Fail("`views` names no view");
      }
    }
    const int64_t perView =
        int64_t{s.widthCells} * s.samples.across * s.heightCells * s.samples.down;
    if (perView > kMaxSnapshotViewSamples) {
      Fail("size x samples is " + std::to_string(perView) + " samples a view, more than " +
           std::to_string(kMaxSnapshotViewSamples));
    }
  }

  void ParseView(const std::string& name) {
    const SnapshotSettings& s = golden_.settings;
    if (NextContent(("view " + name).c_str()) != "view " + name) {
      Fail("expected `view " + name + "` (the views in the order of the header)");
    }
    SnapshotFrame frame;
    frame.view = *SnapshotViewFor(name, s.theta, s.phi);
    std::string_view line;
    for (int row = 0; row < s.heightCells; ++row) {
      if (!lines_.Next(line)) Fail("the file ends inside view " + name + "'s frame");
      if (line.size() < 2 || line.front() != '|' || line.back() != '|') {
        Fail("a frame row must be the row's characters between two `|`");
      }
      const std::string_view text = line.substr(1, line.size() - 2);
      const auto codePoints = DecodeUtf8(text);
      if (!codePoints || static_cast<int>(codePoints->size()) != s.widthCells) {
        Fail("a frame row must be " + std::to_string(s.widthCells) + " UTF-8 characters");
      }
      for (const char32_t cell : *codePoints) {
        if (IsControlOrFormat(cell)) {
          Fail("a frame row may not hold control or format characters");
        }
      }
      frame.textRows.emplace_back(text);
    }
    std::string_view after = ParseSamples(frame.samples);
    if (after.starts_with("textures ")) {
      ParseTextureColours(after, frame.textureColours);
      if (!lines_.Next(after)) after = {};
    }
    if (!after.empty() && !after.starts_with("#")) {
      Fail("expected a blank line after the shades (or the texture colours)");
    }
    golden_.frames.push_back(std::move(frame));
  }

  // `textures WxH` (the frame's size), then a line a row: RRGGBB or - runs, or `=`.
  void ParseTextureColours(std::string_view head, std::vector<uint32_t>& colours) {
    const SnapshotSettings& s = golden_.settings;
    const int width = s.widthCells, height = s.heightCells;
    if (head != "textures " + std::to_string(width) + "x" + std::to_string(height)) {
      Fail("expected `textures " + std::to_string(width) + "x" + std::to_string(height) + "`");
    }
    colours.reserve(static_cast<size_t>(width) * height);
    std::string_view line;
    for (int y = 0; y < height; ++y) {
      if (!lines_.Next(line)) Fail("the file ends inside the texture colours");
      if (line == "=") {
        if (y == 0) Fail("`=` repeats the row above; the first row has none");
        colours.insert(colours.end(), colours.end() - width, colours.end());
        continue;
      }
      int64_t count = 0;
      for (const std::string_view token : Words(line)) {
        const size_t star = token.find('*');
        const std::string_view value = token.substr(0, star);
        const auto run = star == std::string_view::npos ? std::optional<int>(1)
                                                        : Number<int>(token.substr(star + 1));
        uint32_t rgb = 0;
        const bool hex =
            value.size() == 6 &&
            std::from_chars(value.data(), value.data() + 6, rgb, 16).ptr == value.data() + 6;
        if ((value != "-" && !hex) || !run || *run < 1) {
          Fail("a texture colour run must be RRGGBB or -, then *COUNT or nothing");
        }
        count += *run;
        if (count > width) Fail("a texture row must hold " + std::to_string(width) + " cells");
        colours.insert(colours.end(), static_cast<size_t>(*run),
                       value == "-" ? 0U : rgb | 0x01000000U);
      }
      if (count != width) Fail("a texture row must hold " + std::to_string(width) + " cells");
    }
  }

  // Returns the line after the shades (empty at the end of the file).
  std::string_view ParseSamples(SnapshotSamples& samples) {
    const SnapshotSettings& s = golden_.settings;
    const int width = s.widthCells * s.samples.across, height = s.heightCells * s.samples.down;
    std::string_view line;
    if (!lines_.Next(line) ||
        line != "samples " + std::to_string(width) + "x" + std::to_string(height)) {
      Fail("expected `samples " + std::to_string(width) + "x" + std::to_string(height) + "`");
    }
    samples.widthSamples = width;
    samples.heightSamples = height;
    samples.faces.reserve(static_cast<size_t>(width) * height);
    for (int y = 0; y < height; ++y) {
      if (!lines_.Next(line)) Fail("the file ends inside the samples");
      if (line == "=") {
        if (y == 0) Fail("`=` repeats the row above; the first row has none");
        samples.faces.insert(samples.faces.end(), samples.faces.end() - width, samples.faces.end());
        continue;
      }
      int64_t count = 0;
      for (const std::string_view token : Words(line)) {
        const size_t star = token.find('*');
        const auto face = Number<uint32_t>(token.substr(0, star));
        const auto run = star == std::string_view::npos ? std::optional<int>(1)
                                                        : Number<int>(token.substr(star + 1));
        if (!face || !run || *run < 1) Fail("a sample run must be FACE or FACE*COUNT");
        count += *run;
        if (count > width) Fail("a sample row must hold " + std::to_string(width) + " samples");
        samples.faces.insert(samples.faces.end(), static_cast<size_t>(*run), *face);
      }
      if (count != width) Fail("a sample row must hold " + std::to_string(width) + " samples");
    }
    // Shades of the faces seen, then every sample given its face's shade.
    std::unordered_map<uint32_t, uint8_t> shades;
    while (lines_.Next(line) && line.starts_with("shades ")) {
      for (const std::string_view token : Words(line.substr(7))) {
        const size_t colon = token.find(':');
        const auto face = Number<uint32_t>(token.substr(0, colon));
        int shade = -1;
        if (colon != std::string_view::npos)
          shade = Number<int>(token.substr(colon + 1)).value_or(-1);
        if (!face || *face == 0 || shade < 0 || shade >= kSnapshotShadeSteps) {
          Fail("a shade must be FACE:SHADE, SHADE 0 to " + std::to_string(kSnapshotShadeSteps - 1));
        }
        shades[*face] = static_cast<uint8_t>(shade);
      }
    }
    if (line.starts_with("shades ")) line = {};  // the file ended after the shades
    samples.shades.resize(samples.faces.size());
    for (size_t i = 0; i < samples.faces.size(); ++i) {
      if (samples.faces[i] == 0) continue;
      const auto shade = shades.find(samples.faces[i]);
      if (shade == shades.end()) {
        Fail("face " + std::to_string(samples.faces[i]) + " is seen but has no shade");
      }
      samples.shades[i] = shade->second;
    }
    return line;
  }

  LineCursor lines_;
  SnapshotGolden golden_;
};

}  // namespace

Loaded<SnapshotGolden> ParseSnapshotGolden(std::string_view text, const std::string& name) {
  try {
    return GoldenParser(text).Parse();
  } catch (const GoldenProblem& problem) {
    return LoadError{name, problem.line, 0, problem.message};
  }
}

Loaded<SnapshotGolden> ReadSnapshotGolden(const std::string& path) {
  Loaded<std::string> bytes =
      ReadRegularFile(path, [](size_t sizeBytes) -> std::optional<std::string> {
        if (sizeBytes <= kMaxSnapshotGoldenBytes) return std::nullopt;
        return "the golden is " + FormatBytes(static_cast<double>(sizeBytes)) + ", more than " +
               FormatBytes(static_cast<double>(kMaxSnapshotGoldenBytes));
      });
  if (!bytes.Ok()) return bytes.Error();
  return ParseSnapshotGolden(bytes.Value(), path);
}

}  // namespace termshade
