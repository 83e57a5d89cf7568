#include "tui/LineEditor.h"

namespace termshade {

void LineEditor::Insert(char c) {
  if (c < 0x20 || c > 0x7e || text_.size() >= 4096) return;
  text_.insert(text_.begin() + static_cast<std::ptrdiff_t>(cursor_), c);
  ++cursor_;
}

void LineEditor::Backspace() {
  if (cursor_ == 0) return;
  --cursor_;
  text_.erase(cursor_, 1);
}

void LineEditor::Delete() {
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
}

}  // namespace termshade
