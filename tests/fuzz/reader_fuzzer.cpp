// libFuzzer target, differential: our own readers' fast steps against their
// plain forms. The first byte picks a chunk count; the rest is read as an
// OBJ in one chunk and in that many, welded in one step and in two (weld,
// then first-use numbering), and, as 12-byte keys, numbered by first
// occurrence and by meshoptimizer's remap, and as the corners of a binary
// STL, welded in one run and in that many. Any difference aborts.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include <meshoptimizer.h>

#include "geometry/FirstOccurrence.h"
#include "geometry/FirstUseOrder.h"
#include "geometry/WeldVertices.h"
#include "io/read/BinaryStlReader.h"
#include "io/read/ObjReader.h"

namespace {

using termshade::Loaded;
using termshade::Mesh;

std::string Describe(std::optional<Loaded<Mesh>> read) {
  if (!read) return "importer";
  if (!read->Ok()) return read->Error().ToString();
  const Mesh& mesh = read->Value();
  std::string text(reinterpret_cast<const char*>(mesh.verticesFile.data()),
                   mesh.verticesFile.size() * sizeof(termshade::Vec3));
  const auto append = [&text](const auto& values) {
    text.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof values[0]);
    text += '|';
  };
  append(mesh.faceCorners);
  append(mesh.faceStarts);
  append(mesh.edgeHidden);
  append(mesh.segments);
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace termshade;
  if (size == 0) return 0;
  const unsigned parts = 2U + data[0] % 7U;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  constexpr size_t kBudget = size_t{64} << 20;

  // OBJ in chunks against one chunk.
  const std::string one = Describe(ReadObjInChunks(text, "fuzz.obj", kBudget, 1));
  if (Describe(ReadObjInChunks(text, "fuzz.obj", kBudget, parts)) != one) std::abort();

  // First occurrences of 12-byte keys (as STL corners) against meshoptimizer's remap.
  const size_t keys = text.size() / 12;
  const auto keyAt = [&text](size_t i) { return text.data() + i * 12; };
  std::vector<uint32_t> first(keys);
  FindFirstOccurrences<12>(keys, keyAt, first.data());
  std::vector<char> packed(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(keys * 12));
  std::vector<unsigned int> remap(keys);
  if (keys > 0) meshopt_generateVertexRemap(remap.data(), nullptr, keys, packed.data(), keys, 12);
  std::vector<uint32_t> firstOfRemap(keys, UINT32_MAX);
  for (size_t i = 0; i < keys; ++i) {
    if (firstOfRemap[remap[i]] == UINT32_MAX) firstOfRemap[remap[i]] = static_cast<uint32_t>(i);
    if (first[i] != firstOfRemap[remap[i]]) std::abort();
  }

  // A binary STL of those corners (3 keys a record) in runs against one run.
  const size_t triangles = keys / 3;
  if (triangles > 0) {
    std::string stl(80, '\0');
    const auto count = static_cast<uint32_t>(triangles);
    stl.append(reinterpret_cast<const char*>(&count), 4);
    for (size_t t = 0; t < triangles; ++t) {
      stl.append(12, '\0');
      stl.append(text.substr(t * 36, 36));
      stl.append(2, '\0');
    }
    Loaded<Mesh> whole = ReadBinaryStlInParts(stl, "fuzz.stl", 1);
    Loaded<Mesh> split = ReadBinaryStlInParts(stl, "fuzz.stl", parts);
    if (!whole.Ok() || !split.Ok()) std::abort();
    const Mesh &a = whole.Value(), &b = split.Value();
    if (a.faceCorners != b.faceCorners || a.verticesFile.size() != b.verticesFile.size() ||
        std::memcmp(a.verticesFile.data(), b.verticesFile.data(),
                    a.verticesFile.size() * sizeof(Vec3)) != 0) {
      std::abort();
    }
  }

  // The one-step weld against weld then first-use numbering, on the OBJ's mesh.
  std::optional<Loaded<Mesh>> read = ReadObjInChunks(text, "fuzz.obj", kBudget, 1);
  if (read && read->Ok()) {
    Mesh expected = read->Value();
    Mesh actual = expected;
    WeldExactPositions(expected);
    NumberVerticesByFirstUse(expected);
    WeldAndNumberByFirstUse(actual);
    if (actual.faceCorners != expected.faceCorners || actual.segments != expected.segments ||
        actual.verticesFile.size() != expected.verticesFile.size() ||
        std::memcmp(actual.verticesFile.data(), expected.verticesFile.data(),
                    actual.verticesFile.size() * sizeof(Vec3)) != 0) {
      std::abort();
    }
  }
  return 0;
}
