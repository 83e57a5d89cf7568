#include "io/read/DatReader.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace termshade {
namespace {

constexpr int64_t kMaxVertexNumber = std::numeric_limits<int32_t>::max();

bool IsBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
bool IsDigit(char c) {
  return c >= '0' && c <= '9';
}

// A cursor over one line, with 1-based columns for messages.
class LineCursor {
 public:
  explicit LineCursor(std::string_view line) : line_(line) {}

  void SkipBlanks() {
    while (pos_ < line_.size() && IsBlank(line_[pos_])) ++pos_;
  }
  bool AtEnd() const { return pos_ >= line_.size(); }
  char Peek() const { return AtEnd() ? '\0' : line_[pos_]; }
  void Advance(size_t n = 1) { pos_ += n; }
  int Column() const { return static_cast<int>(pos_) + 1; }
  std::string_view Rest() const { return line_.substr(pos_); }
  // What stands at the cursor, for messages.
  std::string Found() const {
    if (AtEnd()) return "end of line";
    std::string quoted = "'";  // built up: GCC 12 warns falsely on "'" + string + "'"
    quoted += SanitizeForTerminal(line_.substr(pos_, 1));
    quoted += '\'';
    return quoted;
  }

  // Digits of an integer; returns false (consuming nothing) if none.
  bool ReadDigits(int64_t& value, bool& overflow) {
    if (!IsDigit(Peek())) return false;
    value = 0;
    overflow = false;
    while (IsDigit(Peek())) {
      value = value * 10 + (Peek() - '0');
      if (value > kMaxVertexNumber) {
        overflow = true;
        value = kMaxVertexNumber + 1;
      }
      Advance();
    }
    return true;
  }

  // A float: [+-] digits [. digits] [e [+-] digits], or [+-] . digits [...].
  // Returns the token's length, 0 when there is no number here.
  size_t FloatLength() const {
    size_t i = pos_;
    auto digitsFrom = [&](size_t& at) {
      const size_t start = at;
      while (at < line_.size() && IsDigit(line_[at])) ++at;
      return at - start;
    };
    if (i < line_.size() && (line_[i] == '+' || line_[i] == '-')) ++i;
    size_t mantissaDigits = digitsFrom(i);
    if (i < line_.size() && line_[i] == '.') {
      ++i;
      mantissaDigits += digitsFrom(i);
    }
    if (mantissaDigits == 0) return 0;
    if (i < line_.size() && (line_[i] == 'e' || line_[i] == 'E')) {
      size_t j = i + 1;
      if (j < line_.size() && (line_[j] == '+' || line_[j] == '-')) ++j;
      if (digitsFrom(j) > 0) i = j;
    }
    return i - pos_;
  }

 private:
  std::string_view line_;
  size_t pos_ = 0;
};

class DatParser {
 public:
  DatParser(std::string_view text, const std::string& fileName, const std::atomic<bool>* cancel,
            const std::function<void(double)>& progress)
      : text_(text), file_(fileName), cancel_(cancel), progress_(progress) {
    mesh_.name = fileName;
  }

  Loaded<Mesh> Run() {
    ReserveForFaces();
    size_t start = 0;
    while (start <= text_.size() && !failed_) {
      if ((lineNumber_ & kLinesBetweenChecks) == 0 && !KeepGoing(start)) {
        return LoadError{file_, 0, 0, "loading cancelled"};
      }
      const size_t end = text_.find('\n', start);
      const size_t stop = end == std::string_view::npos ? text_.size() : end;
      ++lineNumber_;
      ParseLine(text_.substr(start, stop - start));
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
    if (failed_) return error_;
    if (!inFaces_) {
      return LoadError{file_, lineNumber_, 1,
                       "expected a 'Faces:' line after the vertices (found end of file)"};
    }
    vertexLines_ = {};
    vertexIndex_ = {};
    return std::move(mesh_);
  }

 private:
  static constexpr int kLinesBetweenChecks = (1 << 14) - 1;

  // Polls cancel and reports progress; false once cancelled.
  bool KeepGoing(size_t position) const {
    if (cancel_ != nullptr && cancel_->load(std::memory_order_relaxed)) return false;
    if (progress_ && !text_.empty()) {
      progress_(static_cast<double>(position) / static_cast<double>(text_.size()));
    }
    return true;
  }

  // Reserves the face lists once from counts of the text after 'Faces:', so
  // they never grow by doubling (which held up to twice their size, plus a copy).
  void ReserveForFaces() {
    const size_t facesAt = text_.find("Faces:");
    if (facesAt == std::string_view::npos) return;
    const std::string_view faces = text_.substr(facesAt);
    size_t lines = 0, corners = 0;
    bool inNumber = false;
    for (const char c : faces) {
      lines += c == '\n' ? 1 : 0;
      const bool digit = IsDigit(c);
      corners += digit && !inNumber ? 1 : 0;
      inNumber = digit;
    }
    mesh_.faceCorners.reserve(corners);
    mesh_.edgeHidden.reserve(corners);
    mesh_.faceStarts.reserve(lines + 2);
  }

  void Fail(int column, std::string message) {
    if (failed_) return;
    failed_ = true;
    error_ = LoadError{file_, lineNumber_, column, std::move(message)};
  }

  void ParseLine(std::string_view line) {
    LineCursor cursor(line);
    cursor.SkipBlanks();
    if (cursor.AtEnd()) return;
    if (inFaces_) {
      ParseFace(cursor);
    } else if (cursor.Rest().substr(0, 6) == "Faces:") {
      cursor.Advance(6);
      ExpectLineEnd(cursor, "after 'Faces:'");
      inFaces_ = true;
    } else {
      ParseVertex(cursor);
    }
  }

  void ExpectLineEnd(LineCursor& cursor, const std::string& after) {
    cursor.SkipBlanks();
    if (!cursor.AtEnd()) {
      Fail(cursor.Column(), "expected end of line " + after + ", found " + cursor.Found());
    }
  }

  void ParseVertex(LineCursor& cursor) {
    // Step 1: the vertex number.
    const int numberColumn = cursor.Column();
    if (cursor.Peek() == '-' || cursor.Peek() == '+') {
      Fail(numberColumn,
           "expected a vertex number (a whole number >= 1) or 'Faces:', found " + cursor.Found());
      return;
    }
    int64_t number = 0;
    bool overflow = false;
    if (!cursor.ReadDigits(number, overflow)) {
      Fail(numberColumn, "expected a vertex number or 'Faces:', found " + cursor.Found());
      return;
    }
    if (overflow) {
      Fail(numberColumn, "vertex number is too large (at most 2147483647)");
      return;
    }
    if (number == 0) {
      Fail(numberColumn, "vertex number 0 is not valid (vertex numbers start at 1)");
      return;
    }
    if (cursor.Peek() == '.' || !(cursor.AtEnd() || IsBlank(cursor.Peek()))) {
      Fail(cursor.Column(), "expected a blank after vertex number " + std::to_string(number) +
                                ", found " + cursor.Found());
      return;
    }
    if (const auto it = vertexLines_.find(number); it != vertexLines_.end()) {
      Fail(numberColumn, "vertex " + std::to_string(number) + " is already defined on line " +
                             std::to_string(it->second));
      return;
    }
    // Step 2: three coordinates.
    double xyz[3] = {};
    static constexpr const char* kAxis[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      cursor.SkipBlanks();
      const std::string what =
          std::string("the ") + kAxis[axis] + " coordinate of vertex " + std::to_string(number);
      if (!ReadCoordinate(cursor, what, xyz[axis])) return;
    }
    ExpectLineEnd(cursor, "after the z coordinate of vertex " + std::to_string(number));
    if (failed_) return;
    vertexLines_.emplace(number, lineNumber_);
    vertexIndex_.emplace(number, static_cast<uint32_t>(mesh_.verticesFile.size()));
    mesh_.verticesFile.push_back({xyz[0], xyz[1], xyz[2]});
    highestVertex_ = std::max(highestVertex_, number);
  }

  bool ReadCoordinate(LineCursor& cursor, const std::string& what, double& value) {
    const int column = cursor.Column();
    const size_t length = cursor.FloatLength();
    if (length == 0) {
      Fail(column, "expected " + what + " (a number), found " + cursor.Found());
      return false;
    }
    std::string_view token = cursor.Rest().substr(0, length);
    if (token.front() == '+') token.remove_prefix(1);
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    const size_t exponentAt = token.find_first_of("eE");
    const bool negativeExponent =
        exponentAt != std::string_view::npos && token.substr(exponentAt + 1, 1) == "-";
    if (ec == std::errc::result_out_of_range && negativeExponent) {
      value = 0.0;  // underflow: too small to tell from zero
    } else if (ec != std::errc() || !std::isfinite(value)) {
      Fail(column, what + " is out of range for a double");
      return false;
    }
    cursor.Advance(length);
    if (!(cursor.AtEnd() || IsBlank(cursor.Peek()))) {
      Fail(cursor.Column(), "expected a blank after " + what + ", found " + cursor.Found());
      return false;
    }
    return true;
  }

  void ParseFace(LineCursor& cursor) {
    corners_.clear();
    hidden_.clear();
    while (!failed_) {
      cursor.SkipBlanks();
      const char c = cursor.Peek();
      if (c == '.' || c == '#') {
        cursor.Advance();
        ExpectLineEnd(cursor, "after the end of the face");
        break;
      }
      if (cursor.AtEnd()) {
        Fail(cursor.Column(), "expected a vertex number, or '.' or '#' to end the face");
        return;
      }
      ReadFaceCorner(cursor);
    }
    if (failed_) return;
    if (corners_.size() >= 3) {
      mesh_.AddFace(corners_, hidden_);
    } else if (corners_.size() == 2) {
      mesh_.segments.push_back({corners_[0], corners_[1]});
    }
  }

  void ReadFaceCorner(LineCursor& cursor) {
    const int column = cursor.Column();
    const bool hidden = cursor.Peek() == '-';
    if (hidden) cursor.Advance();
    int64_t number = 0;
    bool overflow = false;
    if (!cursor.ReadDigits(number, overflow)) {
      Fail(cursor.Column(),
           "expected a vertex number, or '.' or '#' to end the face, found " + cursor.Found());
      return;
    }
    const char next = cursor.Peek();
    if (!(cursor.AtEnd() || IsBlank(next) || next == '.' || next == '#')) {
      Fail(cursor.Column(), "expected a blank, '.' or '#' after vertex number " +
                                std::to_string(number) + ", found " + cursor.Found());
      return;
    }
    if (number == 0) {
      Fail(column, "vertex number 0 is not valid (vertex numbers start at 1)");
      return;
    }
    const auto it = overflow ? vertexIndex_.end() : vertexIndex_.find(number);
    if (it == vertexIndex_.end()) {
      const std::string shown = overflow ? "number" : std::to_string(number);
      Fail(column, "vertex " + shown + " is not defined (" +
                       (highestVertex_ > 0 ? "highest is " + std::to_string(highestVertex_)
                                           : std::string("no vertices are defined")) +
                       ")");
      return;
    }
    corners_.push_back(it->second);
    hidden_.push_back(hidden ? 1 : 0);
  }

  std::string_view text_;
  std::string file_;
  const std::atomic<bool>* cancel_;
  const std::function<void(double)>& progress_;
  Mesh mesh_;
  int lineNumber_ = 0;
  bool inFaces_ = false;
  bool failed_ = false;
  LoadError error_;
  int64_t highestVertex_ = 0;
  std::unordered_map<int64_t, uint32_t> vertexIndex_;
  std::unordered_map<int64_t, int> vertexLines_;
  std::vector<uint32_t> corners_;
  std::vector<uint8_t> hidden_;
};

}  // namespace

Loaded<Mesh> ParseDat(std::string_view text, const std::string& fileName) {
  return ParseDat(text, fileName, nullptr, {});
}

Loaded<Mesh> ParseDat(std::string_view text, const std::string& fileName,
                      const std::atomic<bool>* cancel,
                      const std::function<void(double)>& progress) {
  // A UTF-8 byte order mark (some Windows editors write one) is not content;
  // columns on line 1 count from after it, as an editor shows them.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark)
    text.remove_prefix(kByteOrderMark.size());
  return DatParser(text, fileName, cancel, progress).Run();
}

}  // namespace termshade
