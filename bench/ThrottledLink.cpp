#include "ThrottledLink.h"

#include <algorithm>
#include <charconv>
#include <limits>

namespace termshade {
namespace {

// Bytes that arrive together: a piece leaves the link whole (about a TCP
// segment; finer than any frame).
constexpr size_t kPieceBytes = 1024;

std::optional<double> NumberWithUnit(std::string_view text, std::string_view unit) {
  if (text.size() <= unit.size() || text.substr(text.size() - unit.size()) != unit) {
    return std::nullopt;
  }
  text.remove_suffix(unit.size());
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !(value >= 0.0)) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

std::optional<LinkSpec> ParseLinkSpec(std::string_view text) {
  const size_t colon = text.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const std::string_view rate = text.substr(0, colon), delay = text.substr(colon + 1);
  LinkSpec spec;
  if (const auto kbit = NumberWithUnit(rate, "kbit")) {
    spec.bytesPerSecond = *kbit * 1000.0 / 8.0;
  } else if (const auto mbit = NumberWithUnit(rate, "mbit")) {
    spec.bytesPerSecond = *mbit * 1e6 / 8.0;
  } else {
    return std::nullopt;
  }
  const auto ms = NumberWithUnit(delay, "ms");
  if (!ms || spec.bytesPerSecond <= 0.0 || *ms > 10000.0) return std::nullopt;
  spec.delaySeconds = *ms / 1000.0;
  return spec;
}

void ThrottledLink::Push(double now, std::string_view bytes) {
  for (size_t at = 0; at < bytes.size(); at += kPieceBytes) {
    const std::string_view piece = bytes.substr(at, kPieceBytes);
    const double start = std::max(now, freeAt_);
    freeAt_ = spec_.bytesPerSecond > 0.0
                  ? start + static_cast<double>(piece.size()) / spec_.bytesPerSecond
                  : start;
    pieces_.push_back({freeAt_ + spec_.delaySeconds, std::string(piece)});
    queuedBytes_ += piece.size();
  }
}

std::string ThrottledLink::TakeArrived(double now) {
  std::string arrived;
  while (!pieces_.empty() && pieces_.front().arrival <= now) {
    arrived += pieces_.front().bytes;
    queuedBytes_ -= pieces_.front().bytes.size();
    pieces_.pop_front();
  }
  return arrived;
}

double ThrottledLink::NextArrival() const {
  return pieces_.empty() ? std::numeric_limits<double>::max() : pieces_.front().arrival;
}

}  // namespace termshade
