#include "io/ObjReader.h"

#include <charconv>
#include <cstdint>
#include <vector>

#include "geometry/DropUnusedVertices.h"
#include "geometry/HugePages.h"

namespace termshade {
namespace {

/// One line of the file without its newline (and a trailing carriage return).
struct Line {
  std::string_view text;
  int number = 0;
};

/// Calls visit(line) for each line; stops when visit returns false.
template <typename Visit>
void ForEachLine(std::string_view text, Visit visit) {
  size_t position = 0;
  int number = 0;
  while (position < text.size()) {
    size_t end = text.find('\n', position);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(position, end - position);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position = end + 1;
    if (!visit(Line{line, ++number})) return;
  }
}

bool IsBlank(char c) {
  return c == ' ' || c == '\t';
}

std::string_view Keyword(std::string_view line) {
  size_t start = 0;
  while (start < line.size() && IsBlank(line[start])) ++start;
  size_t end = start;
  while (end < line.size() && !IsBlank(line[end])) ++end;
  return line.substr(start, end - start);
}

/// Counts from the first pass: what to allocate, or why the importer should read it.
struct ObjCounts {
  uint64_t vertices = 0;
  uint64_t faces = 0;
  uint64_t corners = 0;  ///< an upper bound: the words of face lines
  bool needsImporter = false;
};

uint64_t CountWords(std::string_view line) {
  uint64_t words = 0;
  bool inWord = false;
  for (const char c : line) {
    if (IsBlank(c)) {
      inWord = false;
    } else if (!inWord) {
      inWord = true;
      ++words;
    }
  }
  return words;
}

ObjCounts CountObj(std::string_view text) {
  ObjCounts counts;
  ForEachLine(text, [&counts](const Line& line) {
    const std::string_view keyword = Keyword(line.text);
    const bool continued = !line.text.empty() && line.text.back() == '\\';
    if (continued || keyword == "mtllib" || keyword == "usemtl" || keyword == "curv" ||
        keyword == "surf" || keyword == "cstype" || keyword == "curv2") {
      counts.needsImporter = true;
    } else if (keyword == "v") {
      ++counts.vertices;
      if (CountWords(line.text) > 5) counts.needsImporter = true;  // x y z r g b: colours
    } else if (keyword == "f" || keyword == "fo" || keyword == "l") {
      ++counts.faces;
      counts.corners += CountWords(line.text) - 1;
    }
    return !counts.needsImporter;
  });
  return counts;
}

/// Reads numbers and corners from one line, tracking the column for errors.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  void SkipBlanks() {
    while (position_ < text_.size() && IsBlank(text_[position_])) ++position_;
  }
  bool AtEnd() {
    SkipBlanks();
    return position_ >= text_.size() || text_[position_] == '#';
  }
  int Column() const { return static_cast<int>(position_) + 1; }
  void SkipWord() {
    SkipBlanks();
    while (position_ < text_.size() && !IsBlank(text_[position_])) ++position_;
  }

  bool ReadDouble(double& value) {
    SkipBlanks();
    size_t start = position_;
    if (start < text_.size() && text_[start] == '+') ++start;
    const char* first = text_.data() + start;
    const auto result = std::from_chars(first, text_.data() + text_.size(), value);
    if (result.ec != std::errc{} || result.ptr == first) return false;
    // Like Assimp, the number is the word's longest numeric beginning ("3.1+e2" is 3.1).
    position_ = static_cast<size_t>(result.ptr - text_.data());
    while (position_ < text_.size() && !IsBlank(text_[position_])) ++position_;
    return true;
  }

  /// The position index of a corner word (v, v/vt, v//vn, v/vt/vn); the rest is skipped.
  bool ReadCorner(int64_t& index) {
    SkipBlanks();
    const char* first = text_.data() + position_;
    const auto result = std::from_chars(first, text_.data() + text_.size(), index);
    if (result.ec != std::errc{} || result.ptr == first) return false;
    position_ = static_cast<size_t>(result.ptr - text_.data());
    while (position_ < text_.size() && !IsBlank(text_[position_])) {
      const char c = text_[position_];
      if (c != '/' && c != '-' && (c < '0' || c > '9')) return false;
      ++position_;
    }
    return true;
  }

 private:
  std::string_view text_;
  size_t position_ = 0;
};

class ObjParser {
 public:
  ObjParser(const std::string& path, const ObjCounts& counts) : path_(path) {
    mesh_.name = path;
    mesh_.verticesFile.reserve(counts.vertices);
    mesh_.faceStarts.reserve(counts.faces + 1);
    mesh_.faceCorners.reserve(counts.corners);
    mesh_.edgeHidden.reserve(counts.corners);
    AdviseHugePages(mesh_.verticesFile);
    AdviseHugePages(mesh_.faceStarts);
    AdviseHugePages(mesh_.faceCorners);
    AdviseHugePages(mesh_.edgeHidden);
  }

  bool Line(const termshade::Line& line) {
    LineCursor cursor(line.text);
    const std::string_view keyword = Keyword(line.text);
    cursor.SkipWord();
    if (keyword == "v") return Vertex(line, cursor);
    if (keyword == "f" || keyword == "fo" || keyword == "l") return Face(line, cursor);
    return true;  // vt, vn, g, o, s, comments and the rest: not geometry we draw
  }

  std::optional<LoadError> Error() const { return error_; }
  Mesh TakeMesh() { return std::move(mesh_); }

 private:
  bool Fail(const termshade::Line& line, const LineCursor& cursor, std::string message) {
    error_ = LoadError{path_, line.number, cursor.Column(), std::move(message)};
    return false;
  }

  bool Vertex(const termshade::Line& line, LineCursor& cursor) {
    double xyz[3];
    for (double& coordinate : xyz) {
      if (!cursor.ReadDouble(coordinate)) return Fail(line, cursor, "expected a number");
    }
    mesh_.verticesFile.push_back({xyz[0], xyz[1], xyz[2]});
    return true;
  }

  bool Face(const termshade::Line& line, LineCursor& cursor) {
    corners_.clear();
    const auto defined = static_cast<int64_t>(mesh_.verticesFile.size());
    while (!cursor.AtEnd()) {
      const int column = cursor.Column();
      int64_t index = 0;
      if (!cursor.ReadCorner(index)) return Fail(line, cursor, "expected a vertex number");
      const int64_t zeroBased = index < 0 ? defined + index : index - 1;
      if (index == 0 || zeroBased < 0 || zeroBased >= defined) {
        error_ = LoadError{path_, line.number, column,
                           "vertex " + std::to_string(index) + " is not defined (" +
                               std::to_string(defined) + " so far)"};
        return false;
      }
      corners_.push_back(static_cast<uint32_t>(zeroBased));
    }
    if (corners_.size() >= 3 && Keyword(line.text) != "l") {
      mesh_.AddFace(corners_);
    } else if (corners_.size() >= 2) {
      for (size_t i = 0; i + 1 < corners_.size(); ++i) {
        mesh_.segments.push_back({corners_[i], corners_[i + 1]});
      }
    }
    return true;
  }

  const std::string& path_;
  Mesh mesh_;
  std::vector<uint32_t> corners_;
  std::optional<LoadError> error_;
};

std::string MemoryBudgetMessage(uint64_t neededBytes, uint64_t budgetBytes) {
  constexpr uint64_t kMiB = uint64_t{1} << 20;
  return "the model needs about " + std::to_string(neededBytes / kMiB + 1) +
         " MiB, more than the memory budget of " + std::to_string(budgetBytes / kMiB) + " MiB";
}

}  // namespace

std::optional<Loaded<Mesh>> ReadObj(std::string_view text, const std::string& path,
                                    size_t memoryBudgetBytes) {
  // Step 1: counts, and whether the importer is needed.
  const ObjCounts counts = CountObj(text);
  if (counts.needsImporter) return std::nullopt;
  const uint64_t meshBytes = counts.vertices * sizeof(Vec3) +
                             counts.corners * (sizeof(uint32_t) + 1) +
                             counts.faces * sizeof(uint32_t);
  if (meshBytes > memoryBudgetBytes) {
    return Loaded<Mesh>(LoadError{path, 0, 0, MemoryBudgetMessage(meshBytes, memoryBudgetBytes)});
  }

  // Step 2: the geometry, line by line.
  ObjParser parser(path, counts);
  ForEachLine(text, [&parser](const Line& line) { return parser.Line(line); });
  if (auto error = parser.Error()) return Loaded<Mesh>(*error);
  Mesh mesh = parser.TakeMesh();
  DropUnusedVertices(mesh);
  if (mesh.FaceCount() == 0) {
    return Loaded<Mesh>(LoadError{path, 0, 0, "the file holds no polygons ('f' lines)"});
  }
  return Loaded<Mesh>(std::move(mesh));
}

}  // namespace termshade
