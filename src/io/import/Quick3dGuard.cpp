#include "io/import/Quick3dGuard.h"

#include <cctype>
#include <cstdint>
#include <cstring>

namespace termshade {
namespace {

// A little-endian cursor that stops at the end instead of reading past it.
class Cursor {
 public:
  explicit Cursor(std::string_view bytes) : bytes_(bytes) {}
  uint64_t Left() const { return bytes_.size() - position_; }
  bool Skip(uint64_t count) {
    if (count > Left()) return false;
    position_ += count;
    return true;
  }
  bool Byte(uint8_t& value) {
    if (Left() < 1) return false;
    value = static_cast<uint8_t>(bytes_[position_++]);
    return true;
  }
  template <typename T>
  bool Int(T& value) {
    if (Left() < sizeof(T)) return false;
    std::memcpy(&value, bytes_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    return true;
  }
  /// Skips a NUL-terminated name; its length without the NUL, or -1 at the end.
  int64_t Name() {
    const size_t end = bytes_.find('\0', position_);
    if (end == std::string_view::npos) return -1;
    const auto length = static_cast<int64_t>(end - position_);
    position_ = end + 1;
    return length;
  }

 private:
  std::string_view bytes_;
  size_t position_ = 0;
};

bool IsQuick3d(std::string_view bytes) {
  if (bytes.size() < 8) return false;
  std::string magic(bytes.substr(0, 8));
  for (char& c : magic) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return magic == "quick3do" || magic == "quick3ds";
}

std::string TooMany(const char* what, uint64_t count) {
  return "read as Quick3D: a count of " + std::to_string(count) + " " + what +
         " is more than the bytes after it can hold";
}

// One 'm' chunk: every mesh's counts against the bytes left. nullopt: fine or cut short.
std::optional<std::string> CheckMeshes(Cursor& in, uint32_t meshes, bool textured, bool faceFlags) {
  for (uint32_t m = 0; m < meshes; ++m) {
    uint32_t vertices = 0, faces = 0, normals = 0, uvs = 0;
    if (!in.Int(vertices)) return std::nullopt;
    if (uint64_t{vertices} * 12 > in.Left()) return TooMany("vertices", vertices);
    in.Skip(uint64_t{vertices} * 12);
    if (!in.Int(faces)) return std::nullopt;
    // A face: its corner count (2 bytes), a corner (4) at least, its material (4).
    if (uint64_t{faces} * 10 > in.Left()) return TooMany("faces", faces);
    uint64_t corners = 0;
    for (uint32_t f = 0; f < faces; ++f) {
      uint16_t count = 0;
      if (!in.Int(count)) return std::nullopt;
      corners += count;
    }
    if (corners * 4 + uint64_t{faces} * 4 > in.Left()) return TooMany("face corners", corners);
    in.Skip(corners * 4 + uint64_t{faces} * 4);
    if (!in.Int(normals)) return std::nullopt;
    if (uint64_t{normals} * 12 > in.Left()) return TooMany("normals", normals);
    in.Skip(uint64_t{normals} * 12);
    if (!in.Int(uvs)) return std::nullopt;
    if (textured && uvs != 0) {
      if (uint64_t{uvs} * 8 + corners * 4 > in.Left()) return TooMany("texture coordinates", uvs);
      in.Skip(uint64_t{uvs} * 8 + corners * 4);
    }
    if (!in.Skip(36) || (faceFlags && !in.Skip(faces))) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> CheckQuick3dCounts(std::string_view bytes) {
  if (!IsQuick3d(bytes) || bytes.size() < 22) return std::nullopt;
  // Step 1: the header's counts; the importer reserves for them at once.
  Cursor in(bytes);
  in.Skip(8);
  uint8_t major = 0, minor = 0;
  uint32_t meshes = 0, materials = 0, textures = 0;
  in.Byte(major);
  in.Byte(minor);
  in.Int(meshes);
  in.Int(materials);
  in.Int(textures);
  constexpr uint64_t kLeastMeshBytes = 74, kLeastMaterialBytes = 45;
  if (meshes * kLeastMeshBytes > in.Left()) return TooMany("meshes", meshes);
  if (materials * kLeastMaterialBytes > in.Left()) return TooMany("materials", materials);
  // Step 2: the chunks, as the importer reads them, until the scene chunk or the end.
  for (uint8_t chunk = 0; in.Byte(chunk);) {
    if (chunk == 'm') {
      const bool faceFlags = minor > '0' && major == '3';
      if (auto problem = CheckMeshes(in, meshes, textures != 0, faceFlags)) return problem;
    } else if (chunk == 'c') {
      for (uint32_t i = 0; i < materials; ++i) {
        const int64_t length = in.Name();
        if (length < 0) return std::nullopt;
        if (length > 1023) return "read as Quick3D: a material name longer than 1023 bytes";
        if (!in.Skip(44)) return std::nullopt;
      }
    } else if (chunk == 't') {
      for (uint32_t i = 0; i < textures; ++i) {
        uint32_t width = 0, height = 0;
        if (in.Name() < 0 || !in.Int(width) || !in.Int(height)) return std::nullopt;
        const uint64_t texels = uint64_t{width} * height;
        if (texels * 3 > in.Left()) return TooMany("texels", texels);
        in.Skip(texels * 3);
      }
    } else {
      return std::nullopt;  // the scene chunk ends the file; anything else the importer refuses
    }
  }
  return std::nullopt;
}

}  // namespace termshade
