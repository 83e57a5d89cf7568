#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "tui/InputDecoder.h"

namespace termshade {
namespace {

// Every event decoded from `bytes` (all available at once, as in a burst);
// `insideAnswer`: whether the bytes end inside an answer.
std::vector<InputEvent> Decode(const std::string& bytes, bool* insideAnswer = nullptr) {
  std::deque<int> keys(bytes.begin(), bytes.end());
  for (int& key : keys) key &= 0xFF;
  auto next = [&keys] {
    if (keys.empty()) return kNoInput;
    const int key = keys.front();
    keys.pop_front();
    return key;
  };
  InputDecoder decoder(next, next);
  std::vector<InputEvent> events;
  for (auto event = decoder.Next(); event; event = decoder.Next()) events.push_back(*event);
  if (insideAnswer != nullptr) *insideAnswer = decoder.InsideAnswer();
  return events;
}

using Kind = MouseReport::Kind;

void ExpectReport(const InputEvent& event, Kind kind, int col, int row) {
  ASSERT_TRUE(event.mouse.has_value());
  EXPECT_EQ(event.mouse->kind, kind);
  EXPECT_EQ(event.mouse->col, col);
  EXPECT_EQ(event.mouse->row, row);
}

TEST(InputDecoder, ABurstOfSgrReportsGivesEveryReportInOrder) {
  const auto events = Decode("\x1b[<0;41;13M\x1b[<32;46;13M\x1b[<0;51;15m");
  ASSERT_EQ(events.size(), 3U);
  ExpectReport(events[0], Kind::kPress, 40, 12);
  ExpectReport(events[1], Kind::kMotion, 45, 12);
  ExpectReport(events[2], Kind::kRelease, 50, 14);
}

TEST(InputDecoder, X10ReportsAndTheWheel) {
  const auto events =
      Decode(std::string("\x1b[M") + char(32) + char(33 + 40) + char(33 + 12) + "\x1b[M" +
             char(32 + 3) + char(33 + 50) + char(33 + 14) + "\x1b[<64;3;4M\x1b[<65;3;4M");
  ASSERT_EQ(events.size(), 4U);
  ExpectReport(events[0], Kind::kPress, 40, 12);
  ExpectReport(events[1], Kind::kRelease, 50, 14);
  ExpectReport(events[2], Kind::kWheelUp, 2, 3);
  ExpectReport(events[3], Kind::kWheelDown, 2, 3);
}

TEST(InputDecoder, KeysAroundReportsStayKeysInOrder) {
  const auto events = Decode("a\x1b[<0;2;3Mq");
  ASSERT_EQ(events.size(), 3U);
  EXPECT_EQ(events[0].key, 'a');
  ExpectReport(events[1], Kind::kPress, 1, 2);
  EXPECT_EQ(events[2].key, 'q');
}

TEST(InputDecoder, WhatIsNotAWholeReportComesOutAsItsKeys) {
  for (const std::string bytes :
       {"\x1b", "\x1bx", "\x1b[", "\x1b[<", "\x1b[<0;41", "\x1b[<0;41;13X", "\x1b[<;1;1M",
        "\x1b[<0;0;5M", "\x1b[<1234567;1;1M", "\x1b[M !", "\x1b[A"}) {
    const auto events = Decode(bytes);
    ASSERT_EQ(events.size(), bytes.size()) << "bytes of " << bytes.substr(1);
    for (size_t i = 0; i < bytes.size(); ++i) {
      EXPECT_FALSE(events[i].mouse.has_value()) << bytes.substr(1);
      EXPECT_EQ(events[i].key, static_cast<unsigned char>(bytes[i])) << bytes.substr(1);
    }
  }
}

TEST(InputDecoder, DeviceAttributeAnswersAmongKeysAndReports) {
  // tmux's, xterm's and the Linux console's answers, a key, a report.
  const auto events =
      Decode("\x1b[?1;2cx\x1b[?64;1;2;6;9;15;16;17;18;21;22;28c\x1b[<0;2;3M\x1b[?6c\x1b[?62;c");
  ASSERT_EQ(events.size(), 6U);
  EXPECT_TRUE(events[0].deviceAnswer);
  EXPECT_FALSE(events[1].deviceAnswer);
  EXPECT_EQ(events[1].key, 'x');
  EXPECT_TRUE(events[2].deviceAnswer);
  ExpectReport(events[3], Kind::kPress, 1, 2);
  EXPECT_TRUE(events[4].deviceAnswer);
  EXPECT_TRUE(events[5].deviceAnswer);
  for (const InputEvent& event : events) {
    if (event.deviceAnswer) {
      EXPECT_EQ(event.key, kNoInput);
      EXPECT_FALSE(event.mouse.has_value());
    }
  }
}

TEST(InputDecoder, WhatBeginsAsAnAnswerNeverComesOutAsKeys) {
  // No digit, another final byte, too long: answers of no use, no keys.
  for (const std::string& bytes :
       std::vector<std::string>{"\x1b[?c", "\x1b[?1;2R", "\x1b[?" + std::string(70, '1') + "c"}) {
    const auto events = Decode(bytes);
    ASSERT_EQ(events.size(), 1U) << "bytes of " << bytes.substr(1);
    EXPECT_FALSE(events[0].deviceAnswer) << bytes.substr(1);
    EXPECT_EQ(events[0].key, kNoInput) << bytes.substr(1);
    ASSERT_TRUE(events[0].reply.has_value()) << bytes.substr(1);
    EXPECT_EQ(events[0].reply->kind, TerminalReply::Kind::kOther);
  }
  // Cut short, it waits for its rest.
  EXPECT_TRUE(Decode("\x1b[?1;2").empty());
  // A CSI sequence no key sends less than ESC [ ? stays keys.
  const std::string bytes = "\x1b[c";
  const auto events = Decode(bytes);
  ASSERT_EQ(events.size(), bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) EXPECT_EQ(events[i].key, bytes[i]);
}

TEST(InputDecoder, AnAnswerSplitBetweenReadsIsAwaited) {
  // The rest of an answer comes a little later (the await function has it).
  std::deque<int> now{27, '[', '?'};
  std::deque<int> later{'1', ';', '2', 'c', 'q'};
  auto next = [&now] {
    if (now.empty()) return kNoInput;
    const int key = now.front();
    now.pop_front();
    return key;
  };
  auto await = [&] {
    if (!now.empty()) return next();
    if (later.empty()) return kNoInput;
    const int key = later.front();
    later.pop_front();
    return key;
  };
  InputDecoder decoder(next, await);
  const auto first = decoder.Next();
  ASSERT_TRUE(first.has_value());
  EXPECT_TRUE(first->deviceAnswer);
  // The q came with the answer's rest; it is a key, read next.
  now.push_back(later.front());
  later.pop_front();
  const auto second = decoder.Next();
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->key, 'q');
}

// A terminal's bytes with gaps: kGap is a moment nothing waits, neither
// at once nor within the await (the rest comes later, under load). Every
// event decoded, Next() called again after each gap as the event loop does.
constexpr int kGap = -2;
struct GappedDecode {
  std::vector<InputEvent> events;
  bool insideAnswer = false;
};
GappedDecode DecodeWithGaps(const std::vector<int>& script, bool answerDue = true) {
  std::deque<int> keys(script.begin(), script.end());
  auto next = [&keys] {
    if (keys.empty()) return kNoInput;
    const int key = keys.front();
    keys.pop_front();
    return key == kGap ? kNoInput : key;
  };
  InputDecoder decoder(next, next);
  decoder.SetAnswerDue(answerDue);
  GappedDecode out;
  while (true) {
    for (auto event = decoder.Next(); event; event = decoder.Next()) out.events.push_back(*event);
    if (keys.empty()) break;
  }
  out.insideAnswer = decoder.InsideAnswer();
  return out;
}

std::vector<int> Bytes(const std::string& text) {
  std::vector<int> out;
  for (const char c : text) out.push_back(static_cast<unsigned char>(c));
  return out;
}

std::vector<int> WithGaps(const std::string& text) {
  std::vector<int> out;
  for (const int byte : Bytes(text)) {
    out.push_back(byte);
    out.push_back(kGap);
    out.push_back(kGap);
  }
  return out;
}

TEST(InputDecoder, AnAnswerArrivingByteByByteWithGapsIsOneAnswer) {
  const GappedDecode decoded = DecodeWithGaps(WithGaps("\x1b[?62;22c"));
  ASSERT_EQ(decoded.events.size(), 1U);
  EXPECT_TRUE(decoded.events[0].deviceAnswer);
  EXPECT_FALSE(decoded.insideAnswer);
}

TEST(InputDecoder, ACtrlCTypedIntoAnAnswerIsAKeyAndTheAnswerStaysWhole) {
  // 0x03 after the '?' (the answer known): out at once; before it: after the answer.
  for (const std::string& bytes : {std::string("\x1b[?62\x03;22c"), std::string("\x1b[\x03?62;22c"),
                                   std::string("\x1b[?\x03")}) {
    std::vector<int> script = WithGaps(bytes);
    for (const int byte : Bytes(bytes.back() == '\x03' ? "62;22cq" : "q")) script.push_back(byte);
    const GappedDecode decoded = DecodeWithGaps(script);
    ASSERT_EQ(decoded.events.size(), 3U) << bytes.substr(1);
    EXPECT_EQ(decoded.events[0].key, 3) << bytes.substr(1);
    EXPECT_TRUE(decoded.events[1].deviceAnswer) << bytes.substr(1);
    EXPECT_EQ(decoded.events[2].key, 'q') << bytes.substr(1);
  }
}

TEST(InputDecoder, AnEscFollowedByNothingIsAKeyAndAStaleAnswerIsDropped) {
  // No answer due: a lone Esc, then keys.
  GappedDecode decoded = DecodeWithGaps({27, kGap, kGap, '[', 'x'}, false);
  ASSERT_EQ(decoded.events.size(), 3U);
  EXPECT_EQ(decoded.events[0].key, 27);
  EXPECT_EQ(decoded.events[1].key, '[');
  // One due: the Esc waits for what follows; a key after it makes it a key.
  decoded = DecodeWithGaps({27, kGap, kGap, 'x'});
  ASSERT_EQ(decoded.events.size(), 2U);
  EXPECT_EQ(decoded.events[0].key, 27);
  EXPECT_EQ(decoded.events[1].key, 'x');
  // An answer whose rest never comes: dropped once the next byte comes over
  // a second later, and that byte is a key.
  InputDecoder::Clock::time_point clock{};
  std::vector<int> script = Bytes("\x1b[?6");
  script.push_back(kGap);
  script.push_back(kGap);
  script.push_back(-3);  // the clock jumps 2 s
  script.push_back('q');
  std::deque<int> keys(script.begin(), script.end());
  auto next = [&] {
    if (keys.empty()) return kNoInput;
    const int key = keys.front();
    keys.pop_front();
    if (key == -3) {
      clock += std::chrono::seconds(2);
      return kNoInput;
    }
    return key == kGap ? kNoInput : key;
  };
  InputDecoder decoder(next, next, [&clock] { return clock; });
  std::vector<InputEvent> events;
  while (!keys.empty()) {
    for (auto event = decoder.Next(); event; event = decoder.Next()) events.push_back(*event);
  }
  ASSERT_EQ(events.size(), 2U);
  ASSERT_TRUE(events[0].reply.has_value());
  EXPECT_EQ(events[0].reply->kind, TerminalReply::Kind::kOther);
  EXPECT_EQ(events[1].key, 'q');
  // An Esc while an answer is due, and no byte after it: a key once a second has passed.
  keys = {27, kGap, kGap};
  decoder.SetAnswerDue(true);
  EXPECT_FALSE(decoder.Next().has_value());
  EXPECT_FALSE(decoder.Next().has_value());
  EXPECT_TRUE(decoder.WaitsForRest());
  clock += std::chrono::milliseconds(500);
  EXPECT_FALSE(decoder.Next().has_value());
  clock += std::chrono::milliseconds(600);
  const auto esc = decoder.Next();
  ASSERT_TRUE(esc.has_value());
  EXPECT_EQ(esc->key, 27);
  EXPECT_FALSE(decoder.WaitsForRest());
}

TEST(InputDecoder, TheStartUpQueriesAnswersAreDecoded) {
  const auto events = Decode(
      "\x1b]11;rgb:ffff/ffff/f0f0\x1b\\"  // OSC 11, ST
      "\x1b]11;rgb:0/8/f\x07"             // 1 hex digit a channel, BEL
      "\x1bP1+r524742=382f382f38\x1b\\"   // XTGETTCAP RGB: has it
      "\x1bP0+r5463\x1b\\"                // Tc: does not
      "\x1bP1$r0m\x1b\\"                  // a DECRQSS answer: of no use
      "\x1b[6;17;8t"                      // the cell, 17 by 8 pixels
      "\x1b[?62;22c");
  ASSERT_EQ(events.size(), 7U);
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(events[i].reply.has_value()) << i;
  using ReplyKind = TerminalReply::Kind;
  EXPECT_EQ(events[0].reply->kind, ReplyKind::kBackgroundColour);
  EXPECT_DOUBLE_EQ(events[0].reply->red, 1.0);
  EXPECT_NEAR(events[0].reply->blue, 0xf0f0 / 65535.0, 1e-9);
  EXPECT_EQ(events[1].reply->kind, ReplyKind::kBackgroundColour);
  EXPECT_DOUBLE_EQ(events[1].reply->red, 0.0);
  EXPECT_NEAR(events[1].reply->green, 8 / 15.0, 1e-9);
  EXPECT_DOUBLE_EQ(events[1].reply->blue, 1.0);
  EXPECT_EQ(events[2].reply->kind, ReplyKind::kCapability);
  EXPECT_EQ(events[2].reply->capability, "RGB");
  EXPECT_TRUE(events[2].reply->hasCapability);
  EXPECT_EQ(events[3].reply->capability, "Tc");
  EXPECT_FALSE(events[3].reply->hasCapability);
  EXPECT_EQ(events[4].reply->kind, ReplyKind::kOther);
  EXPECT_EQ(events[5].reply->kind, ReplyKind::kCellSize);
  EXPECT_EQ(events[5].reply->cellWidthPx, 8);
  EXPECT_EQ(events[5].reply->cellHeightPx, 17);
  EXPECT_TRUE(events[6].deviceAnswer);
}

TEST(InputDecoder, AnswersSplitWithGapsAndBadOnesNeverBecomeKeys) {
  const GappedDecode decoded =
      DecodeWithGaps(WithGaps("\x1b]11;rgb:1/2/3\x1b\\\x1bP1+r5463\x1b\\\x1b]11;rgb:xyz\x07"));
  ASSERT_EQ(decoded.events.size(), 3U);
  EXPECT_EQ(decoded.events[0].reply->kind, TerminalReply::Kind::kBackgroundColour);
  EXPECT_EQ(decoded.events[1].reply->kind, TerminalReply::Kind::kCapability);
  EXPECT_EQ(decoded.events[2].reply->kind, TerminalReply::Kind::kOther);
  // A string's ESC followed by a control key (input_fuzzer's finding): the
  // string ends there, and ESC and the key come out in the order sent.
  const auto cut = Decode("\x1b]1;r\x1b\x01q");
  ASSERT_EQ(cut.size(), 4U);
  EXPECT_TRUE(cut[0].reply.has_value());
  EXPECT_EQ(cut[1].key, 27);
  EXPECT_EQ(cut[2].key, 1);
  EXPECT_EQ(cut[3].key, 'q');
  // Alt-] and Alt-P followed by a letter stay keys.
  for (const std::string& bytes : {std::string("\x1b]x"), std::string("\x1bPq")}) {
    const auto events = Decode(bytes);
    ASSERT_EQ(events.size(), bytes.size()) << bytes.substr(1);
    for (size_t i = 0; i < bytes.size(); ++i) EXPECT_EQ(events[i].key, bytes[i]) << bytes.substr(1);
  }
  // No key sends CSI digits t: a window report that is no cell size is an
  // answer of no use, never keys (t, digits and ; are viewer keys).
  const auto window = Decode("\x1b[8;24;80tq");
  ASSERT_EQ(window.size(), 2U);
  ASSERT_TRUE(window[0].reply.has_value());
  EXPECT_EQ(window[0].reply->kind, TerminalReply::Kind::kOther);
  EXPECT_EQ(window[1].key, 'q');
}

// A terminal's bytes against a clock: kGap is a moment nothing waits (as in
// DecodeWithGaps), kLongGap one that lasts 1.2 s (past the second an answer
// cut short is otherwise waited for). Next() called after each, as the
// event loop does; no answer due (the frame pacer gave up on the terminal).
constexpr int kLongGap = -3;
struct ClockedDecoder {
  std::deque<int> keys;
  InputDecoder::Clock::time_point clock{};
  InputDecoder decoder{[this] { return Take(); }, [this] { return Take(); },
                       [this] { return clock; }};
  int Take() {
    if (keys.empty()) return kNoInput;
    const int key = keys.front();
    keys.pop_front();
    if (key == kLongGap) clock += std::chrono::milliseconds(1200);
    return key < 0 ? kNoInput : key;
  }
  std::vector<InputEvent> Run(const std::vector<int>& script) {
    keys.insert(keys.end(), script.begin(), script.end());
    std::vector<InputEvent> events;
    do {
      for (auto event = decoder.Next(); event; event = decoder.Next()) events.push_back(*event);
    } while (!keys.empty());
    return events;
  }
};

TEST(InputDecoder, StartUpAnswersLateAndSplitWithLongGapsNeverBecomeKeys) {
  ClockedDecoder terminal;
  terminal.decoder.ExpectStartupAnswers();
  // Cut after the ESC, inside the OSC and before its ST, inside the DCS, the
  // CSI t and the DA1 answer; 1.2 s between the pieces.
  std::vector<int> script;
  for (const std::string& piece :
       {std::string("\x1b"), std::string("]11;rgb:ffff/ff"), std::string("ff/ffff\x1b"),
        std::string("\\\x1bP1+r5247"), std::string("42\x1b\\\x1b[6;"), std::string("17;8"),
        std::string("t\x1b["), std::string("?62;22cq")}) {
    for (const int byte : Bytes(piece)) script.push_back(byte);
    script.push_back(kGap);
    script.push_back(kLongGap);
  }
  const auto events = terminal.Run(script);
  ASSERT_EQ(events.size(), 5U);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(events[i].reply.has_value()) << i;
  EXPECT_EQ(events[0].reply->kind, TerminalReply::Kind::kBackgroundColour);
  EXPECT_DOUBLE_EQ(events[0].reply->red, 1.0);
  EXPECT_EQ(events[1].reply->capability, "RGB");
  EXPECT_EQ(events[2].reply->kind, TerminalReply::Kind::kCellSize);
  EXPECT_EQ(events[2].reply->cellHeightPx, 17);
  EXPECT_TRUE(events[3].deviceAnswer);
  EXPECT_EQ(events[4].key, 'q');
  // The DA1 answer ends the wait for them: an Esc alone is a key at once.
  EXPECT_FALSE(terminal.decoder.ExpectingStartupAnswers());
  const auto esc = terminal.Run({27, kGap});
  ASSERT_EQ(esc.size(), 1U);
  EXPECT_EQ(esc[0].key, 27);
}

TEST(InputDecoder, TheStartUpAnswersAreExpectedForTenSecondsAtMost) {
  ClockedDecoder terminal;
  terminal.decoder.ExpectStartupAnswers();
  // A piece whose rest never comes waits while the answers are expected...
  std::vector<int> script = Bytes("\x1b[6;");
  for (int i = 0; i < 8; ++i) script.push_back(kLongGap);  // 9.6 s
  EXPECT_TRUE(terminal.Run(script).empty());
  EXPECT_TRUE(terminal.decoder.ExpectingStartupAnswers());
  EXPECT_TRUE(terminal.decoder.WaitsForRest());
  // ...and is given up (here as the keys it was) once they are not.
  const auto events = terminal.Run({kLongGap, kGap});
  EXPECT_FALSE(terminal.decoder.ExpectingStartupAnswers());
  ASSERT_EQ(events.size(), 4U);
  EXPECT_EQ(events[0].key, 27);
  EXPECT_EQ(events[3].key, ';');
}

TEST(InputDecoder, AnAnswerLongerThanAnyAskedForIsReadToItsEndNotKeys) {
  for (const std::string& end : {std::string("\x1b\\"), std::string("\x07")}) {
    const auto events = Decode("\x1b]11;rgb:" + std::string(1000, 'f') + end + "q");
    ASSERT_EQ(events.size(), 2U) << end.size();
    ASSERT_TRUE(events[0].reply.has_value());
    EXPECT_EQ(events[0].reply->kind, TerminalReply::Kind::kOther);  // of no use
    EXPECT_EQ(events[1].key, 'q');
  }
}

// Random bursts of report fragments and stray bytes (as a hostile or broken
// terminal might send): decoding ends, every byte is one key or part of one
// report, and reports' cells are in range.
TEST(InputDecoder, RandomBurstsDecodeEveryByteOnce) {
  const std::vector<std::string> pieces{"\x1b",
                                        "[",
                                        "<",
                                        "M",
                                        "m",
                                        ";",
                                        "0",
                                        "32",
                                        "64",
                                        "99999",
                                        "123456",
                                        "\x1b[<0;41;13M",
                                        "\x1b[M !!",
                                        "q",
                                        "\xff",
                                        std::string(1, '\0'),
                                        "\x1b[?1;2c",
                                        "?",
                                        "c",
                                        "\x03",
                                        "]",
                                        "P",
                                        "\x1b]11;rgb:0/0/0\x07",
                                        "\x1bP1+r524742\x1b\\",
                                        "\x1b[6;16;8t",
                                        "\x07",
                                        "\\"};
  std::mt19937 random(20261203);
  for (int trial = 0; trial < 20000; ++trial) {
    std::string bytes;
    const int count = static_cast<int>(random() % 12);
    for (int i = 0; i < count; ++i) bytes += pieces[random() % pieces.size()];
    bool inside = false;
    const auto events = Decode(bytes, &inside);
    size_t keys = 0, reports = 0, answers = 0, replies = 0;
    for (const InputEvent& event : events) {
      if (event.deviceAnswer) {
        ++answers;
      } else if (event.reply) {
        ++replies;
        EXPECT_EQ(event.key, kNoInput) << trial;
      } else if (event.mouse) {
        ++reports;
        EXPECT_GE(event.mouse->col, 0) << trial;
        EXPECT_GE(event.mouse->row, 0) << trial;
        EXPECT_LT(event.mouse->col, 100000) << trial;
        EXPECT_LT(event.mouse->row, 100000) << trial;
      } else {
        ++keys;
      }
    }
    // A report takes at least 6 bytes (ESC [ M and three), a DA1 answer 5
    // (ESC [ ? 6 c), another 3 (ESC [ ? cut short).
    EXPECT_LE(keys + 6 * reports + 5 * answers + 3 * replies, bytes.size()) << trial;
    if (reports == 0 && answers == 0 && replies == 0 && !inside) {
      EXPECT_EQ(keys, bytes.size()) << trial;
    }
  }
}

}  // namespace
}  // namespace termshade
