#include "io/read/LoadBudget.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "io/read/RegularFile.h"

namespace termshade {
namespace {

// Whitespace-separated tokens of a header, a line at a time.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : text_(text) {}

  // The next token, skipping blanks, newlines and (optionally) '#' comments.
  std::string_view Next(bool skipComments) {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (std::isspace(static_cast<unsigned char>(c)) != 0) {
        ++pos_;
      } else if (skipComments && c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else {
        break;
      }
    }
    const size_t start = pos_;
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) == 0)
      ++pos_;
    return text_.substr(start, pos_ - start);
  }
  // The rest of the current line, as one piece.
  std::string_view Line() {
    const size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }
  size_t Position() const { return pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
};

// A header count: its value, and the digits the file wrote for messages
// (a double would print 2^64 - 1 as 2^64).
struct HeaderCount {
  double value = 0;
  std::string text;
};

// A count as an importer reads it from a header: the number the token
// begins with ("900./x" is 900, as Assimp's atoi-like parsers take it);
// nullopt when it begins with none.
std::optional<HeaderCount> Count(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end == token.data()) return std::nullopt;
  const std::string_view number = token.substr(0, static_cast<size_t>(end - token.data()));
  const bool digits = !number.empty() && std::all_of(number.begin(), number.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", value);
  return HeaderCount{value, digits ? std::string(number) : std::string(text)};
}

std::string Plain(double count) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", count);
  return text;
}

std::optional<std::string> CheckOff(std::string_view bytes) {
  Tokens tokens(bytes);
  const std::string_view keyword = tokens.Next(true);
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") return std::nullopt;
  const auto vertices = Count(tokens.Next(true));
  const auto faces = Count(tokens.Next(true));
  if (!vertices || !faces) return std::nullopt;
  if (vertices->value < 0 || faces->value < 0)
    return "the header's vertex or face count is negative";
  // Smallest body: a vertex is at least "0 0 0\n", a face at least "0\n".
  const double body = static_cast<double>(bytes.size() - std::min(bytes.size(), tokens.Position()));
  if (vertices->value * 6 + faces->value * 2 > body) {
    return "the header promises " + vertices->text + " vertices and " + faces->text +
           " faces, more than the " + Plain(body) + " bytes after it can hold";
  }
  return std::nullopt;
}

double PlyTypeBytes(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 1;
}

// Where the line that ends a PLY header starts (its first word "end_header",
// as PlyReader and Assimp's parser find it); npos when there is none.
size_t PlyHeaderEnd(std::string_view bytes) {
  for (size_t line = bytes.find('\n'); line != std::string_view::npos;
       line = bytes.find('\n', line)) {
    ++line;
    const size_t word = bytes.find_first_not_of(" \t", line);
    if (word == std::string_view::npos) return std::string_view::npos;
    if (bytes.substr(word, 10) != "end_header") continue;
    const size_t after = word + 10;
    if (after == bytes.size() || bytes[after] == ' ' || bytes[after] == '\t' ||
        bytes[after] == '\r' || bytes[after] == '\n') {
      return word;
    }
  }
  return std::string_view::npos;
}

std::optional<std::string> CheckPly(std::string_view bytes) {
  if (bytes.substr(0, 3) != "ply") return std::nullopt;
  const size_t end = PlyHeaderEnd(bytes);
  if (end == std::string_view::npos) return std::nullopt;
  const size_t bodyStart = std::min(bytes.find('\n', end), bytes.size());
  const double body = static_cast<double>(bytes.size() - bodyStart);
  Tokens tokens(bytes.substr(0, end));
  bool ascii = true;
  // Per element: its count and the fewest bytes one of it takes.
  struct Element {
    std::string name;
    HeaderCount count;
    double minBytes = 0;
  };
  std::vector<Element> elements;
  for (std::string_view word = tokens.Next(false); !word.empty(); word = tokens.Next(false)) {
    if (word == "format") {
      ascii = tokens.Next(false) == "ascii";
    } else if (word == "element") {
      const std::string_view name = tokens.Next(false);
      const auto count = Count(tokens.Next(false));
      if (!count) return std::nullopt;
      if (count->value < 0) return "element '" + std::string(name) + "' has a negative count";
      elements.push_back({std::string(name), *count, 0});
    } else if (word == "property" && !elements.empty()) {
      const std::string_view type = tokens.Next(false);
      // A list takes at least its count; anything else at least its size.
      const double size = type == "list" ? PlyTypeBytes(tokens.Next(false)) : PlyTypeBytes(type);
      elements.back().minBytes += ascii ? 2 : size;
      tokens.Line();
    } else {
      tokens.Line();  // comment, obj_info, ply, ...
    }
  }
  double needed = 0;
  for (const Element& element : elements) {
    needed += element.count.value * std::max(element.minBytes, 1.0);
  }
  if (needed > body) {
    std::string counts;
    for (const Element& element : elements) {
      counts += (counts.empty() ? "" : ", ") + element.count.text + " " + element.name;
    }
    return "the header promises " + counts + ", more than the " + Plain(body) +
           " bytes after it can hold";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> CheckHeaderCounts(std::string_view format, std::string_view bytes) {
  if (format == "off") return CheckOff(bytes);
  if (format == "ply") return CheckPly(bytes);
  return std::nullopt;
}

size_t EstimateImportBytes(std::string_view format, size_t fileBytes) {
  // Peak resident bytes per file byte, measured with /usr/bin/time -v on
  // generated 200k-triangle spheres (termshade generate sphere -o FILE),
  // with a margin; formats not measured get the largest.
  double perByte = 24;
  if (format == "dat") perByte = 12;
  if (format == "stl") perByte = 12;
  if (format == "obj") perByte = 16;
  if (format == "ply") perByte = 20;
  constexpr double kBaseBytes = 32.0 * (1 << 20);
  return static_cast<size_t>(std::min(kBaseBytes + perByte * static_cast<double>(fileBytes), 1e18));
}

std::optional<size_t> EstimateOwnReaderBytes(std::string_view format, size_t fileBytes) {
  // Peak resident bytes per file byte of `termshade render` on the generated
  // 2M-triangle spheres (/usr/bin/time), with a margin: the file is held
  // while the mesh is read (OBJ 85 MB, STL 100 MB, PLY 38 MB of file).
  double perByte = 0;
  if (format == "stl") perByte = 3;
  if (format == "obj") perByte = 3;
  if (format == "ply") perByte = 6;
  if (perByte == 0) return std::nullopt;
  constexpr double kBaseBytes = 32.0 * (1 << 20);
  return static_cast<size_t>(std::min(kBaseBytes + perByte * static_cast<double>(fileBytes), 1e18));
}

size_t EstimateLeastLoadBytes(size_t fileBytes) {
  return std::min(EstimateImportBytes("dat", fileBytes), *EstimateOwnReaderBytes("stl", fileBytes));
}

size_t LargestLoadableBytes(size_t budgetBytes) {
  size_t low = 0, high = budgetBytes;  // the least load of `low` bytes fits
  if (EstimateLeastLoadBytes(0) > budgetBytes) return 0;
  while (low < high) {
    const size_t middle = low + (high - low + 1) / 2;
    if (EstimateLeastLoadBytes(middle) <= budgetBytes) {
      low = middle;
    } else {
      high = middle - 1;
    }
  }
  return low;
}

size_t EstimatePreparedBytes(size_t fileBytes, size_t vertices, size_t corners, size_t faces,
                             size_t largestFaceCorners) {
  const auto v = static_cast<double>(vertices), c = static_cast<double>(corners),
             f = static_cast<double>(faces);
  const double triangles = std::max(0.0, c - 2 * f);
  // Faces other than one triangle each are kept: corners, hidden flags, starts.
  const double keptFaces = c == 3 * f ? 0.0 : 5 * c + 4 * f;
  // The first frame: world vertices and the renderer's per-vertex buffers
  // (48 / vertex), triangles (16), planes, starts, per-face buffers and clusters (40 / face).
  const double frame = 48 * v + 16 * triangles + 40 * f + keptFaces;
  // Preparation at its peak: world vertices, corners, edge uses (8 / corner),
  // their per-vertex starts, orientation's per-face arrays (14 / face).
  const double prepare = 32 * v + 12 * c + 14 * f + keptFaces;
  // Triangulation (faces other than triangles): world vertices, the faces
  // (corners, hidden flags, starts), the triangles so far with their faces
  // (16 / triangle, reserved at once) and the largest face's work arrays.
  const double triangulate =
      keptFaces == 0.0 ? 0.0
                       : 24 * v + 5 * c + 4 * f + 16 * triangles +
                             kTriangulateBytesPerCorner * static_cast<double>(largestFaceCorners);
  // Reading: the file and the mesh (vertices, corners with hidden flags, starts).
  const double read = static_cast<double>(fileBytes) + 24 * v + 5 * c + 4 * f;
  constexpr double kBaseBytes = 16.0 * (1 << 20);
  return static_cast<size_t>(
      std::min(kBaseBytes + std::max({read, frame, prepare, triangulate}), 1e18));
}

size_t EstimateMeshBytes(size_t vertices, size_t corners, size_t faces) {
  // Mesh: vertices, corners, hidden flags, face starts. Scene: world vertices,
  // triangles, face planes, edge sets while preparing.
  const double bytes = 48.0 * static_cast<double>(vertices) + 85.0 * static_cast<double>(corners) +
                       40.0 * static_cast<double>(faces);
  return static_cast<size_t>(std::min(bytes, 1e18));
}

std::string OverBudgetMessage(double neededBytes, size_t budgetBytes) {
  return "loading it needs about " + FormatBytes(neededBytes) +
         ", more than the memory budget of " + FormatBytes(static_cast<double>(budgetBytes)) +
         " (raise it with --memory-budget or TERMSHADE_MEMORY_BUDGET)";
}

std::optional<size_t> ParseByteCount(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || !(value >= 0)) return std::nullopt;
  std::string suffix(end, text.data() + text.size());
  std::transform(suffix.begin(), suffix.end(), suffix.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  double scale = 1;
  if (!suffix.empty() && std::string_view("KMGT").find(suffix.front()) != std::string_view::npos) {
    scale = std::pow(1024.0, 1 + static_cast<int>(std::string_view("KMGT").find(suffix.front())));
    suffix.erase(0, 1);
    if (suffix == "IB" || suffix == "B") suffix.clear();
  } else if (suffix == "B") {
    suffix.clear();
  }
  if (!suffix.empty()) return std::nullopt;
  const double bytes = value * scale;
  // Past 64 TiB no budget means anything (x86-64 user space is 128 TiB).
  constexpr double kMostBytes = 64.0 * 1099511627776.0;
  if (bytes < 1 || bytes > kMostBytes) return std::nullopt;
  return static_cast<size_t>(bytes);
}

}  // namespace termshade
