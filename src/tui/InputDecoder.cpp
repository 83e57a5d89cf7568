#include "tui/InputDecoder.h"

namespace termshade {
namespace {

constexpr int kEscape = 27;
// Digits a number of a report may have (cells and codes are far smaller;
// more is not a report).
constexpr int kMaxDigits = 5;
// Bytes a DA1 answer's parameters may take (xterm's, the longest known, has 24:
// 64;1;2;6;9;15;16;17;18;21;22;28).
constexpr int kMaxAnswerBytes = 64;

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
  const int key = Read();
  if (key == kNoInput) return std::nullopt;
  if (key != kEscape) return InputEvent{key, std::nullopt, false};
  // ESC [ < ... (SGR), ESC [ M ... (X10) or ESC [ ? ... c (a DA1 answer);
  // else the keys as they came.
  std::deque<int> consumed;
  auto give = [&](int k) {
    consumed.push_back(k);
    return k;
  };
  std::optional<MouseReport> report;
  if (give(Read()) == '[') {
    const int kind = give(Read(true));
    if (kind == '<') report = SgrReport(consumed);
    if (kind == 'M') report = X10Report(consumed);
    if (kind == '?' && DeviceAnswer(consumed)) return InputEvent{kNoInput, std::nullopt, true};
  }
  if (report) return InputEvent{kNoInput, report, false};
  // Not a report: ESC alone, and what followed read again (kNoInput dropped).
  for (auto it = consumed.rbegin(); it != consumed.rend(); ++it) {
    if (*it != kNoInput) pending_.push_front(*it);
  }
  return InputEvent{kEscape, std::nullopt, false};
}

// code ; col ; row then M (press, motion) or m (release); 1-based cells.
std::optional<MouseReport> InputDecoder::SgrReport(std::deque<int>& consumed) {
  int numbers[3] = {0, 0, 0};
  for (int n = 0; n < 3; ++n) {
    int digits = 0;
    for (;;) {
      const int key = Read(true);
      consumed.push_back(key);
      if (key >= '0' && key <= '9' && digits < kMaxDigits) {
        numbers[n] = numbers[n] * 10 + (key - '0');
        ++digits;
        continue;
      }
      if (digits == 0) return std::nullopt;
      if (n < 2 && key == ';') break;
      if (n == 2 && (key == 'M' || key == 'm')) {
        if (numbers[1] < 1 || numbers[2] < 1) return std::nullopt;
        return FromCode(numbers[0], numbers[1] - 1, numbers[2] - 1, key == 'm');
      }
      return std::nullopt;
    }
  }
  return std::nullopt;
}

// Three bytes: code, col and row, each + 32 (cells 1-based, so col + 33).
std::optional<MouseReport> InputDecoder::X10Report(std::deque<int>& consumed) {
  int bytes[3] = {0, 0, 0};
  for (int& byte : bytes) {
    byte = Read(true);
    consumed.push_back(byte);
    if (byte < 32 || byte > 255) return std::nullopt;
  }
  if (bytes[1] < 33 || bytes[2] < 33) return std::nullopt;
  return FromCode(bytes[0] - 32, bytes[1] - 33, bytes[2] - 33, false);
}

// Parameters (digits and ';', at least one digit) then c. No key sends
// ESC [ ?, so the rest is waited for as a report's is.
bool InputDecoder::DeviceAnswer(std::deque<int>& consumed) {
  bool digit = false;
  for (int length = 0; length <= kMaxAnswerBytes; ++length) {
    const int key = Read(true);
    consumed.push_back(key);
    if (key >= '0' && key <= '9') {
      digit = true;
    } else if (key == 'c') {
      return digit;
    } else if (key != ';') {
      return false;
    }
  }
  return false;
}

}  // namespace termshade
