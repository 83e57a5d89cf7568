#include "io/write/MeshExport.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstring>

#include "geometry/FaceNormal.h"
#include "io/write/DatWriter.h"

namespace termshade {
namespace {

static_assert(std::endian::native == std::endian::little, "binary writers assume little endian");

template <typename T>
void AppendBinary(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void AppendNumber(std::string& out, double value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
  out.append(buffer, result.ptr);
}

void AppendNumber(std::string& out, uint64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

std::string WriteObj(const Mesh& mesh) {
  std::string out = "# written by termshade\n";
  for (const Vec3& p : mesh.verticesFile) {
    out += "v ";
    AppendNumber(out, p.x);
    out += ' ';
    AppendNumber(out, p.y);
    out += ' ';
    AppendNumber(out, p.z);
    out += '\n';
  }
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    out += 'f';
    for (const uint32_t corner : mesh.Face(f)) {
      out += ' ';
      AppendNumber(out, uint64_t{corner} + 1);
    }
    out += '\n';
  }
  return out;
}

size_t FanTriangleCount(const Mesh& mesh) {
  size_t count = 0;
  for (size_t f = 0; f < mesh.FaceCount(); ++f) count += mesh.Face(f).size() - 2;
  return count;
}

void AppendVertex(std::string& out, Vec3 p) {
  AppendBinary(out, static_cast<float>(p.x));
  AppendBinary(out, static_cast<float>(p.y));
  AppendBinary(out, static_cast<float>(p.z));
}

std::string WriteBinaryStl(const Mesh& mesh) {
  std::string out(80, ' ');
  out.replace(0, 24, "termshade binary STL    ");
  const size_t triangles = FanTriangleCount(mesh);
  out.reserve(84 + triangles * 50);
  AppendBinary(out, static_cast<uint32_t>(triangles));
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    const auto corners = mesh.Face(f);
    Vec3 normal =
        NewellNormal(corners.size(), [&](size_t i) { return mesh.verticesFile[corners[i]]; });
    const double length = Length(normal);
    if (length > 0.0) normal = normal * (1.0 / length);
    for (size_t i = 1; i + 1 < corners.size(); ++i) {
      AppendVertex(out, normal);
      AppendVertex(out, mesh.verticesFile[corners[0]]);
      AppendVertex(out, mesh.verticesFile[corners[i]]);
      AppendVertex(out, mesh.verticesFile[corners[i + 1]]);
      AppendBinary(out, uint16_t{0});
    }
  }
  return out;
}

std::string WriteBinaryPly(const Mesh& mesh) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\ncomment written by termshade\nelement vertex ";
  AppendNumber(out, uint64_t{mesh.verticesFile.size()});
  out += "\nproperty float x\nproperty float y\nproperty float z\nelement face ";
  AppendNumber(out, uint64_t{mesh.FaceCount()});
  out += "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : mesh.verticesFile) AppendVertex(out, p);
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    const auto corners = mesh.Face(f);
    AppendBinary(out, static_cast<uint8_t>(std::min<size_t>(corners.size(), 255)));
    for (size_t i = 0; i < corners.size() && i < 255; ++i) {
      AppendBinary(out, static_cast<int32_t>(corners[i]));
    }
  }
  return out;
}

}  // namespace

std::optional<ExportFormat> ExportFormatFromPath(std::string_view path) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string ext(path.substr(dot + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "dat") return ExportFormat::kDat;
  if (ext == "obj") return ExportFormat::kObj;
  if (ext == "stl") return ExportFormat::kStl;
  if (ext == "ply") return ExportFormat::kPly;
  return std::nullopt;
}

std::string ExportMesh(const Mesh& mesh, ExportFormat format) {
  switch (format) {
    case ExportFormat::kObj:
      return WriteObj(mesh);
    case ExportFormat::kStl:
      return WriteBinaryStl(mesh);
    case ExportFormat::kPly:
      return WriteBinaryPly(mesh);
    case ExportFormat::kDat:
      break;
  }
  return WriteDat(mesh);
}

}  // namespace termshade
