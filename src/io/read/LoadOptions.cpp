#include "io/read/LoadOptions.h"

#include <charconv>
#include <cstdlib>

#include "io/read/LoadBudget.h"

namespace termshade {

size_t DefaultMemoryBudgetBytes() {
  constexpr size_t kDefaultBudget = size_t{2} << 30;
  const char* text = std::getenv("TERMSHADE_MEMORY_BUDGET");
  if (text == nullptr || *text == '\0') return kDefaultBudget;
  return ParseByteCount(text).value_or(kDefaultBudget);
}

std::optional<uint32_t> ParseImportSeconds(std::string_view text) {
  constexpr uint32_t kMostSeconds = 86400;
  uint32_t seconds = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  if (seconds < 1 || seconds > kMostSeconds) return std::nullopt;
  return seconds;
}

uint32_t DefaultImportCpuSeconds() {
  const char* text = std::getenv("TERMSHADE_IMPORT_SECONDS");
  if (text == nullptr) return 0;
  return ParseImportSeconds(text).value_or(0);
}

std::optional<std::string> LoadEnvironmentProblem() {
  if (const char* text = std::getenv("TERMSHADE_MEMORY_BUDGET");
      text != nullptr && *text != '\0' && !ParseByteCount(text)) {
    return std::string("TERMSHADE_MEMORY_BUDGET='") + text +
           "': expected a size such as 4G, 512M or 1000000 (bytes), 1 byte to 64T";
  }
  if (const char* text = std::getenv("TERMSHADE_IMPORT_SECONDS");
      text != nullptr && *text != '\0' && !ParseImportSeconds(text)) {
    return std::string("TERMSHADE_IMPORT_SECONDS='") + text +
           "': expected whole seconds from 1 to 86400";
  }
  return std::nullopt;
}

}  // namespace termshade
