#include "tui/ShellQuote.h"

#include <cstdio>

#include "shade/Utf8.h"

namespace termshade {
namespace {

bool Plain(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         std::string_view("@%+=:,./-_").find(c) != std::string_view::npos;
}

// Whether single quotes keep the word as typed text: valid UTF-8, no control
// characters (C0, DEL, C1).
bool Printable(std::string_view word) {
  const auto codePoints = DecodeUtf8(word);
  if (!codePoints) return false;
  for (const char32_t c : *codePoints) {
    if (c < 0x20 || (c >= 0x7f && c < 0xa0)) return false;
  }
  return true;
}

}  // namespace

std::string ShellQuote(std::string_view word) {
  bool plain = !word.empty();
  for (const char c : word) plain = plain && Plain(c);
  if (plain) return std::string(word);
  std::string quoted;
  if (Printable(word)) {
    quoted.push_back('\'');
    for (const char c : word) {
      if (c == '\'') {
        quoted.append("'\\''");
      } else {
        quoted.push_back(c);
      }
    }
    quoted.push_back('\'');
    return quoted;
  }
  quoted.append("$'");
  for (const char c : word) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f && c != '\'' && c != '\\') {
      quoted.push_back(c);
    } else {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\x%02x", byte);
      quoted.append(escape);
    }
  }
  quoted.push_back('\'');
  return quoted;
}

}  // namespace termshade
