#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <optional>
#include <string>

#include "tui/TerminalReply.h"

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

/// A key (ncurses key code), a mouse report, the terminal's answer to a
/// primary device attributes request (DA1, ESC [ c): ESC [ ? digits and ; c,
/// or its answer to another query (TerminalReply).
/// A terminal answers in order, once it has read every byte sent before the
/// request, so the answer says a frame has reached the screen (FramePacer).
struct InputEvent {
  int key = kNoInput;
  std::optional<MouseReport> mouse;
  bool deviceAnswer = false;           ///< a DA1 answer (key kNoInput, no mouse)
  std::optional<TerminalReply> reply;  ///< another answer (key kNoInput, no mouse)
};

/// Turns the keys ncurses passes on into keys, mouse reports and the
/// terminal's answers. The viewer decodes mouse reports itself: ncurses
/// queues a burst of reports (press, motion and release read at once, as
/// over SSH or while a frame is drawn) but hands out only the last, so a
/// drag whose press came in one burst with its release never started.
///
/// A sequence no key sends (ESC [ ?, ESC ] digit, ESC P digit, ESC [ digits
/// t) is an answer: its bytes never come out as keys. Cut short, it waits
/// for its rest across calls (a gap under load), until a second passes
/// without a byte; control keys typed into it (Ctrl-C) come out as keys at
/// once. Any other sequence that is not a whole report or answer comes out
/// as the keys it was, in order. A lone Esc is one that nothing follows
/// within the await. While an answer is due (SetAnswerDue) any sequence cut
/// short waits as an answer does (an answer's ESC may arrive alone, its rest
/// later): an Esc is then one that something other than [, ] or P follows,
/// or nothing for a second (a call of Next() after it: WaitsForRest).
/// While the start-up answers are expected (ExpectStartupAnswers, until
/// their DA1 answer or kStartupAnswerLimit) the second does not apply: on a
/// slow link they come late and in pieces, after the frame pacer gave up.
class InputDecoder {
 public:
  using Clock = std::chrono::steady_clock;
  /// nextKey: the next key or kNoInput at once; awaitKey: the same, waiting
  /// a little for one (the rest of a report that has begun); now: the clock.
  InputDecoder(std::function<int()> nextKey, std::function<int()> awaitKey,
               std::function<Clock::time_point()> now = Clock::now)
      : nextKey_(std::move(nextKey)), awaitKey_(std::move(awaitKey)), now_(std::move(now)) {}
  /// The next key, report or answer; nullopt when no input is waiting.
  std::optional<InputEvent> Next();
  /// Whether an answer has begun and waits for its rest.
  bool InsideAnswer() const { return answer_; }
  /// Whether the terminal owes an answer (a request in flight).
  void SetAnswerDue(bool due) { answerDue_ = due; }
  /// The longest the start-up answers are expected after ExpectStartupAnswers().
  static constexpr std::chrono::seconds kStartupAnswerLimit{10};
  /// The start-up queries were sent: until their DA1 answer is read (at most
  /// kStartupAnswerLimit), a sequence cut short waits for its rest however
  /// long the gap.
  void ExpectStartupAnswers() { startupUntil_ = now_() + kStartupAnswerLimit; }
  /// Whether the start-up answers are still expected.
  bool ExpectingStartupAnswers() const { return startupUntil_ && now_() < *startupUntil_; }
  /// Whether a sequence cut short waits for its rest: Next() should be
  /// called again within a second, though no input comes, to give it up.
  bool WaitsForRest() const { return stalled_; }

 private:
  enum class State { kGround, kEscape, kCsi, kX10, kOsc, kDcs, kStringEnd };
  int Read(bool await);
  void Feed(int key);
  void FeedEscape(int key);
  void FeedCsi(int key);
  void FeedX10(int key);
  void FeedString(int key);
  void FeedStringEnd(int key);
  /// The answer an OSC or DCS string gives (none past the longest asked for).
  TerminalReply StringReply() const;
  void BecomeAnswer();
  void FinishCsi(int finalByte);
  void Finish(InputEvent event);
  void GiveBack();
  void GiveUp();
  void Drop();
  void Emit(InputEvent event) { ready_.push_back(std::move(event)); }

  std::function<int()> nextKey_;
  std::function<int()> awaitKey_;
  std::function<Clock::time_point()> now_;
  std::deque<int> pending_;       ///< keys read ahead and given back
  std::deque<InputEvent> ready_;  ///< decoded, not yet handed out
  State state_ = State::kGround;
  std::deque<int> sequence_;  ///< the sequence's keys so far, ESC first (to give back)
  std::string body_;          ///< its parameters or string
  std::deque<int> held_;      ///< control keys typed into a sequence not yet an answer
  bool answer_ = false;       ///< the sequence is an answer: never keys
  bool stalled_ = false;      ///< the last await for its rest found nothing
  bool answerDue_ = false;
  std::optional<Clock::time_point> startupUntil_;  ///< the start-up answers expected until then
  Clock::time_point lastByte_{};
};

}  // namespace termshade
