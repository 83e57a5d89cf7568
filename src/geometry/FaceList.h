#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/Mesh.h"

namespace termshade {

/// One face's corners (vertex indices, in order): a view of stored corners,
/// or three held by value where they are implicit.
class FaceCorners {
 public:
  explicit FaceCorners(std::span<const uint32_t> stored) : stored_(stored) {}
  explicit FaceCorners(std::array<uint32_t, 3> triangle) : triangle_(triangle), implicit_(true) {}
  // NOLINTBEGIN(readability-identifier-naming): a range, as range-for and std::size name it
  size_t size() const { return implicit_ ? 3 : stored_.size(); }
  const uint32_t* begin() const { return implicit_ ? triangle_.data() : stored_.data(); }
  const uint32_t* end() const { return begin() + size(); }
  // NOLINTEND(readability-identifier-naming)
  uint32_t operator[](size_t i) const { return begin()[i]; }

 private:
  std::span<const uint32_t> stored_;
  std::array<uint32_t, 3> triangle_{};
  bool implicit_ = false;
};

/// A mesh's faces with what is implied left out: starts empty when every face
/// is a triangle (face f is corners[3f..3f+3)), hidden empty when no edge is hidden.
struct FaceList {
  std::vector<uint32_t> corners;
  std::vector<uint32_t> starts;  ///< FaceCount() + 1 entries, or empty
  std::vector<uint8_t> hidden;   ///< parallel to corners, or empty
  size_t faceCount = 0;

  size_t FaceCount() const { return faceCount; }
  size_t Start(size_t face) const { return starts.empty() ? 3 * face : starts[face]; }
  FaceCorners Face(size_t face) const {
    return FaceCorners(std::span(corners).subspan(Start(face), Start(face + 1) - Start(face)));
  }
  /// The edge from corner i of the face to the next is not drawn as a line.
  bool EdgeHidden(size_t face, size_t i) const {
    return !hidden.empty() && hidden[Start(face) + i] != 0;
  }
  void Clear() { *this = FaceList{}; }
};

/// Takes the faces out of a mesh (its corners, starts and hidden flags are
/// moved), leaving out starts and flags that say nothing.
FaceList TakeFaces(Mesh& mesh);

}  // namespace termshade
