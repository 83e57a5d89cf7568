#include "io/read/ContentSniff.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>

namespace termshade {
namespace {

struct Magic {
  std::string_view prefix;
  std::string_view what;
};

constexpr std::array<Magic, 16> kMagics{{
    {"\x89PNG\r\n\x1a\n", "PNG image"},
    {"\xff\xd8\xff", "JPEG image"},
    {"GIF87a", "GIF image"},
    {"GIF89a", "GIF image"},
    {"BM", "BMP image"},
    {"%PDF-", "PDF document"},
    {"\x7f"
     "ELF",
     "ELF executable"},
    {"\x1f\x8b", "gzip-compressed data"},
    {"BZh", "bzip2-compressed data"},
    {"\xfd"
     "7zXZ\0",
     "xz-compressed data"},
    {"7z\xbc\xaf\x27\x1c", "7-Zip archive"},
    {"\x28\xb5\x2f\xfd", "zstd-compressed data"},
    {"OggS", "Ogg media"},
    {"ID3", "MP3 audio"},
    {"RIFF", "RIFF media (WAV, AVI or WebP)"},
    {"\xca\xfe\xba\xbe", "Java class or Mach-O file"},
}};

bool HoldsOwnSize(std::string_view bytes) {
  if (bytes.size() < 26) return false;
  uint32_t size = 0;
  for (int i = 5; i >= 2; --i) size = (size << 8) | static_cast<unsigned char>(bytes[i]);
  return size == bytes.size();
}

bool IsBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

bool IsNumber(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return (ec == std::errc() || ec == std::errc::result_out_of_range) &&
         end == token.data() + token.size();
}

}  // namespace

std::optional<std::string> RecognisedNonModel(std::string_view bytes) {
  for (const Magic& magic : kMagics) {
    if (bytes.substr(0, magic.prefix.size()) == magic.prefix) {
      // "BM" alone is weak: a BMP also holds its own size at bytes 2..5 (little-endian).
      if (magic.what == "BMP image" && !HoldsOwnSize(bytes)) continue;
      return std::string(magic.what);
    }
  }
  return std::nullopt;
}

bool LooksLikeDat(std::string_view bytes) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (bytes.substr(0, 3) == kByteOrderMark) bytes.remove_prefix(3);
  // Step 1: the first line with anything on it.
  std::string_view line;
  while (!bytes.empty()) {
    const size_t end = std::min(bytes.find('\n'), bytes.size());
    line = bytes.substr(0, end);
    bytes.remove_prefix(std::min(end + 1, bytes.size()));
    while (!line.empty() && IsBlank(line.front())) line.remove_prefix(1);
    while (!line.empty() && IsBlank(line.back())) line.remove_suffix(1);
    if (!line.empty()) break;
  }
  if (line.substr(0, 6) == "Faces:") return true;
  // Step 2: a vertex number and exactly three coordinates.
  std::array<std::string_view, 5> tokens{};
  size_t count = 0;
  while (!line.empty()) {
    const size_t end = std::min(
        static_cast<size_t>(std::find_if(line.begin(), line.end(), IsBlank) - line.begin()),
        line.size());
    if (count == tokens.size()) return false;
    tokens[count++] = line.substr(0, end);
    line.remove_prefix(end);
    while (!line.empty() && IsBlank(line.front())) line.remove_prefix(1);
  }
  if (count != 4) return false;
  if (!std::all_of(tokens[0].begin(), tokens[0].end(),
                   [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; })) {
    return false;
  }
  return IsNumber(tokens[1]) && IsNumber(tokens[2]) && IsNumber(tokens[3]);
}

std::string LowerExtension(std::string_view path) {
  const size_t slash = path.find_last_of('/');
  const std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  if (dot == std::string_view::npos || dot == 0) return "";
  std::string ext(name.substr(dot + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace termshade
