#pragma once

#include <cstdint>

#include "geometry/Projection.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"

namespace termshade {

/// The line character for a direction in cells, judged by its angle on screen
/// (cell heights scaled by cellAspect): '-', '|', '/' or '\'.
char LineGlyph(double duCells, double dvCells, double cellAspect);

/// Draws a projected segment into the cells it crosses at their centers (one
/// cell per column or row along its major axis), with the glyph for its slope.
void DrawLine(const CellPoint& a, const CellPoint& b, double cellAspect, uint32_t faceNumber,
              int16_t level, DepthBuffer& depth, CellBuffer& cells);

}  // namespace termshade
