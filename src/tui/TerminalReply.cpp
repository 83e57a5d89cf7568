#include "tui/TerminalReply.h"

#include <charconv>

namespace termshade {
namespace {

constexpr int kMaxCellPx = 1000;  // a larger cell is not believed

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// One channel of `rgb:`: 1 to 4 hex digits, scaled to 0..1 by its width.
std::optional<double> Channel(std::string_view digits) {
  if (digits.empty() || digits.size() > 4) return std::nullopt;
  int value = 0;
  for (char c : digits) {
    if (HexDigit(c) < 0) return std::nullopt;
    value = value * 16 + HexDigit(c);
  }
  return value / static_cast<double>((1 << (4 * digits.size())) - 1);
}

// "524742" -> "RGB"; nullopt when not pairs of hex digits.
std::optional<std::string> FromHex(std::string_view hex) {
  if (hex.empty() || hex.size() % 2 != 0) return std::nullopt;
  std::string out;
  for (size_t i = 0; i < hex.size(); i += 2) {
    const int high = HexDigit(hex[i]), low = HexDigit(hex[i + 1]);
    if (high < 0 || low < 0) return std::nullopt;
    out += static_cast<char>(high * 16 + low);
  }
  return out;
}

// The next ';'-separated number of `text` (consumed), or nullopt.
std::optional<int> TakeNumber(std::string_view& text) {
  const size_t end = text.find(';');
  const std::string_view part = text.substr(0, end);
  int value = 0;
  const auto [at, error] = std::from_chars(part.data(), part.data() + part.size(), value);
  if (error != std::errc() || at != part.data() + part.size() || part.empty()) return std::nullopt;
  text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  return value;
}

}  // namespace

TerminalReply ReplyFromOsc(std::string_view body) {
  TerminalReply reply;
  constexpr std::string_view kPrefix = "11;rgb:";
  if (body.substr(0, kPrefix.size()) != kPrefix) return reply;
  body.remove_prefix(kPrefix.size());
  const size_t first = body.find('/');
  const size_t second = first == std::string_view::npos ? first : body.find('/', first + 1);
  if (second == std::string_view::npos) return reply;
  const auto red = Channel(body.substr(0, first));
  const auto green = Channel(body.substr(first + 1, second - first - 1));
  const auto blue = Channel(body.substr(second + 1));
  if (!red || !green || !blue) return reply;
  reply.kind = TerminalReply::Kind::kBackgroundColour;
  reply.red = *red;
  reply.green = *green;
  reply.blue = *blue;
  return reply;
}

TerminalReply ReplyFromDcs(std::string_view body) {
  TerminalReply reply;
  if (body.size() < 4 || (body[0] != '0' && body[0] != '1') || body.substr(1, 2) != "+r") {
    return reply;
  }
  const std::string_view names = body.substr(3);
  const auto name = FromHex(names.substr(0, names.find('=')));
  if (!name) return reply;
  reply.kind = TerminalReply::Kind::kCapability;
  reply.capability = *name;
  reply.hasCapability = body[0] == '1';
  return reply;
}

std::optional<TerminalReply> ReplyFromCsi(std::string_view parameters, char finalByte) {
  if (finalByte != 't') return std::nullopt;
  const auto kind = TakeNumber(parameters);
  const auto height = TakeNumber(parameters);
  const auto width = TakeNumber(parameters);
  if (kind != 6 || !height || !width || !parameters.empty()) return std::nullopt;
  if (*height < 1 || *width < 1 || *height > kMaxCellPx || *width > kMaxCellPx) {
    return std::nullopt;
  }
  TerminalReply reply;
  reply.kind = TerminalReply::Kind::kCellSize;
  reply.cellWidthPx = *width;
  reply.cellHeightPx = *height;
  return reply;
}

}  // namespace termshade
