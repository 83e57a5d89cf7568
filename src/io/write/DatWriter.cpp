#include "io/write/DatWriter.h"

#include <charconv>

namespace termshade {

std::string FormatCoordinate(double value) {
  if (value == 0.0) return "0";
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 9);
  return {buffer, result.ptr};
}

std::string WriteDat(const Mesh& mesh) {
  std::string out;
  for (size_t i = 0; i < mesh.verticesFile.size(); ++i) {
    const Vec3& p = mesh.verticesFile[i];
    out += std::to_string(i + 1) + ' ' + FormatCoordinate(p.x) + ' ' + FormatCoordinate(p.y) + ' ' +
           FormatCoordinate(p.z) + '\n';
  }
  out += "Faces:\n";
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    const auto corners = mesh.Face(f);
    for (size_t i = 0; i < corners.size(); ++i) {
      if (i > 0) out += ' ';
      if (mesh.edgeHidden[mesh.faceStarts[f] + i]) out += '-';
      out += std::to_string(corners[i] + 1);
    }
    out += ".\n";
  }
  for (const auto& segment : mesh.segments) {
    out += std::to_string(segment[0] + 1) + ' ' + std::to_string(segment[1] + 1) + ".\n";
  }
  return out;
}

}  // namespace termshade
