#pragma once

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>

#include "process/HugePages.h"

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
/// Open-addressing table of key indices (linear probing), grown to twice its
/// slots whenever it is 3/4 full, so its size follows the distinct keys, not
/// all keys: a binary STL's 6 corners a vertex need a sixth of the slots.
template <size_t KeyBytes, typename KeyAt>
class FirstOccurrenceTable {
 public:
  static constexpr uint32_t kEmpty = UINT32_MAX;

  FirstOccurrenceTable(size_t expectedDistinct, KeyAt keyAt) : keyAt_(keyAt) {
    Allocate(std::bit_ceil(std::max<size_t>(64, expectedDistinct + expectedDistinct / 2)));
    const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
    seed_ =
        (reinterpret_cast<uintptr_t>(table_.get()) ^ static_cast<uint64_t>(now)) * kSeedMultiplier;
  }

  uint64_t Hash(const char* key) const { return HashKeyBytes<KeyBytes>(key, seed_); }
  void PrefetchSlot(uint64_t hash) const { __builtin_prefetch(table_.get() + (hash & mask_)); }
  /// The key the hash's first slot holds, or kEmpty.
  uint32_t HeldAt(uint64_t hash) const { return table_[hash & mask_]; }

  /// Frees the table, its pages handed back (HugePages.h); unusable after.
  void ReleasePages() {
    termshade::ReleasePages(table_.get(), (mask_ + 1) * sizeof(uint32_t));
    table_.reset();
  }

  /// The first index whose key equals key i's (hash given); i itself when new.
  uint32_t FindOrInsert(uint32_t i, uint64_t hash) {
    const char* key = keyAt_(i);
    size_t slot = hash & mask_;
    while (true) {
      const uint32_t held = table_[slot];
      if (held == kEmpty) break;
      if (std::memcmp(keyAt_(held), key, KeyBytes) == 0) return held;
      slot = (slot + 1) & mask_;
    }
    table_[slot] = i;
    if (++held_ * 4 >= (mask_ + 1) * 3) Grow();
    return i;
  }

 private:
  void Allocate(size_t slots) {
    table_.reset(new uint32_t[slots]);
    AdviseHugePages(table_.get(), slots * sizeof(uint32_t));
    std::fill(table_.get(), table_.get() + slots, kEmpty);
    mask_ = slots - 1;
  }

  // Twice the slots; every held key inserted again by its hash.
  void Grow() {
    std::unique_ptr<uint32_t[]> old = std::move(table_);
    const size_t oldSlots = mask_ + 1;
    Allocate(oldSlots * 2);
    for (size_t s = 0; s < oldSlots; ++s) {
      const uint32_t held = old[s];
      if (held == kEmpty) continue;
      size_t slot = Hash(keyAt_(held)) & mask_;
      while (table_[slot] != kEmpty) slot = (slot + 1) & mask_;
      table_[slot] = held;
    }
  }

  KeyAt keyAt_;
  std::unique_ptr<uint32_t[]> table_;
  size_t mask_ = 0;
  size_t held_ = 0;
  uint64_t seed_ = 0;
};

/// For each of count keys (KeyBytes bytes, the i-th at keyAt(i)), writes to
/// first[i] the index of the first key with the same bytes (first[i] <= i;
/// first[i] == i for a key's first occurrence). Bitwise equality, like
/// meshopt_generateVertexRemap, whose numbering this gives, about 3 times
/// faster: keys compared in place (no copy), inline, with the table slots and
/// the keys they hold prefetched a batch ahead. The hash is seeded per call,
/// so no input can be crafted to make every key probe the same slots; the
/// result does not depend on the seed. expectedDistinct sizes the table at
/// first (it grows as needed). One thread: split by hash over two
/// threads, each thread's share of the probes took as long as the whole on
/// one (every thread reads and hashes every key), measured on a 2M-triangle
/// STL. count must be below 2^32 - 1.
template <size_t KeyBytes, typename KeyAt>
void FindFirstOccurrences(size_t count, KeyAt keyAt, uint32_t* first, size_t expectedDistinct = 0) {
  if (count == 0) return;
  FirstOccurrenceTable<KeyBytes, KeyAt> table(expectedDistinct == 0 ? count : expectedDistinct,
                                              keyAt);
  constexpr uint32_t kEmpty = FirstOccurrenceTable<KeyBytes, KeyAt>::kEmpty;
  // The keys in order, a batch at a time.
  constexpr size_t kBatch = 32;
  uint64_t hashes[kBatch];
  for (size_t begin = 0; begin < count; begin += kBatch) {
    const size_t end = std::min(count, begin + kBatch);
    // Stage 1: hashes, and the slots they start at fetched.
    for (size_t i = begin; i < end; ++i) {
      hashes[i - begin] = table.Hash(keyAt(i));
      table.PrefetchSlot(hashes[i - begin]);
    }
    // Stage 2: the keys those slots hold fetched, to compare with.
    for (size_t i = begin; i < end; ++i) {
      const uint32_t held = table.HeldAt(hashes[i - begin]);
      if (held != kEmpty) __builtin_prefetch(keyAt(held));
    }
    // Stage 3: linear probing; the table grows before it fills.
    for (size_t i = begin; i < end; ++i) {
      first[i] = table.FindOrInsert(static_cast<uint32_t>(i), hashes[i - begin]);
    }
  }
}

}  // namespace termshade
