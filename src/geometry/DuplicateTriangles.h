#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace termshade {

struct Scene;

/// Triangles per vertex beyond which a mesh is looked at for repeated
/// triangles: a closed surface has about 2, the hostile inputs of issue 32
/// (a triangle a million times over, a 1000-gon 20,000 times over the same
/// corners) have hundreds of thousands.
inline constexpr size_t kRepeatCheckTrianglesPerVertex = 8;

/// Drops every triangle (3 vertex indices a triangle, flat) that repeats an
/// earlier one with the same corners in the same turn (any rotation; the
/// reverse turn is another triangle, its other side), keeping the first;
/// returns how many were dropped. O(n) for n triangles; none are dropped
/// where more than 2^20 differ (the input is then not mainly repeats; the
/// table stays near 40 MB). faces, when given, is per triangle and compacted alongside.
size_t DropRepeatedTriangles(std::vector<uint32_t>& indices,
                             std::vector<uint32_t>* faces = nullptr);

/// The scene's repeated triangles dropped, the first of each kept (the one of
/// the lowest face, which the z-buffer draws on a tie): the faces keep their
/// numbers, a face whose triangles all repeat earlier ones keeps none.
/// Checked only past kRepeatCheckTrianglesPerVertex triangles a vertex, or
/// for an unwelded mesh (2.5 vertices a triangle or more) past as many a
/// distinct position, comparing corners by position;
/// returns how many were dropped. faceCount: the scene's faces (its planes
/// may not be made yet). Call after the triangles are made and
/// before the faces are dropped (they must stay: the triangles no longer give them back).
size_t DropRepeatedSceneTriangles(Scene& scene, size_t faceCount);

}  // namespace termshade
