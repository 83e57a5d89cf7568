#include "shade/AsciiMatcher.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "shade/GlyphInk.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace termshade {

// ByteKey builds keys by shifts and MatchKey reads them back as bytes.
static_assert(std::endian::native == std::endian::little, "cache keys assume little-endian bytes");

namespace {

constexpr size_t kCacheSize = size_t{1} << 12;
constexpr int kProbes = 8;
// Contrast enhancement (Harri): levels below the cell's brightest are pushed
// down by (level / max)^exponent, sharpening edges inside the cell.
constexpr double kContrastExponent = 1.5;
// A missing glyph's ink in Nearest8's last block: its error (8 x 2000^2)
// beats no real one (at most 8 x 255^2) and cannot overflow 32 bits.
constexpr int16_t kNoGlyphInk = 2000;

// ceil(2^24 / d): (x * kReciprocals[d]) >> 24 is x / d for x < 2^12 and d < 2^8
// (the error x (ceil(2^24/d) - 2^24/d) / 2^24 < x d / 2^24 < 1/d).
constexpr std::array<uint32_t, 256> kReciprocals = [] {
  std::array<uint32_t, 256> table{};
  for (uint32_t d = 1; d < 256; ++d) table[d] = ((uint32_t{1} << 24) + d - 1) / d;
  return table;
}();

uint64_t Mix(uint64_t key) {  // splitmix64's finalizer
  key ^= key >> 30;
  key *= 0xBF58476D1CE4E5B9ULL;
  key ^= key >> 27;
  key *= 0x94D049BB133111EBULL;
  return key ^ (key >> 31);
}

}  // namespace

void AsciiMatcher::Prepare(SampleGrid grid) {
  if (grid == grid_) return;
  grid_ = grid;
  count_ = grid.Count();
  glyphs_.clear();
  vectors_.clear();
  // Step 1: each printable glyph's mean ink over each sample's region of the 8 x 16 map.
  const GlyphInkTable& table = DefaultInkTable();
  for (char32_t c = U'!'; c <= U'~'; ++c) {
    const InkMap* ink = table.Find(c);
    if (ink == nullptr) continue;
    glyphs_.push_back(c);
    for (int n = 0; n < count_; ++n) {
      const int i = n % grid.across, j = n / grid.across;
      const int x0 = i * kInkColumns / grid.across, x1 = (i + 1) * kInkColumns / grid.across;
      const int y0 = j * kInkRows / grid.down, y1 = (j + 1) * kInkRows / grid.down;
      int sum = 0;
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) sum += (*ink)[static_cast<size_t>(y * kInkColumns + x)];
      }
      const int area = std::max(1, (x1 - x0) * (y1 - y0));
      const int mean = (sum + area / 2) / area;
      vectors_.push_back(mean);
    }
  }
  pairedInks_.clear();
  if (count_ == 8) {
    const size_t blocks = (glyphs_.size() + 3) / 4;
    pairedInks_.assign(blocks * 4 * 8, kNoGlyphInk);
    for (size_t g = 0; g < glyphs_.size(); ++g) {
      for (size_t n = 0; n < 8; ++n) {
        const size_t at = ((g / 4) * 4 + n / 2) * 8 + (g % 4) * 2 + n % 2;
        pairedInks_[at] = static_cast<int16_t>(vectors_[g * 8 + n]);
      }
    }
  }
  // The brightest glyph's mean ink: what full intensity maps to (SPEC 12's ink range).
  inkScale_ = 0;
  for (size_t g = 0; g < glyphs_.size(); ++g) {
    int sum = 0;
    for (int n = 0; n < count_; ++n) sum += vectors_[g * static_cast<size_t>(count_) + n];
    inkScale_ = std::max(inkScale_, sum / count_);
  }
  // Step 2: the contrast curve, and an empty cache.
  for (int max = 0; max < kLevels; ++max) {
    for (int level = 0; level < kLevels; ++level) {
      const double ratio = max > 0 ? std::min(1.0, double(level) / max) : 0.0;
      enhanced_[level][max] = static_cast<int>(
          std::lround(255.0 * max / (kLevels - 1) * std::pow(ratio, kContrastExponent)));
    }
  }
  cache_.assign(kCacheSize, Entry{});
  // Step 3: the levels of a value, as tables (a row per brightest value for ShapeLevels).
  for (int value = 0; value < 256; ++value) {
    inkLevels_[value] = static_cast<uint8_t>((value * 15 + 127) / 255);
  }
  if (shapeLevels_.empty()) {
    shapeLevels_.resize(256 * 256);
    for (int brightest = 1; brightest < 256; ++brightest) {
      for (int value = 0; value <= brightest; ++value) {
        const std::array<uint8_t, 2> pair{static_cast<uint8_t>(brightest),
                                          static_cast<uint8_t>(value)};
        shapeLevels_[brightest * 256 + value] = ShapeLevels(pair.data(), 3U, 2)[1];
      }
    }
  }
}

uint64_t AsciiMatcher::ByteKey(const uint8_t* row, const uint8_t* values, uint32_t covered) const {
  uint64_t key = 0;
  const auto add = [&](int n) {
    const uint64_t level = row[values[n]] & (0U - ((covered >> n) & 1U));
    key |= level << (8 * n);
  };
  if (count_ == 8) {
    for (int n = 0; n < 8; ++n) add(n);
  } else {
    for (int n = 0; n < count_; ++n) add(n);
  }
  return key;
}

char32_t AsciiMatcher::MatchInk(const uint8_t* values, uint32_t covered) {
  if (count_ <= 8) return MatchKey(ByteKey(inkLevels_.data(), values, covered), nullptr);
  std::array<uint8_t, 32> levels{};
  for (int n = 0; n < count_; ++n) {
    if ((covered >> n) & 1U) levels[n] = static_cast<uint8_t>((values[n] * 15 + 127) / 255);
  }
  return Match(levels);
}

std::array<uint8_t, 32> AsciiMatcher::ShapeLevels(const uint8_t* values, uint32_t covered,
                                                  int count) {
  int brightest = 1;
  for (int n = 0; n < count; ++n) {
    brightest = std::max<int>(brightest, (covered >> n) & 1U ? values[n] : 0);
  }
  // Divisions as multiplications: values * 15 + brightest / 2 < 2^12.
  const uint64_t reciprocal = kReciprocals[static_cast<size_t>(brightest)];
  std::array<uint8_t, 32> levels{};
  for (int n = 0; n < count; ++n) {
    // Covered samples are at least level 1, so a black face still shows.
    const auto scaled = static_cast<uint64_t>(values[n] * 15 + brightest / 2);
    const auto level = static_cast<uint8_t>(std::max<uint64_t>(1, (scaled * reciprocal) >> 24));
    levels[n] = (covered >> n) & 1U ? level : uint8_t{0};
  }
  return levels;
}

char32_t AsciiMatcher::MatchShape(const uint8_t* values, uint32_t covered) {
  if (count_ <= 8) {  // ShapeLevels by table, the key built in registers
    int brightest = 1;
    for (int n = 0; n < count_; ++n) {
      brightest = std::max<int>(brightest, (covered >> n) & 1U ? values[n] : 0);
    }
    return MatchKey(ByteKey(&shapeLevels_[static_cast<size_t>(brightest) * 256], values, covered),
                    nullptr);
  }
  return Match(ShapeLevels(values, covered, count_));
}

char32_t AsciiMatcher::Match(const std::array<uint8_t, 32>& levels) {
  if (count_ > 16) return Nearest(levels);  // too many samples for a 64-bit key
  // The key: the levels (each below 16) as bytes, the second eight in the high nibbles.
  uint64_t low = 0, high = 0;
  std::memcpy(&low, levels.data(), sizeof low);
  std::memcpy(&high, levels.data() + 8, sizeof high);
  return MatchKey(low | high << 4, &levels);
}

char32_t AsciiMatcher::MatchKey(uint64_t key, const std::array<uint8_t, 32>* levels) {
  const auto nearest = [&] {
    if (levels != nullptr) return Nearest(*levels);
    std::array<uint8_t, 32> bytes{};  // up to 8 samples: the key's bytes
    std::memcpy(bytes.data(), &key, sizeof key);
    return count_ == 8 ? Nearest8(bytes) : Nearest(bytes);
  };
  const size_t home = Mix(key) & (kCacheSize - 1);
  for (int probe = 0; probe < kProbes; ++probe) {
    Entry& entry = cache_[(home + probe) & (kCacheSize - 1)];
    if (entry.glyph != 0 && entry.key == key) return entry.glyph;
    if (entry.glyph == 0) {
      entry = {key, nearest()};
      return entry.glyph;
    }
  }
  Entry& entry = cache_[home];  // full: replace the home slot
  entry = {key, nearest()};
  return entry.glyph;
}

std::array<int, 32> AsciiMatcher::TargetInk(const std::array<uint8_t, 32>& levels) const {
  // Enhanced brightness scaled to the most ink any glyph has there.
  int maxLevel = 0;
  for (int n = 0; n < count_; ++n) maxLevel = std::max<int>(maxLevel, levels[n]);
  std::array<int, 32> target{};
  for (int n = 0; n < count_; ++n) {
    target[n] = enhanced_[levels[n]][maxLevel] * inkScale_ / 255;
  }
  return target;
}

char32_t AsciiMatcher::Nearest8(const std::array<uint8_t, 32>& levels) const {
#if defined(__SSE2__)
  const std::array<int, 32> target = TargetInk(levels);
  // Per pair of regions, the two targets in every glyph's two lanes.
  auto pairOf = [&target](size_t k) {
    const auto low = static_cast<uint32_t>(target[2 * k]);
    const auto high = static_cast<uint32_t>(target[2 * k + 1]);
    return _mm_set1_epi32(static_cast<int>(low | high << 16));
  };
  const __m128i targets0 = pairOf(0), targets1 = pairOf(1), targets2 = pairOf(2),
                targets3 = pairOf(3);
  int bestError = INT32_MAX;
  size_t best = 0;
  const size_t blocks = pairedInks_.size() / 32;
  for (size_t b = 0; b < blocks; ++b) {
    // Four glyphs' squared errors: differences of 16-bit lanes, summed in pairs (madd).
    const int16_t* const inks = pairedInks_.data() + b * 32;
    auto squares = [inks](size_t k, __m128i targets) {
      const __m128i difference =
          _mm_sub_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(inks + k * 8)), targets);
      return _mm_madd_epi16(difference, difference);
    };
    const __m128i sum = _mm_add_epi32(_mm_add_epi32(squares(0, targets0), squares(1, targets1)),
                                      _mm_add_epi32(squares(2, targets2), squares(3, targets3)));
    alignas(16) std::array<int32_t, 4> errors{};
    _mm_store_si128(reinterpret_cast<__m128i*>(errors.data()), sum);
    for (size_t j = 0; j < 4; ++j) {
      if (errors[j] < bestError) {  // strict: the lower code point keeps a tie
        bestError = errors[j];
        best = b * 4 + j;
      }
    }
  }
  return glyphs_.empty() ? U'.' : glyphs_[best];
#else
  return Nearest(levels);
#endif
}

char32_t AsciiMatcher::Nearest(const std::array<uint8_t, 32>& levels) const {
  const std::array<int, 32> target = TargetInk(levels);
  int64_t bestError = INT64_MAX;
  char32_t best = U'.';
  for (size_t g = 0; g < glyphs_.size(); ++g) {
    const int* vector = &vectors_[g * static_cast<size_t>(count_)];
    int64_t error = 0;
    for (int n = 0; n < count_; ++n) {
      const int difference = vector[n] - target[n];
      error += difference * difference;
    }
    if (error < bestError) {  // strict: the lower code point keeps a tie
      bestError = error;
      best = glyphs_[g];
    }
  }
  return best;
}

}  // namespace termshade
