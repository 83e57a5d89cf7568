#pragma once

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "geometry/HugePages.h"
#include "geometry/LoadThreads.h"

namespace termshade {

inline constexpr uint64_t kSeedMultiplier = 0x9E3779B97F4A7C15ULL;

/// Hash of a key of KeyBytes bytes (a multiple of 4): 64-bit words mixed
/// with a multiply and finished with murmur3's fmix64; seed varies the hash.
template <size_t KeyBytes>
uint64_t HashKeyBytes(const char* key, uint64_t seed) {
  static_assert(KeyBytes % 4 == 0);
  uint64_t h = seed;
  size_t at = 0;
  for (; at + 8 <= KeyBytes; at += 8) {
    uint64_t word;
    std::memcpy(&word, key + at, 8);
    h = (h ^ word) * 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 31;
  }
  if constexpr (KeyBytes % 8 != 0) {
    uint32_t word;
    std::memcpy(&word, key + at, 4);
    h = (h ^ word) * 0xBF58476D1CE4E5B9ULL;
  }
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDULL;
  h ^= h >> 33;
  h *= 0xC4CEB9FE1A85EC53ULL;
  return h ^ (h >> 33);
}

/// For each of count keys (KeyBytes bytes, the i-th at keyAt(i)), writes to
/// first[i] the index of the first key with the same bytes (first[i] <= i;
/// first[i] == i for a key's first occurrence). Bitwise equality, like
/// meshopt_generateVertexRemap, whose numbering this gives. Runs on every
/// core: each thread owns the keys whose hash falls in its share of one
/// open-addressing table, so the result does not depend on the threads; a
/// share that fills up (hashes crafted to collide) makes one thread redo
/// the whole, which cannot fill up. The hash is seeded per call, so an input
/// cannot be crafted to make every key probe the same slots; the result does
/// not depend on the seed. count must be below 2^32 - 1. threads: 0 for
/// LoadThreadCount's choice (rounded down to a power of two, as every count
/// given is).
template <size_t KeyBytes, typename KeyAt>
void FindFirstOccurrences(size_t count, KeyAt keyAt, uint32_t* first, unsigned threadCount = 0) {
  constexpr uint32_t kEmpty = UINT32_MAX;
  if (count == 0) return;
  // Step 1: a table of at least 1.25 x count slots, a power of two.
  const size_t slots = std::bit_ceil(count + count / 4 + 2);
  std::unique_ptr<uint32_t[]> table(new uint32_t[slots]);
  AdviseHugePages(table.get(), slots * sizeof(uint32_t));
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  const uint64_t seed =
      (reinterpret_cast<uintptr_t>(table.get()) ^ static_cast<uint64_t>(now)) * kSeedMultiplier;

  // Step 2: each part of the table filled by its own thread.
  const auto fill = [&](int part, int parts) {
    const size_t partSlots = slots / static_cast<size_t>(parts);
    uint32_t* partTable = table.get() + static_cast<size_t>(part) * partSlots;
    std::fill(partTable, partTable + partSlots, kEmpty);
    size_t stored = 0;
    constexpr size_t kBatch = 32;  // hashes computed and their slots prefetched ahead
    uint64_t hashes[kBatch];
    for (size_t begin = 0; begin < count; begin += kBatch) {
      const size_t end = std::min(count, begin + kBatch);
      for (size_t i = begin; i < end; ++i) {
        const uint64_t h = HashKeyBytes<KeyBytes>(keyAt(i), seed);
        hashes[i - begin] = h;
        if (static_cast<int>((h >> 32) * static_cast<uint64_t>(parts) >> 32) == part) {
          __builtin_prefetch(partTable + (h & (partSlots - 1)));
        }
      }
      for (size_t i = begin; i < end; ++i) {
        const uint64_t h = hashes[i - begin];
        if (static_cast<int>((h >> 32) * static_cast<uint64_t>(parts) >> 32) != part) continue;
        const char* key = keyAt(i);
        size_t slot = h & (partSlots - 1);
        while (true) {
          const uint32_t held = partTable[slot];
          if (held == kEmpty) {
            if (++stored >= partSlots) return false;  // full: a crafted input
            partTable[slot] = static_cast<uint32_t>(i);
            first[i] = static_cast<uint32_t>(i);
            break;
          }
          if (std::memcmp(keyAt(held), key, KeyBytes) == 0) {
            first[i] = held;
            break;
          }
          slot = (slot + 1) & (partSlots - 1);
        }
      }
    }
    return true;
  };
  if (threadCount == 0) threadCount = static_cast<unsigned>(LoadThreadCount(count));
  int threads = static_cast<int>(std::bit_floor(std::min(threadCount, 64U)));
  while (threads > 1 && slots / static_cast<size_t>(threads) < 64) threads /= 2;
  if (threads > 1) {
    std::vector<uint8_t> done(static_cast<size_t>(threads), 0);
    RunOnLoadThreads(threads,
                     [&](int part) { done[static_cast<size_t>(part)] = fill(part, threads); });
    if (std::all_of(done.begin(), done.end(), [](uint8_t d) { return d != 0; })) return;
  }
  fill(0, 1);
}

}  // namespace termshade
