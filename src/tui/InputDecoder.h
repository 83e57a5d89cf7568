#pragma once

#include <deque>
#include <functional>
#include <optional>

namespace termshade {

/// The value a key source returns when no input is waiting (ncurses' ERR).
constexpr int kNoInput = -1;

/// One mouse report as the terminal sent it: xterm's SGR (1006) encoding,
/// ESC [ < code ; col ; row M|m, or the older X10 one, ESC [ M code col row
/// (each byte + 32). Cells are 0-based.
struct MouseReport {
  enum class Kind { kPress, kRelease, kMotion, kWheelUp, kWheelDown };
  Kind kind = Kind::kPress;
  int button = 0;  ///< 0 left, 1 middle, 2 right (X10 releases do not say: 0)
  int col = 0;
  int row = 0;
};

/// A key (ncurses key code), a mouse report, or the terminal's answer to a
/// primary device attributes request (DA1, ESC [ c): ESC [ ? digits and ; c.
/// A terminal answers in order, once it has read every byte sent before the
/// request, so the answer says a frame has reached the screen (FramePacer).
struct InputEvent {
  int key = kNoInput;
  std::optional<MouseReport> mouse;
  bool deviceAnswer = false;  ///< a DA1 answer (key kNoInput, no mouse)
};

/// Turns the keys ncurses passes on into keys, mouse reports and DA1
/// answers. The viewer
/// decodes mouse reports itself: ncurses queues a burst of reports (press,
/// motion and release read at once, as over SSH or while a frame is drawn)
/// but hands out only the last, so a drag whose press came in one burst with
/// its release never started. Anything that is not a whole report comes out
/// as the keys it was, in order.
class InputDecoder {
 public:
  /// nextKey: the next key or kNoInput at once; awaitKey: the same, waiting
  /// a little for one (the rest of a report that has begun).
  InputDecoder(std::function<int()> nextKey, std::function<int()> awaitKey)
      : nextKey_(std::move(nextKey)), awaitKey_(std::move(awaitKey)) {}
  /// The next key or report; nullopt when no input is waiting.
  std::optional<InputEvent> Next();

 private:
  int Read(bool await = false);
  std::optional<MouseReport> SgrReport(std::deque<int>& consumed);
  std::optional<MouseReport> X10Report(std::deque<int>& consumed);
  bool DeviceAnswer(std::deque<int>& consumed);

  std::function<int()> nextKey_;
  std::function<int()> awaitKey_;
  std::deque<int> pending_;  ///< keys read ahead and given back
};

}  // namespace termshade
