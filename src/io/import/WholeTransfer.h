#pragma once

#include <cstddef>

namespace termshade {

/// True in AddressSanitizer builds (GCC's __SANITIZE_ADDRESS__, clang's feature test).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizerBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizerBuild = true;
#else
inline constexpr bool kAddressSanitizerBuild = false;
#endif
#else
inline constexpr bool kAddressSanitizerBuild = false;
#endif

/// Writes all `size` bytes to fd (retrying interrupted and short writes); false on an error.
bool WriteWhole(int fd, const void* from, size_t size);

/// Reads exactly `size` bytes from fd; false on an error or at the end of its input.
bool ReadWhole(int fd, void* to, size_t size);

}  // namespace termshade
