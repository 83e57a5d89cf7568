#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "shade/CellColour.h"

namespace termshade {

/// Frame dump formats of SPEC 7, and the pictures made from the ansi dump:
/// an SVG picture (io/write/SvgFrame.h) and an asciinema recording
/// (io/write/AsciicastRecording.h).
enum class FrameFormat { kText, kAnsi, kJson, kSvg, kAsciicast };

std::optional<FrameFormat> ParseFrameFormat(std::string_view name);

/// Exactly HeightCells() lines of exactly WidthCells() characters, each ended by '\n'.
void AppendTextFrame(const CellBuffer& cells, std::string& out);

/// The text frame with SGR colours: each face cell's glyph in its face's
/// colour at its shade level (CellColour, as the viewer shows it); where a
/// two-colour glyph mode gives a cell a background face, the background in
/// that face's colour, else the terminal's own; a line that set a colour
/// ends with a reset. ColourMode::kNone gives the text frame. Shades are
/// made for a terminal with `background` (shade/Background.h).
void AppendAnsiFrame(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                     ColourMode mode, std::string& out, Background background = Background::kDark);

/// The SGR sequence that sets the foreground, or the background, to colour.
void AppendForegroundSgr(const TermColour& colour, std::string& out);
void AppendBackgroundSgr(const TermColour& colour, std::string& out);

/// A frame of several samples a cell, for the json dump (SPEC 11): the samples
/// (grid.across x grid.down per cell) and a one-sample frame of the same view,
/// whose faces and depth are those at each cell's center.
struct JsonSamples {
  SampleGrid grid;
  const CellBuffer& samples;
  const CellBuffer& center;
  const DepthBuffer& centerDepth;
};

/// One `termshade-frame/1` JSON object on one line, ended by '\n'. With
/// samples, also the glyph mode, `samples` [k, m] and `sampleFaces`: per
/// cell the k x m sample faces, row-major. The camera's `eyeFromFile`, `d`
/// and `center` carry 12 significant digits (entries below 1e-12 of the
/// matrix's largest are 0), so the dump is the same on every CPU; the rest
/// is exact (shortest round trip).
void AppendJsonFrame(const CellBuffer& cells, const DepthBuffer& depth, const Scene& scene,
                     const Camera& camera, const RenderOptions& options, std::string& out,
                     const JsonSamples* samples = nullptr);

}  // namespace termshade
