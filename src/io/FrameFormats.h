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

/// Frame dump formats of SPEC 7.
enum class FrameFormat { kText, kAnsi, kJson };

std::optional<FrameFormat> ParseFrameFormat(std::string_view name);

/// Exactly HeightCells() lines of exactly WidthCells() characters, each ended by '\n'.
void AppendTextFrame(const CellBuffer& cells, std::string& out);

/// The text frame with SGR foreground colours: each face cell in its face's
/// colour at its shade level (CellColour, as the viewer shows it), the
/// background in the terminal's own colours; a line that set a colour ends
/// with a reset. ColourMode::kNone gives the text frame.
void AppendAnsiFrame(const CellBuffer& cells, std::span<const Rgb> faceColours, int levelCount,
                     ColourMode mode, std::string& out);

/// The SGR sequence that sets the foreground to colour.
void AppendForegroundSgr(const TermColour& colour, std::string& out);

/// One `termshade-frame/1` JSON object on one line, ended by '\n'.
void AppendJsonFrame(const CellBuffer& cells, const DepthBuffer& depth, const Scene& scene,
                     const Camera& camera, const RenderOptions& options, std::string& out);

}  // namespace termshade
