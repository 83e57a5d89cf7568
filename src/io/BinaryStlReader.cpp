#include "io/BinaryStlReader.h"

#include <meshoptimizer.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "geometry/HugePages.h"

namespace termshade {
namespace {

constexpr size_t kHeaderBytes = 80;
constexpr size_t kRecordBytes = 50;  // normal, 3 corners (12 floats), 2 attribute bytes
constexpr size_t kFirstRecord = kHeaderBytes + 4;

uint32_t TriangleCount(std::string_view bytes) {
  uint32_t count = 0;
  std::memcpy(&count, bytes.data() + kHeaderBytes, sizeof count);
  return count;
}

}  // namespace

bool IsBinaryStlLayout(std::string_view bytes) {
  if (bytes.size() < kFirstRecord) return false;
  return kFirstRecord + uint64_t{TriangleCount(bytes)} * kRecordBytes == bytes.size();
}

bool BinaryStlHasColours(std::string_view bytes) {
  return bytes.substr(0, kHeaderBytes).find("COLOR=") != std::string_view::npos;
}

Loaded<Mesh> ReadBinaryStl(std::string_view bytes, const std::string& path) {
  if (!IsBinaryStlLayout(bytes)) {
    return LoadError{path, 0, 0, "not a binary STL (size is not 84 + 50 x triangle count)"};
  }
  const size_t triangles = TriangleCount(bytes);
  if (triangles == 0) return LoadError{path, 0, 0, "the file holds no triangles"};

  // Step 1: the corners as stored, three float triples a triangle.
  std::vector<std::array<float, 3>> corners;
  corners.reserve(triangles * 3);
  AdviseHugePages(corners);
  corners.resize(triangles * 3);
  for (size_t t = 0; t < triangles; ++t) {
    const char* record = bytes.data() + kFirstRecord + t * kRecordBytes;
    std::memcpy(corners[t * 3].data(), record + 12, 36);
  }

  // Step 2: weld bit-identical positions, keeping first-occurrence order;
  // the remap becomes the faces' corners.
  static_assert(std::is_same_v<unsigned int, uint32_t>);
  Mesh mesh;
  mesh.name = path;
  mesh.faceCorners.reserve(corners.size());
  AdviseHugePages(mesh.faceCorners);
  mesh.faceCorners.resize(corners.size());
  const size_t vertexCount =
      meshopt_generateVertexRemap(mesh.faceCorners.data(), nullptr, corners.size(),
                                  corners.data(), corners.size(), sizeof corners[0]);

  // Step 3: the vertices, then (the corners freed) one face per triangle in file order.
  mesh.verticesFile.reserve(vertexCount);
  AdviseHugePages(mesh.verticesFile);
  mesh.verticesFile.resize(vertexCount);
  for (size_t i = 0; i < corners.size(); ++i) {
    const auto& p = corners[i];
    mesh.verticesFile[mesh.faceCorners[i]] = {p[0], p[1], p[2]};
  }
  corners = {};
  mesh.faceStarts.reserve(triangles + 1);
  mesh.edgeHidden.reserve(mesh.faceCorners.size());
  AdviseHugePages(mesh.faceStarts);
  AdviseHugePages(mesh.edgeHidden);
  mesh.faceStarts.resize(triangles + 1);
  for (size_t t = 0; t <= triangles; ++t) mesh.faceStarts[t] = static_cast<uint32_t>(t * 3);
  mesh.edgeHidden.assign(mesh.faceCorners.size(), 0);
  return mesh;
}

}  // namespace termshade
