#include "io/LoadError.h"

#include <algorithm>
#include <cstdio>

namespace termshade {

std::string LoadError::ToString() const {
  std::string out = SanitizeForTerminal(file, 4096);
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
    if (column > 0) {
      out += ':';
      out += std::to_string(column);
    }
  }
  // Messages quote file content and importers' text: escaped too (escaping
  // is idempotent, so already escaped text stays as it is).
  return out + ": " + SanitizeForTerminal(message, 1000);
}

std::string SanitizeForTerminal(std::string_view text, size_t maxLength) {
  std::string out;
  for (char c : text) {
    if (out.size() >= maxLength) {
      out += "...";
      break;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      out += escaped;
    }
  }
  return out;
}

std::string SanitizeLinesForTerminal(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    out += SanitizeForTerminal(text.substr(start, end - start), text.size() * 4 + 4);
    if (end == text.size()) break;
    out += '\n';
    start = end + 1;
  }
  return out;
}

}  // namespace termshade
