#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace termshade {

/// A located problem with an input: file:line:column: message (line and
/// column 1-based; 0 when the problem has no place in the text).
struct LoadError {
  std::string file;
  int line = 0;
  int column = 0;
  std::string message;

  /// keepUtf8: as SanitizeForTerminal's.
  std::string ToString(bool keepUtf8 = false) const;
};

/// Either a value or the error that prevented it.
template <typename T>
class Loaded {
 public:
  Loaded(T value) : state_(std::move(value)) {}          // NOLINT(google-explicit-constructor)
  Loaded(LoadError error) : state_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  bool Ok() const { return std::holds_alternative<T>(state_); }
  T& Value() { return std::get<T>(state_); }
  const LoadError& Error() const { return std::get<LoadError>(state_); }

 private:
  std::variant<T, LoadError> state_;
};

/// Makes text from a file safe to show: control bytes, DEL and bytes >= 0x80
/// become \xNN, so no escape sequence reaches a terminal. keepUtf8 (a UTF-8
/// terminal): valid UTF-8 for a code point SafeCodePointCells accepts stays
/// as it is.
std::string SanitizeForTerminal(std::string_view text, size_t maxLength = 200,
                                bool keepUtf8 = false);

/// As SanitizeForTerminal, line by line: newlines stay, nothing is cut short
/// (help text, multi-line messages).
std::string SanitizeLinesForTerminal(std::string_view text);

}  // namespace termshade
