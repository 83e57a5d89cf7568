#include "io/import/OpenGexGuard.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace termshade {
namespace {

// Whether Assimp's OpenGEX importer may read the content under this name: an
// unknown name, .ogex, or a glTF name whose content is not glTF (that
// importer refuses it and Assimp sniffs).
bool MayReachOpenGex(std::string_view bytes, const std::string& format) {
  if (format.empty() || format == "ogex") return true;
  if (format == "glb") return bytes.substr(0, 4) != "glTF";
  if (format == "gltf") {
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    return first == std::string_view::npos || bytes[first] != '{';
  }
  return false;
}

// As BaseImporter::SearchFileHeaderForToken: the first 200 bytes, lower-cased, NULs dropped.
bool HasOpenGexToken(std::string_view bytes) {
  std::string header;
  for (const char c : bytes.substr(0, 200)) {
    if (c != '\0') header += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  constexpr std::array<std::string_view, 4> kTokens = {"metric", "geometrynode",
                                                       "vertexarray (attrib", "indexarray"};
  return std::any_of(kTokens.begin(), kTokens.end(), [&](std::string_view token) {
    return header.find(token) != std::string::npos;
  });
}

}  // namespace

std::optional<std::string> CheckOpenGexStructure(std::string_view bytes,
                                                 const std::string& format) {
  if (!MayReachOpenGex(bytes, format) || !HasOpenGexToken(bytes)) return std::nullopt;
  // Step 1: brackets by kind, skipping // and /* */ comments and "..." strings.
  int parens = 0, squares = 0, braces = 0;
  char last = '\0';
  for (size_t i = 0; i < bytes.size(); ++i) {
    const char c = bytes[i];
    if (c == '/' && i + 1 < bytes.size() && bytes[i + 1] == '/') {
      i = std::min(bytes.find('\n', i), bytes.size());
      continue;
    }
    if (c == '/' && i + 1 < bytes.size() && bytes[i + 1] == '*') {
      const size_t close = bytes.find("*/", i + 2);
      if (close == std::string_view::npos) return "read as OpenGEX: a /* comment is never closed";
      i = close + 1;
      continue;
    }
    if (c == '"') {
      for (++i; i < bytes.size() && bytes[i] != '"'; ++i) {
        if (bytes[i] == '\\') ++i;
      }
      if (i >= bytes.size()) return "read as OpenGEX: a string is never closed";
      last = '"';
      continue;
    }
    parens += c == '(' ? 1 : c == ')' ? -1 : 0;
    squares += c == '[' ? 1 : c == ']' ? -1 : 0;
    braces += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (parens < 0 || squares < 0 || braces < 0) {
      return "read as OpenGEX: a closing bracket before its opening one";
    }
    if (std::isspace(static_cast<unsigned char>(c)) == 0 && c != '\0') last = c;
  }
  // Step 2: everything closed, and the last structure too.
  if (parens != 0 || squares != 0 || braces != 0) {
    return "read as OpenGEX: a structure is never closed (unbalanced brackets)";
  }
  if (last != '}') return "read as OpenGEX: expected the content to end with a structure's '}'";
  return std::nullopt;
}

}  // namespace termshade
