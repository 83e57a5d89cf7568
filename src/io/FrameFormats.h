#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"

namespace termshade {

/// Frame dump formats of SPEC 7.
enum class FrameFormat { kText, kAnsi, kJson };

std::optional<FrameFormat> ParseFrameFormat(std::string_view name);

/// Exactly HeightCells() lines of exactly WidthCells() characters, each ended by '\n'.
void AppendTextFrame(const CellBuffer& cells, std::string& out);

/// The text frame with 256-colour SGR sequences (yellow faces, light blue
/// background; a cell's background face, as two-colour glyph modes give,
/// in its shade), reset at the end of every line.
void AppendAnsiFrame(const CellBuffer& cells, int levelCount, std::string& out);

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
/// cell the k x m sample faces, row-major.
void AppendJsonFrame(const CellBuffer& cells, const DepthBuffer& depth, const Scene& scene,
                     const Camera& camera, const RenderOptions& options, std::string& out,
                     const JsonSamples* samples = nullptr);

}  // namespace termshade
