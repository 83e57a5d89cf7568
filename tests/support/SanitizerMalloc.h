#pragma once

// Whether a sanitizer replaces glibc's malloc in this build (AddressSanitizer,
// MemorySanitizer): heap policy and resident-memory tests do not apply then.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define TERMSHADE_SANITIZER_MALLOC 1
#endif
#endif

namespace termshade {

#if defined(__SANITIZE_ADDRESS__) || defined(TERMSHADE_SANITIZER_MALLOC)
inline constexpr bool kSanitizerMalloc = true;
#else
inline constexpr bool kSanitizerMalloc = false;
#endif

}  // namespace termshade
