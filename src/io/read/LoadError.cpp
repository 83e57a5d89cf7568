#include "io/read/LoadError.h"

#include <algorithm>
#include <cstdio>

#include "shade/Utf8.h"

namespace termshade {

std::string LoadError::ToString(bool keepUtf8) const {
  std::string out = SanitizeForTerminal(file, 4096, keepUtf8);
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
  return out + ": " + SanitizeForTerminal(message, 1000, keepUtf8);
}

std::string SanitizeForTerminal(std::string_view text, size_t maxLength, bool keepUtf8) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (out.size() >= maxLength) {
      out += "...";
      break;
    }
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += text[i++];
      continue;
    }
    // A whole UTF-8 sequence the terminal shows safely, one or two cells wide.
    if (keepUtf8 && byte >= 0x80) {
      const auto length = static_cast<size_t>(Utf8SequenceLength(byte));
      const std::string_view sequence = text.substr(i, length);
      const auto decoded = length > 1 && sequence.size() == length
                               ? DecodeUtf8(sequence)
                               : std::optional<std::vector<char32_t>>{};
      if (decoded && SafeCodePointCells(decoded->front()) > 0) {
        out += sequence;
        i += length;
        continue;
      }
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
    out += escaped;
    ++i;
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
