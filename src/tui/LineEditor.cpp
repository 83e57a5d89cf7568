#include "tui/LineEditor.h"

#include "shade/Utf8.h"

namespace termshade {
namespace {

constexpr size_t kMaxCodePoints = 4096;

bool IsControl(char32_t c) {
  return c < 0x20 || (c >= 0x7F && c <= 0x9F);
}

}  // namespace

void LineEditor::InsertByte(unsigned char byte) {
  if (byte < 0x80) {
    pending_.clear();
    Insert(byte);
    return;
  }
  // Step 1: a lead byte starts a sequence; a continuation byte extends one.
  const bool continuation = (byte & 0xC0) == 0x80;
  if (!continuation) pending_.clear();
  if (continuation && pending_.empty()) return;
  pending_ += static_cast<char>(byte);
  const auto wanted =
      static_cast<size_t>(Utf8SequenceLength(static_cast<unsigned char>(pending_[0])));
  if (wanted == 0) {
    pending_.clear();
    return;
  }
  // Step 2: once complete, one code point (or nothing, if invalid).
  if (pending_.size() < wanted) return;
  const auto decoded = DecodeUtf8(pending_);
  pending_.clear();
  if (decoded && decoded->size() == 1) Insert(decoded->front());
}

void LineEditor::Insert(char32_t codePoint) {
  if (IsControl(codePoint) || text_.size() >= kMaxCodePoints) return;
  text_.insert(text_.begin() + static_cast<std::ptrdiff_t>(cursor_), codePoint);
  ++cursor_;
}

std::string LineEditor::Text() const {
  std::string bytes;
  for (char32_t c : text_) {
    if (IsRawByte(c)) {
      bytes += static_cast<char>(c - kRawByteBase);
    } else {
      AppendUtf8(bytes, c);
    }
  }
  return bytes;
}

void LineEditor::Backspace() {
  pending_.clear();
  if (cursor_ == 0) return;
  --cursor_;
  text_.erase(cursor_, 1);
}

void LineEditor::Delete() {
  pending_.clear();
  if (cursor_ < text_.size()) text_.erase(cursor_, 1);
}

void LineEditor::Left() {
  if (cursor_ > 0) --cursor_;
}

void LineEditor::Right() {
  if (cursor_ < text_.size()) ++cursor_;
}

void LineEditor::Clear() {
  text_.clear();
  cursor_ = 0;
  pending_.clear();
}

void LineEditor::SetText(std::string_view bytes) {
  Clear();
  for (size_t i = 0; i < bytes.size();) {
    // A printable code point in valid UTF-8 as typed; any other byte raw.
    const auto lead = static_cast<unsigned char>(bytes[i]);
    const auto length = static_cast<size_t>(Utf8SequenceLength(lead));
    if (length > 0 && i + length <= bytes.size()) {
      const auto decoded = DecodeUtf8(bytes.substr(i, length));
      if (decoded && decoded->size() == 1 && !IsControl(decoded->front())) {
        Insert(decoded->front());
        i += length;
        continue;
      }
    }
    if (text_.size() < kMaxCodePoints) {
      text_.insert(text_.begin() + static_cast<std::ptrdiff_t>(cursor_), kRawByteBase + lead);
      ++cursor_;
    }
    ++i;
  }
}

}  // namespace termshade
