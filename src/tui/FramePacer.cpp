#include "tui/FramePacer.h"

#include <algorithm>

namespace termshade {
namespace {

// Requests remembered at most: a terminal that never answers gets one per
// frame, and only the newest matter once it does.
constexpr size_t kMaxRequestsKept = 64;

}  // namespace

void FramePacer::RequestSent(Clock::time_point now, size_t frameBytes) {
  if (inFlight_.size() == kMaxRequestsKept) inFlight_.pop_front();
  inFlight_.push_back({now, frameBytes});
}

void FramePacer::AnswerRead(Clock::time_point now) {
  answered_ = true;
  answering_ = true;
  if (inFlight_.empty()) return;  // one given up on (timeout), answered late
  lastRoundTripSeconds_ = std::chrono::duration<double>(now - inFlight_.front().sent).count();
  inFlight_.pop_front();
}

FramePacer::Clock::time_point FramePacer::Deadline() const {
  return inFlight_.front().sent + (answered_ ? kAnswerTimeout : kFirstAnswerTimeout);
}

bool FramePacer::MayDraw(Clock::time_point now) {
  if (inFlight_.empty() || !answering_) return true;
  if (now < Deadline()) return BytesInFlight() < kBytesInFlightBudget;
  // No answer in time: the requests in flight are kept (their answers may
  // still come), and frames are paced without them until one does.
  answering_ = false;
  return true;
}

int FramePacer::WakeMs(Clock::time_point now) const {
  if (inFlight_.empty() || !answering_) return -1;
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(Deadline() - now);
  return static_cast<int>(std::max<long long>(0, left.count()));
}

size_t FramePacer::BytesInFlight() const {
  size_t bytes = 0;
  for (const Request& request : inFlight_) bytes += request.frameBytes;
  return bytes;
}

}  // namespace termshade
