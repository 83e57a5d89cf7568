#pragma once

#include <string>

namespace termshade {

/// A one-line text field with a cursor (the viewer's "open file" prompt).
/// Accepts printable ASCII only, so nothing typed can reach the terminal as a control.
class LineEditor {
 public:
  void Insert(char c);
  void Backspace();
  void Delete();
  void Left();
  void Right();
  void Home() { cursor_ = 0; }
  void End() { cursor_ = text_.size(); }
  void Clear();

  const std::string& Text() const { return text_; }
  size_t Cursor() const { return cursor_; }

 private:
  std::string text_;
  size_t cursor_ = 0;
};

}  // namespace termshade
