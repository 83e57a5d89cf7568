#include "io/read/PlyReader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "geometry/DropUnusedVertices.h"
#include "io/read/LoadBudget.h"
#include "process/HugePages.h"

namespace termshade {
namespace {

enum class Encoding { kAscii, kLittleEndian, kBigEndian };

enum class ScalarType : uint8_t {
  kInt8,
  kUint8,
  kInt16,
  kUint16,
  kInt32,
  kUint32,
  kFloat32,
  kFloat64
};

struct Property {
  std::string name;
  ScalarType type = ScalarType::kFloat32;
  bool isList = false;
  ScalarType countType = ScalarType::kUint8;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  size_t dataOffset = 0;  ///< first byte after end_header's line
  int dataLine = 0;       ///< its line number (ascii)
};

size_t ScalarBytes(ScalarType type) {
  switch (type) {
    case ScalarType::kInt8:
    case ScalarType::kUint8:
      return 1;
    case ScalarType::kInt16:
    case ScalarType::kUint16:
      return 2;
    case ScalarType::kInt32:
    case ScalarType::kUint32:
    case ScalarType::kFloat32:
      return 4;
    case ScalarType::kFloat64:
      return 8;
  }
  return 1;
}

std::optional<ScalarType> ParseScalarType(std::string_view name) {
  struct Named {
    std::string_view name;
    ScalarType type;
  };
  static constexpr Named kTypes[] = {
      {"char", ScalarType::kInt8},      {"int8", ScalarType::kInt8},
      {"uchar", ScalarType::kUint8},    {"uint8", ScalarType::kUint8},
      {"short", ScalarType::kInt16},    {"int16", ScalarType::kInt16},
      {"ushort", ScalarType::kUint16},  {"uint16", ScalarType::kUint16},
      {"int", ScalarType::kInt32},      {"int32", ScalarType::kInt32},
      {"uint", ScalarType::kUint32},    {"uint32", ScalarType::kUint32},
      {"float", ScalarType::kFloat32},  {"float32", ScalarType::kFloat32},
      {"double", ScalarType::kFloat64}, {"float64", ScalarType::kFloat64},
  };
  for (const Named& named : kTypes) {
    if (named.name == name) return named.type;
  }
  return std::nullopt;
}

std::vector<std::string_view> Words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

LoadError HeaderError(const std::string& path, int line, const std::string& message) {
  return LoadError{path, line, 1, message};
}

// Step 1 of a read: the header, up to and including end_header.
Loaded<Header> ParseHeader(std::string_view bytes, const std::string& path) {
  Header header;
  size_t position = 0;
  int lineNumber = 0;
  bool sawFormat = false;
  while (true) {
    const size_t end = bytes.find('\n', position);
    if (end == std::string_view::npos || lineNumber > 100000) {
      return HeaderError(path, lineNumber, "expected 'end_header' to close the PLY header");
    }
    const std::string_view line = bytes.substr(position, end - position);
    position = end + 1;
    ++lineNumber;
    const std::vector<std::string_view> words = Words(line);
    if (lineNumber == 1) {
      if (words.size() != 1 || words[0] != "ply") {
        return HeaderError(path, 1, "expected 'ply' on the first line");
      }
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "end_header") break;
    if (words[0] == "format") {
      if (words.size() != 3) return HeaderError(path, lineNumber, "expected 'format TYPE 1.0'");
      if (words[1] == "ascii") {
        header.encoding = Encoding::kAscii;
      } else if (words[1] == "binary_little_endian") {
        header.encoding = Encoding::kLittleEndian;
      } else if (words[1] == "binary_big_endian") {
        header.encoding = Encoding::kBigEndian;
      } else {
        return HeaderError(path, lineNumber,
                           "expected ascii, binary_little_endian or binary_big_endian");
      }
      sawFormat = true;
    } else if (words[0] == "element") {
      uint64_t count = 0;
      if (words.size() != 3 ||
          std::from_chars(words[2].data(), words[2].data() + words[2].size(), count).ec !=
              std::errc{}) {
        return HeaderError(path, lineNumber, "expected 'element NAME COUNT'");
      }
      header.elements.push_back({std::string(words[1]), count, {}});
    } else if (words[0] == "property") {
      if (header.elements.empty()) {
        return HeaderError(path, lineNumber, "a property before any element");
      }
      Property property;
      if (words.size() == 5 && words[1] == "list") {
        const auto countType = ParseScalarType(words[2]);
        const auto itemType = ParseScalarType(words[3]);
        if (!countType || !itemType || *countType == ScalarType::kFloat32 ||
            *countType == ScalarType::kFloat64) {
          return HeaderError(path, lineNumber, "expected 'property list COUNT_TYPE TYPE NAME'");
        }
        property = {std::string(words[4]), *itemType, true, *countType};
      } else if (words.size() == 3) {
        const auto type = ParseScalarType(words[1]);
        if (!type) return HeaderError(path, lineNumber, "unknown property type");
        property = {std::string(words[2]), *type, false, ScalarType::kUint8};
      } else {
        return HeaderError(path, lineNumber, "expected 'property TYPE NAME'");
      }
      header.elements.back().properties.push_back(std::move(property));
    }
    // Any other line is taken as a comment, as Assimp and Blender's writers do.
  }
  if (!sawFormat) return HeaderError(path, lineNumber, "the header has no 'format' line");
  header.dataOffset = position;
  header.dataLine = lineNumber + 1;
  return header;
}

// Reads scalars from the data part, binary or ascii, remembering where it is.
class DataCursor {
 public:
  DataCursor(std::string_view data, Encoding encoding, int firstLine)
      : data_(data), encoding_(encoding), line_(firstLine) {}

  bool Read(ScalarType type, double& value) {
    return encoding_ == Encoding::kAscii ? ReadText(value) : ReadBinary(type, value);
  }
  int Line() const { return line_; }
  size_t Offset() const { return offset_; }
  /// The unread bytes of a little-endian binary file (empty for other encodings).
  std::string_view RestLittleEndian() const {
    const bool little =
        encoding_ == Encoding::kLittleEndian && std::endian::native == std::endian::little;
    return little ? data_.substr(offset_) : std::string_view{};
  }
  void Skip(size_t bytes) { offset_ += bytes; }

 private:
  template <typename T>
  bool ReadRaw(double& value) {
    if (data_.size() - offset_ < sizeof(T)) return false;
    char raw[sizeof(T)];
    std::memcpy(raw, data_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    const bool swap =
        (encoding_ == Encoding::kBigEndian) == (std::endian::native == std::endian::little);
    if (swap) {
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    }
    T typed;
    std::memcpy(&typed, raw, sizeof(T));
    value = static_cast<double>(typed);
    return true;
  }

  bool ReadBinary(ScalarType type, double& value) {
    switch (type) {
      case ScalarType::kInt8:
        return ReadRaw<int8_t>(value);
      case ScalarType::kUint8:
        return ReadRaw<uint8_t>(value);
      case ScalarType::kInt16:
        return ReadRaw<int16_t>(value);
      case ScalarType::kUint16:
        return ReadRaw<uint16_t>(value);
      case ScalarType::kInt32:
        return ReadRaw<int32_t>(value);
      case ScalarType::kUint32:
        return ReadRaw<uint32_t>(value);
      case ScalarType::kFloat32:
        return ReadRaw<float>(value);
      case ScalarType::kFloat64:
        return ReadRaw<double>(value);
    }
    return false;
  }

  bool ReadText(double& value) {
    while (offset_ < data_.size() && (data_[offset_] == ' ' || data_[offset_] == '\t' ||
                                      data_[offset_] == '\r' || data_[offset_] == '\n')) {
      if (data_[offset_] == '\n') ++line_;
      ++offset_;
    }
    const char* first = data_.data() + offset_;
    const char* last = data_.data() + data_.size();
    const auto result = std::from_chars(first, last, value);
    if (result.ec != std::errc{} || result.ptr == first) return false;
    offset_ += static_cast<size_t>(result.ptr - first);
    return true;
  }

  std::string_view data_;
  Encoding encoding_;
  size_t offset_ = 0;
  int line_ = 1;
};

// A little-endian binary scalar as a double, as DataCursor reads it.
double ScalarAt(const char* bytes, ScalarType type) {
  const auto as = [bytes]<typename T>(T typed) {
    std::memcpy(&typed, bytes, sizeof typed);
    return static_cast<double>(typed);
  };
  switch (type) {
    case ScalarType::kInt8:
      return as(int8_t{});
    case ScalarType::kUint8:
      return as(uint8_t{});
    case ScalarType::kInt16:
      return as(int16_t{});
    case ScalarType::kUint16:
      return as(uint16_t{});
    case ScalarType::kInt32:
      return as(int32_t{});
    case ScalarType::kUint32:
      return as(uint32_t{});
    case ScalarType::kFloat32:
      return as(float{});
    case ScalarType::kFloat64:
      return as(double{});
  }
  return 0.0;
}

bool IsColourName(std::string_view name) {
  return name == "red" || name == "green" || name == "blue" || name == "diffuse_red" ||
         name == "diffuse_green" || name == "diffuse_blue" || name == "r" || name == "g" ||
         name == "b";
}

bool NeedsImporter(const Header& header) {
  for (const Element& element : header.elements) {
    if (element.name == "tristrips" || element.name == "material") return true;
    for (const Property& property : element.properties) {
      if (IsColourName(property.name)) return true;
    }
  }
  return false;
}

// The least bytes one instance of an element takes in the data part.
uint64_t MinimumBytes(const Element& element, Encoding encoding) {
  uint64_t bytes = 0;
  for (const Property& property : element.properties) {
    if (encoding == Encoding::kAscii) {
      bytes += 2;  // a digit and a separator
    } else {
      bytes += property.isList ? ScalarBytes(property.countType) : ScalarBytes(property.type);
    }
  }
  return bytes;
}

// What the mesh will take: vertices, and triangles' corners, starts and edge flags.
uint64_t MeshBytes(const Header& header) {
  uint64_t bytes = 0;
  for (const Element& element : header.elements) {
    if (element.name == "vertex") bytes += element.count * sizeof(Vec3);
    if (element.name == "face")
      bytes += element.count * (3 * (sizeof(uint32_t) + 1) + sizeof(uint32_t));
  }
  return bytes;
}

std::string MemoryBudgetMessage(uint64_t neededBytes, uint64_t budgetBytes) {
  constexpr double kMiB = 1024.0 * 1024.0;
  return "the model needs about " + std::to_string(static_cast<uint64_t>(neededBytes / kMiB) + 1) +
         " MiB, more than the memory budget of " +
         std::to_string(static_cast<uint64_t>(budgetBytes / kMiB)) + " MiB";
}

struct Reader {
  const std::string& path;
  DataCursor cursor;
  Mesh mesh;

  LoadError Error(const std::string& what) const {
    if (cursor.Line() > 0) return LoadError{path, cursor.Line(), 0, what};
    return LoadError{path, 0, 0, what + " (at byte " + std::to_string(cursor.Offset()) + ")"};
  }
};

int PropertyIndex(const Element& element, std::string_view name) {
  for (size_t i = 0; i < element.properties.size(); ++i) {
    if (element.properties[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

// Fast path of ReadVertices: little-endian binary vertices without lists, all
// of them in the file (else false, nothing read, and the general path reads
// them and reports where the file ends).
bool ReadFixedVertices(const Element& element, const int xyz[3], Reader& reader) {
  const std::string_view rest = reader.cursor.RestLittleEndian();
  size_t stride = 0;
  size_t offsets[3] = {0, 0, 0};
  for (size_t p = 0; p < element.properties.size(); ++p) {
    const Property& property = element.properties[p];
    if (property.isList) return false;
    for (int axis = 0; axis < 3; ++axis) {
      if (static_cast<int>(p) == xyz[axis]) offsets[axis] = stride;
    }
    stride += ScalarBytes(property.type);
  }
  if (rest.empty() || stride == 0 || element.count > rest.size() / stride) return false;
  const ScalarType types[3] = {element.properties[static_cast<size_t>(xyz[0])].type,
                               element.properties[static_cast<size_t>(xyz[1])].type,
                               element.properties[static_cast<size_t>(xyz[2])].type};
  for (uint64_t v = 0; v < element.count; ++v) {
    const char* record = rest.data() + v * stride;
    reader.mesh.verticesFile[v] = {ScalarAt(record + offsets[0], types[0]),
                                   ScalarAt(record + offsets[1], types[1]),
                                   ScalarAt(record + offsets[2], types[2])};
  }
  reader.cursor.Skip(element.count * stride);
  return true;
}

std::optional<LoadError> ReadVertices(const Element& element, Reader& reader) {
  const int xyz[3] = {PropertyIndex(element, "x"), PropertyIndex(element, "y"),
                      PropertyIndex(element, "z")};
  if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) {
    return LoadError{reader.path, 0, 0, "the vertex element has no x, y and z properties"};
  }
  reader.mesh.verticesFile.reserve(element.count);
  AdviseHugePages(reader.mesh.verticesFile);
  reader.mesh.verticesFile.resize(element.count);
  if (ReadFixedVertices(element, xyz, reader)) return std::nullopt;
  for (uint64_t v = 0; v < element.count; ++v) {
    double coordinates[3] = {0, 0, 0};
    for (size_t p = 0; p < element.properties.size(); ++p) {
      const Property& property = element.properties[p];
      double value = 0.0;
      double count = 1.0;
      if (property.isList && !reader.cursor.Read(property.countType, count)) {
        return reader.Error("the file ends inside vertex " + std::to_string(v));
      }
      if (!(count >= 0.0) || count > 1e6) {
        return reader.Error("vertex " + std::to_string(v) + " has an impossible list length");
      }
      for (uint64_t i = 0; i < static_cast<uint64_t>(count); ++i) {
        if (!reader.cursor.Read(property.type, value)) {
          return reader.Error("expected a number in vertex " + std::to_string(v));
        }
      }
      for (int axis = 0; axis < 3; ++axis) {
        if (static_cast<int>(p) == xyz[axis]) coordinates[axis] = value;
      }
    }
    reader.mesh.verticesFile[v] = {coordinates[0], coordinates[1], coordinates[2]};
  }
  return std::nullopt;
}

// Fast path of ReadFaces: little-endian binary faces whose one property is
// a list of 3 or more 32-bit indices with a uint8 count. Reads faces while
// they are whole and every index names a vertex; returns how many it read,
// and the general path goes on from there (with whatever is wrong there).
uint64_t ReadPlainFaces(const Element& element, Reader& reader) {
  if (element.properties.size() != 1) return 0;
  const Property& list = element.properties[0];
  if (!list.isList || list.countType != ScalarType::kUint8 ||
      (list.type != ScalarType::kInt32 && list.type != ScalarType::kUint32)) {
    return 0;
  }
  const std::string_view rest = reader.cursor.RestLittleEndian();
  // int32 indices from 2^31 up are negative: the general path refuses them.
  const uint64_t named =
      list.type == ScalarType::kInt32
          ? std::min<uint64_t>(reader.mesh.verticesFile.size(), uint64_t{1} << 31)
          : reader.mesh.verticesFile.size();
  Mesh& mesh = reader.mesh;
  size_t at = 0;
  uint64_t f = 0;
  for (; f < element.count && at < rest.size(); ++f) {
    const size_t count = static_cast<uint8_t>(rest[at]);
    if (count < 3 || rest.size() - at - 1 < count * 4) break;
    // Read once (a mapped file may change under the reader): the indices
    // checked are the indices stored.
    uint32_t indices[UINT8_MAX];
    std::memcpy(indices, rest.data() + at + 1, count * 4);
    bool allNamed = true;
    for (size_t i = 0; i < count; ++i) allNamed = allNamed && indices[i] < named;
    if (!allNamed) break;
    for (size_t i = 0; i < count; ++i) {
      mesh.faceCorners.push_back(indices[i]);
      mesh.edgeHidden.push_back(0);
    }
    mesh.faceStarts.push_back(static_cast<uint32_t>(mesh.faceCorners.size()));
    at += 1 + count * 4;
  }
  reader.cursor.Skip(at);
  return f;
}

std::optional<LoadError> ReadFaces(const Element& element, Reader& reader) {
  int indices = PropertyIndex(element, "vertex_indices");
  if (indices < 0) indices = PropertyIndex(element, "vertex_index");
  if (indices < 0 || !element.properties[static_cast<size_t>(indices)].isList) {
    return LoadError{reader.path, 0, 0, "the face element has no vertex_indices list"};
  }
  const uint64_t vertexCount = reader.mesh.verticesFile.size();
  reader.mesh.faceStarts.reserve(element.count + 1);
  reader.mesh.faceCorners.reserve(element.count * 3);
  reader.mesh.edgeHidden.reserve(element.count * 3);
  AdviseHugePages(reader.mesh.faceStarts);
  AdviseHugePages(reader.mesh.faceCorners);
  AdviseHugePages(reader.mesh.edgeHidden);
  std::vector<uint32_t> corners;
  const uint64_t fastFaces = ReadPlainFaces(element, reader);
  for (uint64_t f = fastFaces; f < element.count; ++f) {
    for (size_t p = 0; p < element.properties.size(); ++p) {
      const Property& property = element.properties[p];
      double count = 1.0;
      if (property.isList && !reader.cursor.Read(property.countType, count)) {
        return reader.Error("the file ends inside face " + std::to_string(f));
      }
      if (!(count >= 0.0) || count > 1e6) {
        return reader.Error("face " + std::to_string(f) + " has an impossible corner count");
      }
      corners.clear();
      for (uint64_t i = 0; i < static_cast<uint64_t>(count); ++i) {
        double value = 0.0;
        if (!reader.cursor.Read(property.type, value)) {
          return reader.Error("expected a vertex index in face " + std::to_string(f));
        }
        if (static_cast<int>(p) != indices) continue;
        if (!(value >= 0.0) || value >= static_cast<double>(vertexCount) ||
            value != static_cast<double>(static_cast<uint64_t>(value))) {
          return reader.Error("face " + std::to_string(f) + " names vertex " +
                              std::to_string(static_cast<long long>(value)) + " (the file has " +
                              std::to_string(vertexCount) + " vertices)");
        }
        corners.push_back(static_cast<uint32_t>(value));
      }
      if (static_cast<int>(p) != indices) continue;
      if (corners.size() >= 3) {
        reader.mesh.AddFace(corners);
      } else if (corners.size() == 2) {
        reader.mesh.segments.push_back({corners[0], corners[1]});
      }
    }
  }
  return std::nullopt;
}

std::optional<LoadError> SkipElement(const Element& element, Reader& reader) {
  for (uint64_t e = 0; e < element.count; ++e) {
    for (const Property& property : element.properties) {
      double count = 1.0, value = 0.0;
      if (property.isList && !reader.cursor.Read(property.countType, count)) {
        return reader.Error("the file ends inside element " + element.name);
      }
      if (!(count >= 0.0) || count > 1e6) return reader.Error("an impossible list length");
      for (uint64_t i = 0; i < static_cast<uint64_t>(count); ++i) {
        if (!reader.cursor.Read(property.type, value)) {
          return reader.Error("the file ends inside element " + element.name);
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Loaded<Mesh>> ReadPly(std::string_view bytes, const std::string& path,
                                    size_t memoryBudgetBytes) {
  Loaded<Header> parsed = ParseHeader(bytes, path);
  if (!parsed.Ok()) return Loaded<Mesh>(parsed.Error());
  const Header& header = parsed.Value();
  if (NeedsImporter(header)) return std::nullopt;

  // Step 2: counts against the file's size, before allocating anything.
  const uint64_t dataBytes = bytes.size() - header.dataOffset;
  uint64_t needed = 0;
  for (const Element& element : header.elements) {
    const uint64_t each = std::max<uint64_t>(1, MinimumBytes(element, header.encoding));
    if (element.count > dataBytes / each) {
      return Loaded<Mesh>(LoadError{path, 0, 0,
                                    "the header promises " + std::to_string(element.count) + " " +
                                        element.name + " entries, more than the file can hold"});
    }
    needed += element.count * each;
  }
  if (needed > dataBytes) {
    return Loaded<Mesh>(LoadError{path, 0, 0, "the file is shorter than its header says"});
  }
  if (const uint64_t meshBytes = MeshBytes(header); meshBytes > memoryBudgetBytes) {
    return Loaded<Mesh>(LoadError{path, 0, 0, MemoryBudgetMessage(meshBytes, memoryBudgetBytes)});
  }

  // Step 3: the elements in file order.
  Reader reader{path,
                DataCursor(bytes.substr(header.dataOffset), header.encoding,
                           header.encoding == Encoding::kAscii ? header.dataLine : 0),
                Mesh{}};
  reader.mesh.name = path;
  bool sawVertices = false;
  for (const Element& element : header.elements) {
    std::optional<LoadError> problem;
    if (element.name == "vertex" && !sawVertices) {
      problem = ReadVertices(element, reader);
      sawVertices = true;
    } else if (element.name == "face" && sawVertices) {
      problem = ReadFaces(element, reader);
    } else if (element.name == "face") {
      return std::nullopt;  // faces before vertices: the importer's problem
    } else {
      problem = SkipElement(element, reader);
    }
    if (problem) return Loaded<Mesh>(*problem);
  }
  if (reader.mesh.FaceCount() == 0) {
    return Loaded<Mesh>(LoadError{path, 0, 0, "the file holds no polygons"});
  }
  DropUnusedVertices(reader.mesh);
  return Loaded<Mesh>(std::move(reader.mesh));
}

std::optional<LoadError> CheckPlyHeaderForImporter(std::string_view bytes,
                                                   const std::string& path) {
  // Step 1: where Assimp's first line starts (a leading line end skips to past the first '\n').
  const auto isLineEnd = [](char c) { return c == '\n' || c == '\r' || c == '\0' || c == '\f'; };
  size_t start = 0;
  if (!bytes.empty() && isLineEnd(bytes[0])) {
    const size_t newline = bytes.find('\n');
    if (newline == std::string_view::npos) return std::nullopt;
    start = newline + 1;
  }
  const std::string_view text = bytes.substr(start);
  const auto lower = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  if (text.size() < 3 || lower(text[0]) != 'p' || lower(text[1]) != 'l' || lower(text[2]) != 'y') {
    return std::nullopt;
  }
  // Step 2: a header this reader ends. Assimp splits lines at more bytes than
  // '\n' but starts a line after every '\n', so it reaches the same 'end_header'.
  Loaded<Header> parsed = ParseHeader(text, path);
  const int lineShift = start > 0 ? 1 : 0;
  if (!parsed.Ok()) {
    LoadError error = parsed.Error();
    if (error.line > 0) error.line += lineShift;
    return error;
  }
  // Step 3: the header's counts against the bytes after it, from where Assimp starts.
  if (auto problem = CheckHeaderCounts("ply", text)) return LoadError{path, 0, 0, *problem};
  // Step 4: no byte at which Assimp ends a line and this reader does not (NUL,
  // form feed, a carriage return not before '\n'): it could hide an element
  // line from the header counts' check ("comment\0element vertex 2000000000").
  const std::string_view header = text.substr(0, parsed.Value().dataOffset);
  int line = 1 + lineShift;
  for (size_t i = 0; i < header.size(); ++i) {
    const char c = header[i];
    if (c == '\n') ++line;
    const bool crBeforeNewline = c == '\r' && i + 1 < header.size() && header[i + 1] == '\n';
    if (c == '\0' || c == '\f' || (c == '\r' && !crBeforeNewline)) {
      return LoadError{path, line, 1,
                       "the PLY header holds a NUL, form feed or lone carriage return; expected "
                       "text lines up to 'end_header'"};
    }
  }
  return std::nullopt;
}

}  // namespace termshade
