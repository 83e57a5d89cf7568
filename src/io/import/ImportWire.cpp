#include "io/import/ImportWire.h"

#include <cstring>
#include <type_traits>

namespace termshade {
namespace {

// Names and messages: far more than any a loader writes, far less than memory.
constexpr uint64_t kMaxTextBytes = uint64_t{1} << 20;

template <typename T>
bool PutValue(T value, const WireSink& sink) {
  static_assert(std::is_trivially_copyable_v<T>);
  return sink(&value, sizeof value);
}
bool PutString(const std::string& text, const WireSink& sink) {
  return PutValue<uint64_t>(text.size(), sink) && (text.empty() || sink(text.data(), text.size()));
}
template <typename T>
bool PutArray(const std::vector<T>& values, const WireSink& sink) {
  static_assert(std::is_trivially_copyable_v<T>);
  return PutValue<uint64_t>(values.size(), sink) &&
         (values.empty() || sink(values.data(), values.size() * sizeof(T)));
}

bool PutStrings(const std::vector<std::string>& texts, const WireSink& sink) {
  if (!PutValue<uint64_t>(texts.size(), sink)) return false;
  for (const std::string& text : texts) {
    if (!PutString(text, sink)) return false;
  }
  return true;
}

bool PutTextureImages(const std::vector<TextureImage>& images, const WireSink& sink) {
  if (!PutValue<uint64_t>(images.size(), sink)) return false;
  for (const TextureImage& image : images) {
    if (!PutValue(image.widthTexels, sink) || !PutValue(image.heightTexels, sink) ||
        !PutArray(image.srgbTexels, sink) || !PutString(image.problem, sink) ||
        !PutString(image.readAs, sink)) {
      return false;
    }
  }
  return true;
}

bool PutMesh(const Mesh& mesh, const WireSink& sink) {
  return PutString(mesh.name, sink) && PutValue(static_cast<uint8_t>(mesh.upAxisFile), sink) &&
         PutArray(mesh.verticesFile, sink) && PutArray(mesh.faceCorners, sink) &&
         PutArray(mesh.faceStarts, sink) && PutArray(mesh.edgeHidden, sink) &&
         PutArray(mesh.segments, sink) && PutArray(mesh.faceColors, sink) &&
         PutStrings(mesh.textures, sink) && PutTextureImages(mesh.textureImages, sink) &&
         PutArray(mesh.faceTextures, sink) && PutArray(mesh.cornerUvs, sink);
}

// The texture names: at most kMaxTextures, each 1 to kMaxTextureNameBytes bytes.
bool ReadTextures(WireReader& reader, std::vector<std::string>& textures) {
  uint64_t count = 0;
  if (!reader.U64(count)) return false;
  if (count > kMaxTextures) return reader.Refuse("more texture names than allowed");
  textures.assign(static_cast<size_t>(count), std::string());
  for (std::string& texture : textures) {
    if (!reader.String(texture, kMaxTextureNameBytes)) return false;
    if (texture.empty()) return reader.Refuse("an empty texture name");
    if (texture.find('\0') != std::string::npos)
      return reader.Refuse("a texture name with a NUL byte");
  }
  return true;
}

// The decoded images: none, or one a texture name; each at most
// kMaxTextureSideTexels a side, 3 bytes a texel.
bool ReadTextureImages(WireReader& reader, size_t textureCount, std::vector<TextureImage>& images) {
  uint64_t count = 0;
  if (!reader.U64(count)) return false;
  if (count != 0 && count != textureCount) return reader.Refuse("texture images not one a name");
  images.assign(static_cast<size_t>(count), TextureImage{});
  for (TextureImage& image : images) {
    if (!reader.U32(image.widthTexels) || !reader.U32(image.heightTexels)) return false;
    if (image.widthTexels > kMaxTextureSideTexels || image.heightTexels > kMaxTextureSideTexels) {
      return reader.Refuse("a texture image larger than allowed");
    }
    if (!reader.Array(image.srgbTexels) || !reader.String(image.problem, kMaxTextBytes) ||
        !reader.String(image.readAs, kMaxTextureNameBytes)) {
      return false;
    }
    if (image.srgbTexels.size() != size_t{image.widthTexels} * image.heightTexels * 3) {
      return reader.Refuse("a texture image whose texels do not fill it");
    }
  }
  return true;
}

bool ReadMesh(WireReader& reader, Mesh& mesh) {
  uint8_t up = 0;
  if (!reader.String(mesh.name, kMaxTextBytes) || !reader.U8(up)) return false;
  if (up > static_cast<uint8_t>(UpAxis::kMinusZ)) return reader.Refuse("an unknown up axis");
  mesh.upAxisFile = static_cast<UpAxis>(up);
  if (!reader.Array(mesh.verticesFile) || !reader.Array(mesh.faceCorners) ||
      !reader.Array(mesh.faceStarts) || !reader.Array(mesh.edgeHidden) ||
      !reader.Array(mesh.segments) || !reader.Array(mesh.faceColors) ||
      !ReadTextures(reader, mesh.textures) ||
      !ReadTextureImages(reader, mesh.textures.size(), mesh.textureImages) ||
      !reader.Array(mesh.faceTextures) || !reader.Array(mesh.cornerUvs)) {
    return false;
  }
  const std::string problem = MeshWireProblem(mesh);
  return problem.empty() || reader.Refuse(problem);
}

}  // namespace

bool WireReader::Bytes(void* to, size_t size) {
  if (size > bytesLeft_) return Refuse("more bytes than allowed");
  bytesLeft_ -= size;
  return size == 0 || source_(to, size);
}

bool WireReader::String(std::string& value, uint64_t maxBytes) {
  uint64_t size = 0;
  if (!U64(size)) return false;
  if (size > maxBytes || size > bytesLeft_) return Refuse("a text longer than allowed");
  value.resize(static_cast<size_t>(size));
  return Bytes(value.data(), value.size());
}

bool WriteRequestHead(const ImportRequest& request, const WireSink& sink) {
  return sink(kImportRequestMagic.data(), kImportRequestMagic.size()) &&
         PutString(request.stamp, sink) && PutString(request.source.displayName, sink) &&
         PutString(request.source.importName, sink) && PutString(request.source.folder, sink) &&
         PutString(request.source.format, sink) && PutValue(request.memoryBudgetBytes, sink) &&
         PutValue<uint64_t>(request.bytes.size(), sink);
}

bool ReadRequest(WireReader& reader, ImportRequest& request) {
  char magic[kImportRequestMagic.size()];
  if (!reader.Bytes(magic, sizeof magic)) return false;
  if (std::string_view(magic, sizeof magic) != kImportRequestMagic) {
    return reader.Refuse("not an import request of this version");
  }
  return reader.String(request.stamp, kMaxTextBytes) &&
         reader.String(request.source.displayName, kMaxTextBytes) &&
         reader.String(request.source.importName, kMaxTextBytes) &&
         reader.String(request.source.folder, kMaxTextBytes) &&
         reader.String(request.source.format, kMaxTextBytes) &&
         reader.U64(request.memoryBudgetBytes) && reader.String(request.bytes, UINT64_MAX);
}

bool WriteProgressFrame(double share, const WireSink& sink) {
  return PutValue(static_cast<uint8_t>(ImportFrame::kProgress), sink) && PutValue(share, sink);
}

bool WriteResultFrame(ModuleStatus status, const std::string& exceptionText,
                      const Loaded<Mesh>& result, const WireSink& sink) {
  if (!PutValue(static_cast<uint8_t>(ImportFrame::kResult), sink) ||
      !PutValue(static_cast<int32_t>(status), sink) || !PutString(exceptionText, sink) ||
      !PutValue<uint8_t>(result.Ok() ? 1 : 0, sink)) {
    return false;
  }
  if (result.Ok()) {
    // Loaded's Value() is not const; the mesh is only read.
    return PutMesh(
        const_cast<Loaded<Mesh>&>(result).Value(),  // NOLINT(cppcoreguidelines-pro-type-const-cast)
        sink);
  }
  const LoadError& error = result.Error();
  return PutString(error.file, sink) && PutValue<int32_t>(error.line, sink) &&
         PutValue<int32_t>(error.column, sink) && PutString(error.message, sink);
}

bool ReadResultFrame(WireReader& reader, ModuleStatus& status, std::string& exceptionText,
                     Loaded<Mesh>& result) {
  uint32_t statusValue = 0;
  uint8_t isMesh = 0;
  if (!reader.U32(statusValue) || !reader.String(exceptionText, kMaxTextBytes) ||
      !reader.U8(isMesh)) {
    return false;
  }
  if (statusValue > static_cast<uint32_t>(ModuleStatus::kException) || isMesh > 1) {
    return reader.Refuse("an unknown status");
  }
  status = static_cast<ModuleStatus>(statusValue);
  if (isMesh == 1) {
    Mesh mesh;
    if (!ReadMesh(reader, mesh)) return false;
    result = std::move(mesh);
    return true;
  }
  LoadError error;
  uint32_t line = 0, column = 0;
  if (!reader.String(error.file, kMaxTextBytes) || !reader.U32(line) || !reader.U32(column) ||
      !reader.String(error.message, kMaxTextBytes)) {
    return false;
  }
  error.line = static_cast<int>(line & 0x7fffffffU);
  error.column = static_cast<int>(column & 0x7fffffffU);
  result = std::move(error);
  return true;
}

std::string MeshWireProblem(const Mesh& mesh) {
  const auto vertexCount = mesh.verticesFile.size();
  const auto& starts = mesh.faceStarts;
  if (starts.empty() || starts.front() != 0 || starts.back() != mesh.faceCorners.size()) {
    return "face starts that do not cover the corners";
  }
  if (starts.size() < 2) return "no face";
  if (vertexCount >= (uint64_t{1} << 32)) return "more vertices than corners can name";
  for (size_t face = 1; face < starts.size(); ++face) {
    if (starts[face] < starts[face - 1]) return "face starts out of order";
    if (starts[face] - starts[face - 1] < 3) return "a face of fewer than 3 corners";
  }
  for (const uint32_t corner : mesh.faceCorners) {
    if (corner >= vertexCount) return "a corner past the vertices";
  }
  for (const auto& segment : mesh.segments) {
    if (segment[0] >= vertexCount || segment[1] >= vertexCount) return "a line past the vertices";
  }
  if (mesh.edgeHidden.size() != mesh.faceCorners.size()) return "edge flags not one a corner";
  if (!mesh.faceColors.empty() && mesh.faceColors.size() != mesh.FaceCount()) {
    return "face colours not one a face";
  }
  if (!mesh.faceTextures.empty() && mesh.faceTextures.size() != mesh.FaceCount()) {
    return "face textures not one a face";
  }
  for (const uint32_t texture : mesh.faceTextures) {
    if (texture != kNoTexture && texture >= mesh.textures.size())
      return "a face texture past the names";
  }
  if (mesh.cornerUvs.size() != (mesh.faceTextures.empty() ? 0 : mesh.faceCorners.size())) {
    return "texture coordinates not one a corner of a textured mesh";
  }
  return "";
}

}  // namespace termshade
