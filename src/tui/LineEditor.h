#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace termshade {

/// A one-line text field with a cursor (the viewer's "open file" prompt).
/// Holds code points; typed bytes arrive one at a time and UTF-8 sequences
/// are assembled here. Control characters (C0, DEL, C1) and invalid UTF-8
/// typed are dropped, so nothing typed can reach the terminal as a control.
/// Text set from a file name (Tab completion) keeps such bytes, each held
/// as a code point of its own (kRawByteBase + byte, a lone surrogate no
/// UTF-8 input gives) and given back as the byte by Text().
class LineEditor {
 public:
  /// One byte of typed input (ASCII, or part of a UTF-8 sequence).
  void InsertByte(unsigned char byte);
  void Backspace();
  void Delete();
  void Left();
  void Right();
  void Home() { cursor_ = 0; }
  void End() { cursor_ = text_.size(); }
  void Clear();
  /// Replaces the text, the cursor at its end: UTF-8 as if typed, and every
  /// other byte (controls, invalid UTF-8) kept as a raw byte.
  void SetText(std::string_view bytes);

  /// Raw byte b is held as the code point kRawByteBase + b.
  static constexpr char32_t kRawByteBase = 0xDC00;
  static bool IsRawByte(char32_t c) { return c >= kRawByteBase && c <= kRawByteBase + 0xFF; }

  /// The text as code points; Cursor() counts code points.
  const std::u32string& CodePoints() const { return text_; }
  /// The text as bytes: UTF-8, with raw bytes as they were (a path to open).
  std::string Text() const;
  size_t Cursor() const { return cursor_; }

 private:
  void Insert(char32_t codePoint);

  std::u32string text_;
  size_t cursor_ = 0;
  std::string pending_;  ///< the start of a UTF-8 sequence still being typed
};

}  // namespace termshade
