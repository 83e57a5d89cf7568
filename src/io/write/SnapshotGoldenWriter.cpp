#include "io/write/SnapshotGoldenWriter.h"

#include <charconv>
#include <cstdio>
#include <map>

namespace termshade {
namespace {

constexpr size_t kShadesPerLine = 16;

void AppendSampleRows(const SnapshotSamples& samples, std::string& out) {
  std::string previous, row;
  for (int y = 0; y < samples.heightSamples; ++y) {
    row.clear();
    for (int x = 0; x < samples.widthSamples;) {
      const uint32_t face = samples.faces[samples.Index(x, y)];
      int run = 1;
      while (x + run < samples.widthSamples && samples.faces[samples.Index(x + run, y)] == face) {
        ++run;
      }
      if (!row.empty()) row += ' ';
      row += std::to_string(face);
      if (run > 1) row += '*' + std::to_string(run);
      x += run;
    }
    out += y > 0 && row == previous ? "=" : row;
    out += '\n';
    previous.swap(row);
  }
}

void AppendShades(const SnapshotSamples& samples, std::string& out) {
  std::map<uint32_t, int> shades;  // by face number, so the lines read in order
  for (size_t i = 0; i < samples.faces.size(); ++i) {
    if (samples.faces[i] != 0) shades.emplace(samples.faces[i], samples.shades[i]);
  }
  size_t onLine = 0;
  for (const auto& [face, shade] : shades) {
    out += onLine == 0 ? "shades" : "";
    out += ' ' + std::to_string(face) + ':' + std::to_string(shade);
    if (++onLine == kShadesPerLine) {
      out += '\n';
      onLine = 0;
    }
  }
  if (onLine > 0) out += '\n';
}

// The cells' texture colours, a row a line: runs of RRGGBB (or - where no
// texture shows) with *COUNT, `=` for a row like the one above.
void AppendTextureColours(const std::vector<uint32_t>& colours, int widthCells, std::string& out) {
  const int heightCells = static_cast<int>(colours.size()) / widthCells;
  out += "textures " + std::to_string(widthCells) + "x" + std::to_string(heightCells) + "\n";
  std::string previous, row;
  for (int y = 0; y < heightCells; ++y) {
    row.clear();
    for (int x = 0; x < widthCells;) {
      const uint32_t colour = colours[static_cast<size_t>(y) * widthCells + x];
      int run = 1;
      while (x + run < widthCells &&
             colours[static_cast<size_t>(y) * widthCells + x + run] == colour) {
        ++run;
      }
      if (!row.empty()) row += ' ';
      char hex[8];
      std::snprintf(hex, sizeof hex, "%06x", colour & 0xFFFFFFU);
      row += colour == 0 ? std::string("-") : std::string(hex);
      if (run > 1) row += '*' + std::to_string(run);
      x += run;
    }
    out += y > 0 && row == previous ? "=" : row;
    out += '\n';
    previous.swap(row);
  }
}

}  // namespace

std::string SnapshotNumber(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return {text, result.ptr};
}

std::string FormatSnapshotGolden(const SnapshotGolden& golden) {
  const SnapshotSettings& s = golden.settings;
  std::string out = "termshade-snapshot/" + std::to_string(kSnapshotFormatVersion) + "\n";
  out +=
      "# A termshade snapshot: each view's frame for review, then the samples that\n"
      "# `termshade render MODEL --expect FILE` compares (docs/snapshot-testing.md).\n"
      "# Refresh with --update, or TERMSHADE_UPDATE=1.\n";
  out += "size " + std::to_string(s.widthCells) + "x" + std::to_string(s.heightCells) + "\n";
  out += "cell-aspect " + SnapshotNumber(s.cellAspect) + "\n";
  out += "theta " + SnapshotNumber(s.theta) + "\n";
  out += "phi " + SnapshotNumber(s.phi) + "\n";
  out += "method " + std::string(MethodName(s.method)) + "\n";
  out += "shade " + std::string(ShadeModeName(s.shade)) + "\n";
  out += "glyphs " + std::string(GlyphModeName(s.glyphs)) + "\n";
  out += "ramp " + s.ramp + "\n";
  out += std::string("cull ") + (s.cullBackFaces ? "on" : "off") + "\n";
  out += "up " + (golden.upAxis ? std::string(UpAxisName(*golden.upAxis)) : "auto") + "\n";
  out +=
      "samples " + std::to_string(s.samples.across) + "x" + std::to_string(s.samples.down) + "\n";
  out += "views";
  for (const std::string& view : s.views) out += ' ' + view;
  out += "\n";
  for (const SnapshotFrame& frame : golden.frames) {
    out += "\nview " + frame.view.name + "\n";
    for (const std::string& row : frame.textRows) out += '|' + row + "|\n";
    out += "samples " + std::to_string(frame.samples.widthSamples) + "x" +
           std::to_string(frame.samples.heightSamples) + "\n";
    AppendSampleRows(frame.samples, out);
    AppendShades(frame.samples, out);
    if (!frame.textureColours.empty())
      AppendTextureColours(frame.textureColours, s.widthCells, out);
  }
  return out;
}

}  // namespace termshade
