#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <string_view>

namespace termshade {

/// Flow control by the terminal's own answer. After each frame the viewer
/// sends kRequest (primary device attributes, ESC [ c); a terminal answers
/// it in order, once it has read every byte sent before it, so an answer
/// means that frame has reached the screen. A frame may be drawn only while
/// the frames not yet answered for hold less than kBytesInFlightBudget: one
/// big frame at a time, or a few small ones (so a round trip does not cap
/// the frame rate of small frames), whatever the link. Over SSH the backlog
/// would otherwise pile up in sshd's send buffer, seconds of old pictures
/// the viewer never feels. On a fast terminal the answer is back in well
/// under a millisecond.
///
/// A terminal that does not answer (kFirstAnswerTimeout after the first
/// request, before any answer; kAnswerTimeout once it has answered) is paced
/// without answers (Answering() false) until one arrives: the caller then
/// draws once the terminal's output queue is empty. No clock is read here:
/// every call is told the time, so tests drive it.
class FramePacer {
 public:
  using Clock = std::chrono::steady_clock;

  /// The request sent after each frame: DA1, which every terminal answers
  /// (a cursor position report would do too, but its answer ESC [ 1 ; 2 R is
  /// also shift-F3's key sequence in xterm's terminfo: ncurses turns it into
  /// a key).
  static constexpr std::string_view kRequest = "\x1b[c";
  /// Before any answer: a terminal that answers does so within a round trip
  /// of the first request (sent ahead of the first frame's bytes).
  static constexpr std::chrono::milliseconds kFirstAnswerTimeout{1000};
  /// Once answers have come: a request this old is given up as lost.
  static constexpr std::chrono::milliseconds kAnswerTimeout{5000};
  /// Bytes of frames in flight below which another may go: 0.13 s of a
  /// 256 kbit/s link, the most a key may wait behind beyond one frame.
  static constexpr size_t kBytesInFlightBudget = 4096;

  /// A request was sent at `now`, after `frameBytes` bytes of a frame.
  void RequestSent(Clock::time_point now, size_t frameBytes);
  /// An answer was read at `now`: the oldest request's.
  void AnswerRead(Clock::time_point now);
  /// Whether the next frame may go out now: the frames in flight are under
  /// the budget, or the terminal does not answer. Notes a timeout that has passed.
  bool MayDraw(Clock::time_point now);
  /// Milliseconds until a timeout may change MayDraw, or -1 (none pending).
  int WakeMs(Clock::time_point now) const;
  /// The terminal answers (false after a timeout, until the next answer).
  bool Answering() const { return answering_; }
  /// Requests sent and not answered yet.
  size_t RequestsInFlight() const { return inFlight_.size(); }
  /// Bytes of frames sent and not yet answered for.
  size_t BytesInFlight() const;
  /// The last answer's round trip (request sent to answer read), seconds; 0 before one.
  double LastRoundTripSeconds() const { return lastRoundTripSeconds_; }

 private:
  struct Request {
    Clock::time_point sent;
    size_t frameBytes = 0;
  };
  Clock::time_point Deadline() const;

  std::deque<Request> inFlight_;  ///< oldest first
  bool answered_ = false;         ///< an answer has ever come
  bool answering_ = true;         ///< no timeout since the last answer
  double lastRoundTripSeconds_ = 0.0;
};

}  // namespace termshade
