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
/// background), reset at the end of every line.
void AppendAnsiFrame(const CellBuffer& cells, int levelCount, std::string& out);

/// One `termshade-frame/1` JSON object on one line, ended by '\n'.
void AppendJsonFrame(const CellBuffer& cells, const DepthBuffer& depth, const Scene& scene,
                     const Camera& camera, const RenderOptions& options, std::string& out);

}  // namespace termshade
