#include <gtest/gtest.h>

#include "tui/TerminalQueries.h"

namespace termshade {
namespace {

TEST(TerminalQueries, AnswersDecideBackgroundColourAndCellAspect) {
  TerminalAnswers answers;
  EXPECT_FALSE(answers.background.has_value());  // no answer: nothing said (dark by default)
  TerminalReply white;
  white.kind = TerminalReply::Kind::kBackgroundColour;
  white.red = white.green = white.blue = 1.0;
  TakeReply(white, answers);
  EXPECT_EQ(answers.background, Background::kLight);
  EXPECT_EQ(BackgroundOfColour(0.0, 0.0, 0.0), Background::kDark);
  EXPECT_EQ(BackgroundOfColour(0.16, 0.17, 0.2), Background::kDark);    // Solarized-dark-like
  EXPECT_EQ(BackgroundOfColour(0.99, 0.96, 0.89), Background::kLight);  // Solarized light
  TerminalReply lacks;
  lacks.kind = TerminalReply::Kind::kCapability;
  lacks.capability = "RGB";
  TakeReply(lacks, answers);
  EXPECT_FALSE(answers.directColour);
  TerminalReply has = lacks;
  has.capability = "Tc";
  has.hasCapability = true;
  TakeReply(has, answers);
  EXPECT_TRUE(answers.directColour);
  TerminalReply cell;
  cell.kind = TerminalReply::Kind::kCellSize;
  cell.cellWidthPx = 8;
  cell.cellHeightPx = 17;
  TakeReply(cell, answers);
  EXPECT_DOUBLE_EQ(answers.cellAspect, 17.0 / 8.0);
  cell.cellHeightPx = 80;  // not believed
  TerminalAnswers fresh;
  TakeReply(cell, fresh);
  EXPECT_EQ(fresh.cellAspect, 0.0);
}

TEST(TerminalQueries, TheQueriesAreOscXtgettcapAndCellSize) {
  EXPECT_EQ(kStartupQueries, "\x1b]11;?\x1b\\\x1bP+q524742\x1b\\\x1bP+q5463\x1b\\\x1b[16t");
  EXPECT_LE(kStartupAnswerWaitMs, 100);
}

}  // namespace
}  // namespace termshade
