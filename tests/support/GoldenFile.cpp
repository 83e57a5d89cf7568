#include "support/GoldenFile.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>

#include "io/write/FrameDiff.h"
#include "support/TestSupport.h"

namespace termshade::test {

bool UpdatingGoldens() {
  const char* update = std::getenv("TERMSHADE_UPDATE");
  return std::getenv("TERMSHADE_UPDATE_GOLDEN") != nullptr ||
         (update != nullptr && *update != '\0' && std::strcmp(update, "0") != 0);
}

void ExpectTextGolden(const std::string& path, const std::string& actual) {
  if (UpdatingGoldens()) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  const std::string expected = ReadFile(path);
  if (expected == actual) return;
  const TextFrameDifference difference = CompareTextFrames(expected, actual, false);
  ADD_FAILURE() << "golden frame " << path << ": " << difference.differingCells << " cells differ"
                << (difference.sameShape ? "" : " (rows of other lengths)") << "\n"
                << difference.diff << "(run with TERMSHADE_UPDATE=1 to accept)";
}

}  // namespace termshade::test
