#pragma once

#include <array>
#include <atomic>
#include <cstddef>
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
/// order once a work budget (5e7 point tests) is spent. modelBudget, when
/// given, is the point tests left for the whole model (shared by its faces,
/// lowered by what this one spends): a polygon gets no more than it holds.
/// A set `cancel` (looked at every kEarsPerCancelPoll ears) stops it with
/// the triangles so far: for a caller that drops them.
void TriangulatePolygon(std::span<const Vec3> corners, std::vector<CornerTriangle>& trianglesOut,
                        int64_t* modelBudget = nullptr, const std::atomic<bool>* cancel = nullptr);
inline constexpr uint32_t kEarsPerCancelPoll = 4096;

/// Point tests a model's triangulation may spend in all: 5e7 and 32 a
/// corner (a model of 20,000 1000-gons would otherwise take 1e12).
int64_t ModelPointTestBudget(size_t cornerCount);

}  // namespace termshade
