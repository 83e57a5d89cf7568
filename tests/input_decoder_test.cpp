#include <gtest/gtest.h>

#include <deque>
#include <random>
#include <string>
#include <vector>

#include "tui/InputDecoder.h"

namespace termshade {
namespace {

// Every event decoded from `bytes` (all available at once, as in a burst).
std::vector<InputEvent> Decode(const std::string& bytes) {
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

TEST(InputDecoder, WhatIsNotAWholeAnswerComesOutAsItsKeys) {
  // No digit, a foreign byte, another final byte, cut short, too long.
  for (const std::string& bytes :
       std::vector<std::string>{"\x1b[?c", "\x1b[?1x2c", "\x1b[?1;2R", "\x1b[?1;2", "\x1b[c",
                                "\x1b[?" + std::string(70, '1') + "c"}) {
    const auto events = Decode(bytes);
    ASSERT_EQ(events.size(), bytes.size()) << "bytes of " << bytes.substr(1);
    for (size_t i = 0; i < bytes.size(); ++i) {
      EXPECT_FALSE(events[i].deviceAnswer) << bytes.substr(1);
      EXPECT_EQ(events[i].key, static_cast<unsigned char>(bytes[i])) << bytes.substr(1);
    }
  }
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

// Random bursts of report fragments and stray bytes (as a hostile or broken
// terminal might send): decoding ends, every byte is one key or part of one
// report, and reports' cells are in range.
TEST(InputDecoder, RandomBurstsDecodeEveryByteOnce) {
  const std::vector<std::string> pieces{"\x1b",       "[",     "<",      "M",
                                        "m",          ";",     "0",      "32",
                                        "64",         "99999", "123456", "\x1b[<0;41;13M",
                                        "\x1b[M !!",  "q",     "\xff",   std::string(1, '\0'),
                                        "\x1b[?1;2c", "?",     "c"};
  std::mt19937 random(20261203);
  for (int trial = 0; trial < 20000; ++trial) {
    std::string bytes;
    const int count = static_cast<int>(random() % 12);
    for (int i = 0; i < count; ++i) bytes += pieces[random() % pieces.size()];
    const auto events = Decode(bytes);
    size_t keys = 0, reports = 0, answers = 0;
    for (const InputEvent& event : events) {
      if (event.deviceAnswer) {
        ++answers;
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
    // A report takes at least 6 bytes (ESC [ M and three), an answer 5 (ESC [ ? 6 c).
    EXPECT_LE(keys + 6 * reports + 5 * answers, bytes.size()) << trial;
    if (reports == 0 && answers == 0) {
      EXPECT_EQ(keys, bytes.size()) << trial;
    }
  }
}

}  // namespace
}  // namespace termshade
