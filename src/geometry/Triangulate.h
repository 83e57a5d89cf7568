#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/Vec3.h"

namespace termshade {

/// Triangles as corner positions within one polygon (0-based, counter-clockwise
/// about the polygon's Newell normal).
using CornerTriangle = std::array<uint32_t, 3>;

/// Ear-clipping triangulation of a possibly non-convex, slightly non-planar
/// polygon. Consecutive duplicate corners are dropped first; a simple n-gon
/// then gives n - 2 triangles using every boundary edge once. Never loops
/// forever: each step clips one corner, falling back to collinear and then to
/// the most convex corner when the polygon is not simple, and to corners in
/// order once a work budget (5e7 point tests) is spent.
void TriangulatePolygon(std::span<const Vec3> corners, std::vector<CornerTriangle>& trianglesOut);

}  // namespace termshade
