#include "io/read/ObjReader.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "geometry/DropUnusedVertices.h"
#include "process/HugePages.h"
#include "process/LoadThreads.h"

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
  uint64_t lines = 0;
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

// Hands back a chunk's bytes as its lines are read, 4 MiB at a time
// (FileBytes::Release); nothing without an owner.
class ReleaseBehind {
 public:
  ReleaseBehind(FileBytes* owned, std::string_view file, std::string_view chunk)
      : owned_(owned), file_(file.data()), released_(chunk.data()) {}
  void ReadTo(const char* at) {
    constexpr size_t kReleaseBytes = size_t{4} << 20;
    if (owned_ == nullptr || static_cast<size_t>(at - released_) < kReleaseBytes) return;
    owned_->Release(static_cast<size_t>(released_ - file_), static_cast<size_t>(at - file_));
    released_ = at;
  }

 private:
  FileBytes* owned_;
  const char* file_;
  const char* released_;
};

ObjCounts CountObj(std::string_view text, ReleaseBehind& release) {
  ObjCounts counts;
  ForEachLine(text, [&counts, &release](const Line& line) {
    release.ReadTo(line.text.data());
    ++counts.lines;
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

/// Where one chunk of the file (whole lines) puts what it reads: its
/// vertices at their final place, the corners of its face and line entries
/// packed in its own span of the corner buffer, each entry's end in its own
/// span of the face starts (kLineEntry set for `l` lines), merged in place.
struct ObjChunk {
  std::string_view text;
  ObjCounts counts;
  uint64_t firstLine = 0;    ///< lines before the chunk
  uint64_t firstVertex = 0;  ///< vertices defined before the chunk
  Vec3* vertices = nullptr;
  uint32_t* corners = nullptr;
  uint32_t* entryEnds = nullptr;
  std::optional<LoadError> error;
  /// What the geometry pass wrote: the file may have changed since the counts.
  uint64_t verticesWritten = 0;
  uint64_t entriesWritten = 0;
};

constexpr uint32_t kLineEntry = uint32_t{1} << 31;

class ObjParser {
 public:
  ObjParser(const std::string& path, ObjChunk& chunk) : path_(path), chunk_(chunk) {}

  bool Line(const termshade::Line& line) {
    LineCursor cursor(line.text);
    const std::string_view keyword = Keyword(line.text);
    cursor.SkipWord();
    if (keyword == "v") return Vertex(line, cursor);
    if (keyword == "f" || keyword == "fo") return Entry(line, cursor, 0);
    if (keyword == "l") return Entry(line, cursor, kLineEntry);
    return true;  // vt, vn, g, o, s, comments and the rest: not geometry we draw
  }

  /// Records in the chunk what the lines read so far wrote.
  void Finish() {
    chunk_.verticesWritten = vertices_;
    chunk_.entriesWritten = entries_;
  }

 private:
  bool Fail(const termshade::Line& line, int column, std::string message) {
    chunk_.error = LoadError{path_, static_cast<int>(chunk_.firstLine) + line.number, column,
                             std::move(message)};
    return false;
  }

  bool Changed(const termshade::Line& line) { return Fail(line, 1, kFileChangedMessage); }

  bool Vertex(const termshade::Line& line, LineCursor& cursor) {
    double xyz[3];
    for (double& coordinate : xyz) {
      if (!cursor.ReadDouble(coordinate)) return Fail(line, cursor.Column(), "expected a number");
    }
    // The file is read twice (counts, then geometry) and may have changed
    // in between: no write past what the first pass counted.
    if (vertices_ >= chunk_.counts.vertices) return Changed(line);
    chunk_.vertices[vertices_++] = {xyz[0], xyz[1], xyz[2]};
    return true;
  }

  bool Entry(const termshade::Line& line, LineCursor& cursor, uint32_t kind) {
    const auto defined = static_cast<int64_t>(chunk_.firstVertex + vertices_);
    while (!cursor.AtEnd()) {
      const int column = cursor.Column();
      int64_t index = 0;
      if (!cursor.ReadCorner(index)) return Fail(line, cursor.Column(), "expected a vertex number");
      const int64_t zeroBased = index < 0 ? defined + index : index - 1;
      if (index == 0 || zeroBased < 0 || zeroBased >= defined) {
        return Fail(line, column,
                    "vertex " + std::to_string(index) + " is not defined (" +
                        std::to_string(defined) + " so far)");
      }
      if (corners_ >= chunk_.counts.corners) return Changed(line);
      chunk_.corners[corners_++] = static_cast<uint32_t>(zeroBased);
    }
    if (entries_ >= chunk_.counts.faces) return Changed(line);
    chunk_.entryEnds[entries_++] = static_cast<uint32_t>(corners_) | kind;
    return true;
  }

  const std::string& path_;
  ObjChunk& chunk_;
  size_t vertices_ = 0;
  size_t corners_ = 0;
  size_t entries_ = 0;
};

/// The text cut into up to `parts` chunks of whole lines.
std::vector<std::string_view> SplitAtLines(std::string_view text, size_t parts) {
  std::vector<std::string_view> chunks;
  size_t begin = 0;
  for (size_t part = 1; part <= parts && begin < text.size(); ++part) {
    size_t end = text.size();
    if (part < parts) {
      end = text.find('\n', std::max(begin, text.size() / parts * part));
      end = end == std::string_view::npos ? text.size() : end + 1;
    }
    chunks.push_back(text.substr(begin, end - begin));
    begin = end;
  }
  return chunks;
}

/// Step 3 of a read: the chunks' entries, in file order, as faces (3 or more
/// corners) and segments (an `l` line's, or a 2-corner face), the corners
/// moved down over the spans' unused ends and the dropped entries, the face
/// ends over the entry ends (each written at or before where it was read).
/// Only the entries the geometry pass wrote are merged.
void MergeChunks(std::span<const ObjChunk> chunks, const std::vector<uint32_t*>& spans,
                 Mesh& mesh) {
  size_t written = 0, faces = 0;
  for (size_t c = 0; c < chunks.size(); ++c) {
    const uint32_t* corners = spans[c];
    uint32_t start = 0;
    for (uint64_t e = 0; e < chunks[c].entriesWritten; ++e) {
      const uint32_t entry = chunks[c].entryEnds[e];
      const uint32_t end = entry & ~kLineEntry;
      const uint32_t count = end - start;
      if (count >= 3 && (entry & kLineEntry) == 0) {
        std::memmove(mesh.faceCorners.data() + written, corners + start, count * sizeof(uint32_t));
        written += count;
        mesh.faceStarts[++faces] = static_cast<uint32_t>(written);
      } else if (count >= 2) {
        for (uint32_t i = start; i + 1 < end; ++i) {
          mesh.segments.push_back({corners[i], corners[i + 1]});
        }
      }
      start = end;
    }
  }
  mesh.faceCorners.resize(written);
  mesh.faceStarts.resize(faces + 1);
}

LoadError ChangedError(const std::string& path, const char* message) {
  return LoadError{path, 0, 0, message};
}

std::string MemoryBudgetMessage(uint64_t neededBytes, uint64_t budgetBytes) {
  constexpr uint64_t kMiB = uint64_t{1} << 20;
  return "the model needs about " + std::to_string(neededBytes / kMiB + 1) +
         " MiB, more than the memory budget of " + std::to_string(budgetBytes / kMiB) + " MiB";
}

}  // namespace

std::optional<Loaded<Mesh>> ReadObj(std::string_view text, const std::string& path,
                                    size_t memoryBudgetBytes, FileBytes* owned) {
  constexpr size_t kBytesPerItem = 64;  // about a line
  return ReadObjInChunks(text, path, memoryBudgetBytes,
                         static_cast<size_t>(LoadThreadCount(text.size() / kBytesPerItem)), owned);
}

std::optional<Loaded<Mesh>> ReadObjInChunks(std::string_view text, const std::string& path,
                                            size_t memoryBudgetBytes, size_t chunkCount,
                                            FileBytes* owned) {
  // Step 1: chunks of whole lines, one a thread; their counts, and whether the importer is needed.
  const std::vector<std::string_view> texts = SplitAtLines(text, std::max<size_t>(1, chunkCount));
  std::vector<ObjChunk> chunks(texts.size());
  for (size_t c = 0; c < texts.size(); ++c) chunks[c].text = texts[c];
  // A mapped file's pages are handed back behind both passes (the second
  // maps them again from the page cache): the file is never resident whole
  // beside the mesh. Held bytes are not, as the importer may need them.
  FileBytes* const countRelease = owned != nullptr && owned->Mapped() ? owned : nullptr;
  RunOnLoadThreads(static_cast<int>(chunks.size()), [&](int c) {
    ObjChunk& chunk = chunks[static_cast<size_t>(c)];
    ReleaseBehind release(countRelease, text, chunk.text);
    chunk.counts = CountObj(chunk.text, release);
  });
  if (owned != nullptr && owned->Shrank())
    return Loaded<Mesh>(ChangedError(path, kFilePagesLostMessage));
  ObjCounts counts;
  for (ObjChunk& chunk : chunks) {
    if (chunk.counts.needsImporter) return std::nullopt;
    chunk.firstLine = counts.lines;
    chunk.firstVertex = counts.vertices;
    counts.lines += chunk.counts.lines;
    counts.vertices += chunk.counts.vertices;
    counts.faces += chunk.counts.faces;
    counts.corners += chunk.counts.corners;
  }
  const uint64_t meshBytes = counts.vertices * sizeof(Vec3) +
                             counts.corners * (sizeof(uint32_t) + 1) +
                             counts.faces * sizeof(uint32_t);
  if (meshBytes > memoryBudgetBytes) {
    return Loaded<Mesh>(LoadError{path, 0, 0, MemoryBudgetMessage(meshBytes, memoryBudgetBytes)});
  }
  if (counts.corners >= kLineEntry || counts.vertices >= UINT32_MAX) {
    return Loaded<Mesh>(LoadError{path, 0, 0, "more vertices or corners than 32-bit indices hold"});
  }

  // Step 2: the geometry, each chunk line by line on its own thread.
  Mesh mesh;
  mesh.name = path;
  mesh.verticesFile.reserve(counts.vertices);
  mesh.faceCorners.reserve(counts.corners);
  mesh.faceStarts.reserve(counts.faces + 1);
  AdviseHugePages(mesh.verticesFile);
  AdviseHugePages(mesh.faceCorners);
  AdviseHugePages(mesh.faceStarts);
  mesh.verticesFile.resize(counts.vertices);
  mesh.faceCorners.resize(counts.corners);
  mesh.faceStarts.resize(counts.faces + 1);
  std::vector<uint32_t*> spans;
  uint64_t cornersBefore = 0, entriesBefore = 0;
  for (ObjChunk& chunk : chunks) {
    chunk.vertices = mesh.verticesFile.data() + chunk.firstVertex;
    chunk.corners = mesh.faceCorners.data() + cornersBefore;
    chunk.entryEnds = mesh.faceStarts.data() + 1 + entriesBefore;
    spans.push_back(chunk.corners);
    cornersBefore += chunk.counts.corners;
    entriesBefore += chunk.counts.faces;
  }
  RunOnLoadThreads(static_cast<int>(chunks.size()), [&](int c) {
    ObjChunk& chunk = chunks[static_cast<size_t>(c)];
    ObjParser parser(path, chunk);
    ReleaseBehind release(owned, text, chunk.text);
    ForEachLine(chunk.text, [&parser, &release](const Line& line) {
      release.ReadTo(line.text.data());
      return parser.Line(line);
    });
    parser.Finish();
  });
  if (owned != nullptr && owned->Shrank())
    return Loaded<Mesh>(ChangedError(path, kFilePagesLostMessage));
  for (const ObjChunk& chunk : chunks) {
    if (chunk.error) return Loaded<Mesh>(*chunk.error);
    // Fewer lines than the counts: the file changed between the passes.
    if (chunk.verticesWritten != chunk.counts.vertices ||
        chunk.entriesWritten != chunk.counts.faces) {
      return Loaded<Mesh>(ChangedError(path, kFileChangedMessage));
    }
  }

  // Step 3: faces and segments in file order; an owned file is freed first.
  if (owned != nullptr) owned->Free();
  MergeChunks(chunks, spans, mesh);
  mesh.edgeHidden.reserve(mesh.faceCorners.size());
  AdviseHugePages(mesh.edgeHidden);
  mesh.edgeHidden.assign(mesh.faceCorners.size(), 0);
  DropUnusedVertices(mesh);
  if (mesh.FaceCount() == 0) {
    return Loaded<Mesh>(LoadError{path, 0, 0, "the file holds no polygons ('f' lines)"});
  }
  return Loaded<Mesh>(std::move(mesh));
}

}  // namespace termshade
