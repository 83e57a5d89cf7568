// libFuzzer target: bytes as keys a terminal sends the viewer, through
// InputDecoder (tui/InputDecoder.h). Byte 0xFE stands for "nothing waiting
// now" (the rest arrives later: a report split between reads); 0xFD 0xNN for
// a key above a byte (ncurses' KEY_ codes, 256 + NN). Decoding must end,
// read all input, give keys in the order given (none invented; none
// dropped when no report or answer was found and none was left unfinished),
// and give mouse reports only of 6 bytes or more, with cells in range, DA1
// answers of 5 or more, other answers of 3 or more.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <vector>

#include "tui/InputDecoder.h"

namespace {

constexpr int kGap = -2;  // "nothing waiting now": nextKey says kNoInput, awaitKey skips it

struct Script {
  std::deque<int> keys;
  size_t realKeys = 0;
};

Script ScriptOf(const uint8_t* data, size_t size) {
  Script script;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0xFE) {
      script.keys.push_back(kGap);
    } else if (data[i] == 0xFD && i + 1 < size) {
      script.keys.push_back(256 + data[++i]);
      ++script.realKeys;
    } else {
      script.keys.push_back(data[i]);
      ++script.realKeys;
    }
  }
  return script;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace termshade;
  Script script = ScriptOf(data, size);
  std::vector<int> given;  // keys handed to the decoder, in order
  auto next = [&] {
    if (script.keys.empty()) return kNoInput;
    const int key = script.keys.front();
    script.keys.pop_front();
    if (key == kGap) return kNoInput;
    given.push_back(key);
    return key;
  };
  auto await = [&] {
    while (!script.keys.empty() && script.keys.front() == kGap) script.keys.pop_front();
    return next();
  };
  InputDecoder decoder(next, await);
  std::vector<int> keys;
  size_t reports = 0;
  size_t answers = 0;
  size_t replies = 0;
  // Every gap may end a Next() with nullopt; the loop ends once the script is read.
  for (size_t rounds = 0; rounds <= size + 1; ++rounds) {
    while (auto event = decoder.Next()) {
      if (event->deviceAnswer) {
        if (event->mouse || event->key != kNoInput) std::abort();
        ++answers;
      } else if (event->reply) {
        if (event->mouse || event->key != kNoInput) std::abort();
        ++replies;
      } else if (event->mouse) {
        ++reports;
        const MouseReport& m = *event->mouse;
        if (m.col < 0 || m.row < 0 || m.col >= 100000 || m.row >= 100000) std::abort();
      } else {
        keys.push_back(event->key);
      }
    }
    if (script.keys.empty()) break;
  }
  if (!script.keys.empty() || given.size() != script.realKeys) std::abort();  // input left unread
  // Keys come out in the order given, a report takes at least 6 keys, an
  // answer 5 (ESC [ ? 6 c), and without either every key comes out.
  size_t at = 0;
  for (const int key : keys) {
    while (at < given.size() && given[at] != key) ++at;
    if (at == given.size()) std::abort();  // a key not given, or out of order
    ++at;
  }
  if (keys.size() + 6 * reports + 5 * answers + 3 * replies > given.size()) std::abort();
  if (reports == 0 && answers == 0 && replies == 0 && !decoder.InsideAnswer() &&
      keys.size() != given.size())
    std::abort();
  return 0;
}
