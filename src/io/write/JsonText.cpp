#include "io/write/JsonText.h"

#include <cstdio>

namespace termshade {
namespace {

// How a byte is written in a JSON string: itself, backslash and itself, or \u00XX.
enum class Escape { kNone, kBackslash, kUnicode };

Escape EscapeOf(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (c == '"' || c == '\\') return Escape::kBackslash;
  return byte < 0x20 || byte == 0x7F ? Escape::kUnicode : Escape::kNone;
}

}  // namespace

void AppendJsonText(std::string_view text, std::string& out) {
  out += '"';
  for (const char c : text) {
    switch (EscapeOf(c)) {
      case Escape::kNone:
        out += c;
        break;
      case Escape::kBackslash:
        out += '\\';
        out += c;
        break;
      case Escape::kUnicode: {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(c));
        out += escaped;
        break;
      }
    }
  }
  out += '"';
}

size_t JsonTextLength(std::string_view text) {
  size_t length = 0;
  for (const char c : text) {
    const Escape escape = EscapeOf(c);
    length += escape == Escape::kNone ? 1 : escape == Escape::kBackslash ? 2 : 6;
  }
  return length;
}

}  // namespace termshade
