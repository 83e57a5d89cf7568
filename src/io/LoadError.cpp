#include "io/LoadError.h"

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
  return out + ": " + message;
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

}  // namespace termshade
