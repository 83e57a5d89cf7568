#include "io/BinaryStlReader.h"

#include <cstdint>
#include <cstring>
#include <vector>

#include "geometry/FirstOccurrence.h"
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

Loaded<Mesh> ReadBinaryStl(std::string_view bytes, const std::string& path, FileBytes* owned) {
  if (!IsBinaryStlLayout(bytes)) {
    return LoadError{path, 0, 0, "not a binary STL (size is not 84 + 50 x triangle count)"};
  }
  const size_t triangles = TriangleCount(bytes);
  if (triangles == 0) return LoadError{path, 0, 0, "the file holds no triangles"};
  if (triangles >= UINT32_MAX / 3)
    return LoadError{path, 0, 0, "more triangles than 32-bit indices hold"};

  // Step 1: each corner's first corner with bit-identical coordinates, read
  // in place from the records (12 bytes a corner, 3 corners a record).
  const size_t cornerCount = triangles * 3;
  const char* records = bytes.data() + kFirstRecord;
  const auto cornerAt = [records](size_t corner) {
    return records + (corner / 3) * kRecordBytes + 12 + (corner % 3) * 12;
  };
  Mesh mesh;
  mesh.name = path;
  mesh.faceCorners.reserve(cornerCount);
  AdviseHugePages(mesh.faceCorners);
  mesh.faceCorners.resize(cornerCount);
  // A closed surface has about one vertex for 6 corners: the table starts
  // there and grows if the file has more.
  FindFirstOccurrences<12>(cornerCount, cornerAt, mesh.faceCorners.data(), cornerCount / 5);

  // Step 2: vertices numbered by first occurrence (meshopt_generateVertexRemap's
  // order); the faces' corners become those numbers.
  size_t vertexCount = 0;
  for (size_t i = 0; i < cornerCount; ++i) vertexCount += mesh.faceCorners[i] == i;
  mesh.verticesFile.reserve(vertexCount);
  AdviseHugePages(mesh.verticesFile);
  // An owned file's records already read are handed back as the vertices
  // grow, 4 MiB at a time.
  constexpr size_t kReleaseBytes = size_t{4} << 20;
  size_t released = 0;
  for (size_t i = 0; i < cornerCount; ++i) {
    if (owned != nullptr && i % 3 == 0) {
      const size_t readTo = kFirstRecord + (i / 3) * kRecordBytes;
      if (readTo >= released + kReleaseBytes) {
        owned->Release(released, readTo);
        released = readTo;
      }
    }
    uint32_t& corner = mesh.faceCorners[i];
    if (corner != i) {
      corner = mesh.faceCorners[corner];  // an earlier corner, already numbered
      continue;
    }
    float xyz[3];
    std::memcpy(xyz, cornerAt(i), sizeof xyz);
    corner = static_cast<uint32_t>(mesh.verticesFile.size());
    mesh.verticesFile.push_back({xyz[0], xyz[1], xyz[2]});
  }

  if (owned != nullptr) owned->Free();

  // Step 3: one face per triangle in file order.
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
