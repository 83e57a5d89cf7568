#include "io/write/SvgFrame.h"

#include <cstdio>
#include <map>
#include <tuple>
#include <vector>

#include "shade/CellColour.h"
#include "shade/GlyphShape.h"
#include "shade/Utf8.h"

namespace termshade {
namespace {

// A filled rectangle in SVG units, in one colour.
struct SvgRect {
  double x, y, width, height;
  Srgb8 colour;
};

void AppendNumber(double value, std::string& out) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  out += text;
}

void AppendRect(const SvgRect& rect, std::string& out) {
  out += "<rect x=\"";
  AppendNumber(rect.x, out);
  out += "\" y=\"";
  AppendNumber(rect.y, out);
  out += "\" width=\"";
  AppendNumber(rect.width, out);
  out += "\" height=\"";
  AppendNumber(rect.height, out);
  out += "\" fill=\"" + HexColour(rect.colour) + "\"/>\n";
}

void AppendEscapedGlyph(char32_t glyph, std::string& out) {
  switch (glyph) {
    case U'&':
      out += "&amp;";
      return;
    case U'<':
      out += "&lt;";
      return;
    case U'>':
      out += "&gt;";
      return;
    default:
      AppendUtf8(out, glyph);
  }
}

// Rectangles of one row of cells that abut along the row in one colour and
// the same vertical span become one rectangle.
class RowRects {
 public:
  void Add(const SvgRect& rect) {
    const auto key =
        std::make_tuple(rect.y, rect.height, rect.colour.r, rect.colour.g, rect.colour.b);
    const auto open = open_.find(key);
    if (open != open_.end()) {
      SvgRect& last = rects_[open->second];
      if (last.x + last.width == rect.x) {
        last.width += rect.width;
        return;
      }
    }
    open_[key] = rects_.size();
    rects_.push_back(rect);
  }
  void AppendTo(std::string& out) const {
    for (const SvgRect& rect : rects_) AppendRect(rect, out);
  }

 private:
  std::vector<SvgRect> rects_;
  std::map<std::tuple<double, double, uint8_t, uint8_t, uint8_t>, size_t> open_;
};

// The inked parts of a shape glyph in a cell at (x, y): per part row, the
// runs of set parts, each run one rectangle.
void AddShapeRects(const GlyphShape& shape, double x, double y, double widthPx, double heightPx,
                   Srgb8 colour, RowRects& rects) {
  const double partWidth = widthPx / shape.grid.across, partHeight = heightPx / shape.grid.down;
  for (int down = 0; down < shape.grid.down; ++down) {
    for (int across = 0; across < shape.grid.across;) {
      const auto set = [&](int col) {
        return (shape.pattern >> (down * shape.grid.across + col)) & 1U;
      };
      if (!set(across)) {
        ++across;
        continue;
      }
      int end = across;
      while (end < shape.grid.across && set(end)) ++end;
      rects.Add({x + across * partWidth, y + down * partHeight, (end - across) * partWidth,
                 partHeight, colour});
      across = end;
    }
  }
}

void AppendDots(const GlyphShape& shape, double x, double y, double widthPx, double heightPx,
                Srgb8 colour, std::string& out) {
  const double partWidth = widthPx / shape.grid.across, partHeight = heightPx / shape.grid.down;
  const double radius = 0.3 * std::min(partWidth, partHeight);
  for (int part = 0; part < shape.grid.Count(); ++part) {
    if (((shape.pattern >> part) & 1U) == 0) continue;
    out += "<circle cx=\"";
    AppendNumber(x + (part % shape.grid.across + 0.5) * partWidth, out);
    out += "\" cy=\"";
    AppendNumber(y + (part / shape.grid.across + 0.5) * partHeight, out);
    out += "\" r=\"";
    AppendNumber(radius, out);
    out += "\" fill=\"" + HexColour(colour) + "\"/>\n";
  }
}

// A run of text glyphs in one colour: one <text> element, each glyph placed
// at its cell's left edge (a glyph of a monospace font fills its cell's width).
struct TextRun {
  std::string xs;
  std::string glyphs;
  Srgb8 colour;
  void AppendTo(double baselineY, std::string& out) const {
    if (glyphs.empty()) return;
    out += "<text x=\"" + xs + "\" y=\"";
    AppendNumber(baselineY, out);
    out += "\" fill=\"" + HexColour(colour) + "\">" + glyphs + "</text>\n";
  }
};

}  // namespace

void AppendSvgFrame(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                    const SvgFrameStyle& style, std::string& out) {
  const double widthPx = kSvgCellWidthPx, heightPx = kSvgCellWidthPx * style.cellAspect;
  const double frameWidth = widthPx * cells.WidthCells(),
               frameHeight = heightPx * cells.HeightCells();
  const bool coloured = style.colourMode != ColourMode::kNone;
  CellColourMap colours(faceColours, levelCount, style.colourMode, style.background);
  // Step 1: the document and the terminal's background.
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  AppendNumber(frameWidth, out);
  out += "\" height=\"";
  AppendNumber(frameHeight, out);
  out += "\" viewBox=\"0 0 ";
  AppendNumber(frameWidth, out);
  out += ' ';
  AppendNumber(frameHeight, out);
  out += "\">\n<rect width=\"100%\" height=\"100%\" fill=\"" + HexColour(style.theme.background) +
         "\"/>\n<g shape-rendering=\"crispEdges\">\n";
  std::string dots, text;
  for (int row = 0; row < cells.HeightCells(); ++row) {
    const double y = row * heightPx;
    RowRects backgrounds, inks;
    TextRun run;
    TermColour current;  // as the ansi dump: a blank cell keeps the colour it has
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const double x = col * widthPx;
      // Step 2: the cell's background, where a two-colour mode gives one.
      const int backLevel = cells.BackLevel(col, row);
      if (coloured && backLevel >= 0) {
        const TermColour back =
            colours.ForFace(cells.BackFaceNumber(col, row), backLevel, cells.BackAlbedo(col, row));
        if (back.kind != TermColour::Kind::kDefault)
          backgrounds.Add({x, y, widthPx, heightPx, ShownColour(back, style.theme, true)});
      }
      // Step 3: the glyph, as rectangles, dots or text.
      const int level = cells.Level(col, row);
      if (coloured && level >= 0)
        current = colours.ForFace(cells.FaceNumber(col, row), level, cells.ForeAlbedo(col, row));
      const Srgb8 ink = ShownColour(current, style.theme, false);
      const char32_t glyph = cells.Glyph(col, row);
      const GlyphShape* shape = glyph == U' ' ? nullptr : ShapeOfGlyph(glyph);
      const bool textGlyph = glyph != U' ' && shape == nullptr;
      if (!textGlyph || !(ink == run.colour)) {
        run.AppendTo(y + 0.78 * heightPx, text);
        run = TextRun{{}, {}, ink};
      }
      if (shape && shape->dots) AppendDots(*shape, x, y, widthPx, heightPx, ink, dots);
      if (shape && !shape->dots) AddShapeRects(*shape, x, y, widthPx, heightPx, ink, inks);
      if (!textGlyph) continue;
      if (!run.xs.empty()) run.xs += ' ';
      AppendNumber(x, run.xs);
      AppendEscapedGlyph(glyph, run.glyphs);
    }
    run.AppendTo(y + 0.78 * heightPx, text);
    backgrounds.AppendTo(out);
    inks.AppendTo(out);
  }
  out += "</g>\n";
  out += dots;
  // Step 4: text glyphs in a monospace font filling the cell's width.
  if (!text.empty()) {
    out += "<g font-family=\"DejaVu Sans Mono, Menlo, Consolas, monospace\" font-size=\"";
    AppendNumber(std::min(widthPx / 0.6, heightPx * 0.85), out);
    out += "\">\n" + text + "</g>\n";
  }
  out += "</svg>\n";
}

}  // namespace termshade
