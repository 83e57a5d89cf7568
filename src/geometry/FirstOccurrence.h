#pragma once

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>

#include "geometry/HugePages.h"

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
/// meshopt_generateVertexRemap, whose numbering this gives, about 3 times
/// faster: keys compared in place (no copy), inline, with the table slots and
/// the keys they hold prefetched a batch ahead. The hash is seeded per call,
/// so no input can be crafted to make every key probe the same slots; the
/// result does not depend on the seed. One thread: split by hash over two
/// threads, each thread's share of the probes took as long as the whole on
/// one (every thread reads and hashes every key), measured on a 2M-triangle
/// STL. count must be below 2^32 - 1.
template <size_t KeyBytes, typename KeyAt>
void FindFirstOccurrences(size_t count, KeyAt keyAt, uint32_t* first) {
  constexpr uint32_t kEmpty = UINT32_MAX;
  if (count == 0) return;
  // Step 1: a table of at least 1.25 x count slots, a power of two.
  const size_t slots = std::bit_ceil(count + count / 4 + 2);
  std::unique_ptr<uint32_t[]> table(new uint32_t[slots]);
  AdviseHugePages(table.get(), slots * sizeof(uint32_t));
  std::fill(table.get(), table.get() + slots, kEmpty);
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  const uint64_t seed =
      (reinterpret_cast<uintptr_t>(table.get()) ^ static_cast<uint64_t>(now)) * kSeedMultiplier;

  // Step 2: the keys in order, a batch at a time.
  constexpr size_t kBatch = 32;
  uint64_t hashes[kBatch];
  for (size_t begin = 0; begin < count; begin += kBatch) {
    const size_t end = std::min(count, begin + kBatch);
    // Stage 1: hashes, and the slots they start at fetched.
    for (size_t i = begin; i < end; ++i) {
      const uint64_t h = HashKeyBytes<KeyBytes>(keyAt(i), seed);
      hashes[i - begin] = h;
      __builtin_prefetch(table.get() + (h & (slots - 1)));
    }
    // Stage 2: the keys those slots hold fetched, to compare with.
    for (size_t i = begin; i < end; ++i) {
      const uint32_t held = table[hashes[i - begin] & (slots - 1)];
      if (held != kEmpty) __builtin_prefetch(keyAt(held));
    }
    // Stage 3: linear probing; the table never fills (count < slots).
    for (size_t i = begin; i < end; ++i) {
      const char* key = keyAt(i);
      size_t slot = hashes[i - begin] & (slots - 1);
      while (true) {
        const uint32_t held = table[slot];
        if (held == kEmpty) {
          table[slot] = static_cast<uint32_t>(i);
          first[i] = static_cast<uint32_t>(i);
          break;
        }
        if (std::memcmp(keyAt(held), key, KeyBytes) == 0) {
          first[i] = held;
          break;
        }
        slot = (slot + 1) & (slots - 1);
      }
    }
  }
}

}  // namespace termshade
