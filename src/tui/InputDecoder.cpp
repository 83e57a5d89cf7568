#include "tui/InputDecoder.h"

namespace termshade {
namespace {

constexpr int kEscape = 27;
constexpr int kBell = 7;
// Digits a number of a report may have (cells and codes are far smaller;
// more is not a report).
constexpr int kMaxDigits = 5;
// Bytes a CSI sequence's parameters may take (xterm's DA1 answer, the
// longest known, has 24: ?64;1;2;6;9;15;16;17;18;21;22;28). An answer
// that is longer is read to its end and dropped.
constexpr size_t kMaxParameterBytes = 64;
// Bytes an OSC or DCS answer may take (an OSC 11 answer has 24) before it is dropped.
constexpr size_t kMaxStringBytes = 256;
// An answer cut short is given up when its rest has not come within this.
constexpr auto kAnswerGapLimit = std::chrono::seconds(1);

InputEvent KeyEvent(int key) {
  InputEvent event;
  event.key = key;
  return event;
}

InputEvent ReplyEvent(TerminalReply reply) {
  InputEvent event;
  event.reply = std::move(reply);
  return event;
}

// The report's kind from xterm's button code: + 32 motion, + 64 wheel, the
// low two bits the button (3: released, in X10).
MouseReport FromCode(int code, int col, int row, bool released) {
  MouseReport report;
  report.col = col;
  report.row = row;
  report.button = code & 3;
  if ((code & 64) != 0) {
    report.kind = (code & 1) != 0 ? MouseReport::Kind::kWheelDown : MouseReport::Kind::kWheelUp;
  } else if ((code & 32) != 0) {
    report.kind = MouseReport::Kind::kMotion;
  } else if (released || report.button == 3) {
    report.kind = MouseReport::Kind::kRelease;
    if (report.button == 3) report.button = 0;
  } else {
    report.kind = MouseReport::Kind::kPress;
  }
  return report;
}

// SGR parameters after '<': code ; col ; row (1-based cells), each 1 to
// kMaxDigits digits.
std::optional<MouseReport> SgrReport(const std::string& parameters, bool released) {
  int numbers[3] = {0, 0, 0};
  int n = 0, digits = 0;
  for (size_t i = 1; i < parameters.size(); ++i) {
    const char c = parameters[i];
    if (c >= '0' && c <= '9' && digits < kMaxDigits) {
      numbers[n] = numbers[n] * 10 + (c - '0');
      ++digits;
    } else if (c == ';' && digits > 0 && n < 2) {
      ++n;
      digits = 0;
    } else {
      return std::nullopt;
    }
  }
  if (n != 2 || digits == 0 || numbers[1] < 1 || numbers[2] < 1) return std::nullopt;
  return FromCode(numbers[0], numbers[1] - 1, numbers[2] - 1, released);
}

// '?', then digits and ';' with at least one digit: a DA1 answer's parameters.
bool DeviceAnswerParameters(const std::string& parameters) {
  bool digit = false;
  for (size_t i = 1; i < parameters.size(); ++i) {
    const char c = parameters[i];
    if (c >= '0' && c <= '9') {
      digit = true;
    } else if (c != ';') {
      return false;
    }
  }
  return digit;
}

}  // namespace

int InputDecoder::Read(bool await) {
  if (!pending_.empty()) {
    const int key = pending_.front();
    pending_.pop_front();
    return key;
  }
  return await ? awaitKey_() : nextKey_();
}

std::optional<InputEvent> InputDecoder::Next() {
  while (ready_.empty()) {
    if (state_ == State::kGround) {
      const int key = Read(false);
      if (key == kNoInput) return std::nullopt;
      Feed(key);
      continue;
    }
    // Inside a sequence: its rest is awaited (once, for one stalled before).
    // An answer waits across calls, never keys; so does any sequence while
    // one is due; a second without a byte ends the wait, unless the
    // start-up answers are expected.
    const int key = Read(!stalled_);
    const bool startup = ExpectingStartupAnswers();
    const bool stale = stalled_ && !startup && now_() - lastByte_ > kAnswerGapLimit;
    if (key == kNoInput && (answer_ || answerDue_ || startup) && !stale) {
      stalled_ = true;
      return std::nullopt;
    }
    if (key == kNoInput || stale) {
      if (key != kNoInput) pending_.push_front(key);  // read again after the sequence
      GiveUp();
      continue;
    }
    stalled_ = false;
    Feed(key);
  }
  InputEvent event = std::move(ready_.front());
  ready_.pop_front();
  return event;
}

void InputDecoder::Feed(int key) {
  lastByte_ = now_();
  if (state_ == State::kGround) {
    if (key != kEscape) {
      Emit(KeyEvent(key));
      return;
    }
    state_ = State::kEscape;
    sequence_.push_back(key);
    return;
  }
  if (state_ == State::kEscape) {
    FeedEscape(key);
    return;
  }
  if (state_ == State::kX10) {
    FeedX10(key);
    return;
  }
  if (state_ == State::kStringEnd) {  // anything but \ after the ESC ends the string
    FeedStringEnd(key);
    return;
  }
  // A control key or a special key (ncurses' codes) typed into a sequence
  // is a key: at once in an answer, after the sequence otherwise.
  const bool control = key > 255 || (key < 32 && key != kEscape);
  if (control && !(key == kBell && state_ == State::kOsc)) {
    if (answer_) {
      Emit(KeyEvent(key));
    } else {
      sequence_.push_back(key);
      held_.push_back(key);
    }
    return;
  }
  if (state_ == State::kCsi) {
    FeedCsi(key);
  } else {
    FeedString(key);
  }
}

// ESC [ begins a CSI sequence, ESC ] an OSC string, ESC P a DCS string;
// anything else makes the ESC a key and is read again.
void InputDecoder::FeedEscape(int key) {
  if (key == '[' || key == ']' || key == 'P') {
    state_ = key == '[' ? State::kCsi : key == ']' ? State::kOsc : State::kDcs;
    sequence_.push_back(key);
    return;
  }
  pending_.push_front(key);
  Finish(KeyEvent(kEscape));
}

// Parameter and intermediate bytes (0x20-0x3F), then a final byte (0x40-0x7E).
void InputDecoder::FeedCsi(int key) {
  if (body_.empty() && held_.empty() && key == 'M') {  // X10 mouse: three raw bytes follow
    state_ = State::kX10;
    sequence_.push_back(key);
    return;
  }
  if (key >= 0x20 && key <= 0x3F) {
    if (body_.empty() && key == '?') BecomeAnswer();
    sequence_.push_back(key);
    if (body_.size() <= kMaxParameterBytes) body_ += static_cast<char>(key);
    if (body_.size() > kMaxParameterBytes && !answer_) GiveBack();
    return;
  }
  if (key >= 0x40 && key <= 0x7E) {
    sequence_.push_back(key);
    FinishCsi(key);
    return;
  }
  // ESC or a byte no sequence has: the sequence ends before it.
  if (answer_) {
    Drop();
    pending_.push_front(key);
  } else {
    sequence_.push_back(key);
    GiveBack();
  }
}

void InputDecoder::FinishCsi(int finalByte) {
  const bool overlong = body_.size() > kMaxParameterBytes;
  if (!body_.empty() && body_[0] == '?') {
    InputEvent event;
    if (finalByte == 'c' && !overlong && DeviceAnswerParameters(body_)) {
      event.deviceAnswer = true;
      startupUntil_.reset();  // answered last: no start-up answer follows
    } else {
      event.reply = TerminalReply{};  // another answer, of no use here
    }
    Finish(std::move(event));
    return;
  }
  if (!body_.empty() && body_[0] == '<' && (finalByte == 'M' || finalByte == 'm')) {
    if (const auto report = SgrReport(body_, finalByte == 'm')) {
      InputEvent event;
      event.mouse = report;
      Finish(std::move(event));
      return;
    }
  }
  if (auto reply = ReplyFromCsi(body_, static_cast<char>(finalByte))) {
    Finish(ReplyEvent(std::move(*reply)));
    return;
  }
  // No key sends ESC [ digits t: a window report of no use, never keys.
  if (finalByte == 't' && !body_.empty() && body_[0] >= '0' && body_[0] <= '9') {
    Drop();
    return;
  }
  GiveBack();
}

// Three bytes: code, col and row, each + 32 (cells 1-based, so col + 33).
void InputDecoder::FeedX10(int key) {
  sequence_.push_back(key);
  if (key < 32 || key > 255) {
    GiveBack();
    return;
  }
  if (sequence_.size() < 6) return;
  const int code = sequence_[3], col = sequence_[4], row = sequence_[5];
  if (col < 33 || row < 33) {
    GiveBack();
    return;
  }
  InputEvent event;
  event.mouse = FromCode(code - 32, col - 33, row - 33, false);
  Finish(std::move(event));
}

// An OSC or DCS string: a digit first makes it an answer, then anything up
// to BEL (OSC only) or ST (ESC \).
void InputDecoder::FeedString(int key) {
  if (!answer_) {
    if (key < '0' || key > '9') {
      sequence_.push_back(key);
      GiveBack();
      return;
    }
    BecomeAnswer();
  }
  if (key == kBell) {
    Finish(ReplyEvent(StringReply()));
    return;
  }
  if (key == kEscape) {
    state_ = State::kStringEnd;
    return;
  }
  // Past the longest answer asked for: read to its end, of no use (never keys).
  if (body_.size() > kMaxStringBytes) return;
  body_ += static_cast<char>(key);
}

TerminalReply InputDecoder::StringReply() const {
  if (body_.size() > kMaxStringBytes) return TerminalReply{};
  return sequence_[1] == ']' ? ReplyFromOsc(body_) : ReplyFromDcs(body_);
}

void InputDecoder::FeedStringEnd(int key) {
  if (key == '\\') {
    Finish(ReplyEvent(StringReply()));
    return;
  }
  // ESC and something else: the string ends unfinished; both are read again.
  Drop();
  pending_.push_front(key);
  pending_.push_front(kEscape);
}

// No key sends what has come so far: the sequence is an answer. Control keys
// held until now come out.
void InputDecoder::BecomeAnswer() {
  answer_ = true;
  for (const int key : held_) Emit(KeyEvent(key));
  held_.clear();
}

// A whole sequence: its event, then the control keys typed into it.
void InputDecoder::Finish(InputEvent event) {
  Emit(std::move(event));
  for (const int key : held_) Emit(KeyEvent(key));
  state_ = State::kGround;
  sequence_.clear();
  body_.clear();
  held_.clear();
  answer_ = false;
  stalled_ = false;
}

// Not a report or answer: ESC is a key, and what followed is read again.
void InputDecoder::GiveBack() {
  pending_.insert(pending_.begin(), sequence_.begin() + 1, sequence_.end());
  held_.clear();
  Finish(KeyEvent(kEscape));
}

// A sequence whose rest did not come: an answer is dropped, a lone ESC is
// the Esc key, anything else its keys.
void InputDecoder::GiveUp() {
  if (answer_) {
    Drop();
  } else if (state_ == State::kEscape) {
    Finish(KeyEvent(kEscape));
  } else {
    GiveBack();
  }
}

// An answer cut short or too long: read, and of no use.
void InputDecoder::Drop() {
  Finish(ReplyEvent(TerminalReply{}));
}

}  // namespace termshade
