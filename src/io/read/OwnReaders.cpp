#include "io/read/OwnReaders.h"

#include "geometry/WeldVertices.h"
#include "io/read/BinaryStlReader.h"
#include "io/read/ObjReader.h"
#include "io/read/PlyReader.h"
#include "process/HugePages.h"

namespace termshade {
namespace {

std::optional<Loaded<Mesh>> ReadByFormat(std::string_view bytes, const std::string& format,
                                         const std::string& displayName, size_t memoryBudgetBytes,
                                         FileBytes* owned) {
  if (format == "stl") {
    if (auto misSized = MisSizedBinaryStl(bytes, displayName)) return Loaded<Mesh>(*misSized);
    if (!IsBinaryStlLayout(bytes) || BinaryStlHasColours(bytes)) return std::nullopt;
    return ReadBinaryStl(bytes, displayName, owned);
  }
  if (format == "ply") return ReadPly(bytes, displayName, memoryBudgetBytes);
  if (format == "obj") return ReadObj(bytes, displayName, memoryBudgetBytes, owned);
  return std::nullopt;
}

}  // namespace

std::optional<Loaded<Mesh>> ReadWithOwnReader(std::string_view bytes, const std::string& format,
                                              const std::string& displayName,
                                              size_t memoryBudgetBytes, FileBytes* owned) {
  std::optional<Loaded<Mesh>> read =
      ReadByFormat(bytes, format, displayName, memoryBudgetBytes, owned);
  if (!read || !read->Ok()) return read;
  if (owned != nullptr) owned->Free();  // before the weld's tables
  Mesh& mesh = read->Value();
  mesh.name = displayName;
  mesh.upAxisFile = format == "stl" ? UpAxis::kPlusZ : UpAxis::kPlusY;
  if (format != "stl") {  // the STL reader welds as it reads, in first-use order
    WeldAndNumberByFirstUse(mesh);
  }
  return read;
}

}  // namespace termshade
