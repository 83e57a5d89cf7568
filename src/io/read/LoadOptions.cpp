#include "io/read/LoadOptions.h"

#include <cstdlib>

#include "io/read/LoadBudget.h"

namespace termshade {

size_t DefaultMemoryBudgetBytes() {
  constexpr size_t kDefaultBudget = size_t{2} << 30;
  const char* text = std::getenv("TERMSHADE_MEMORY_BUDGET");
  if (text == nullptr) return kDefaultBudget;
  return ParseByteCount(text).value_or(kDefaultBudget);
}

uint32_t DefaultImportCpuSeconds() {
  const char* text = std::getenv("TERMSHADE_IMPORT_SECONDS");
  if (text == nullptr || *text < '1' || *text > '9') return 0;
  char* end = nullptr;
  const unsigned long seconds = std::strtoul(text, &end, 10);  // NOLINT(google-runtime-int)
  constexpr unsigned long kMostSeconds = 86400;                // NOLINT(google-runtime-int)
  return *end == '\0' && seconds <= kMostSeconds ? static_cast<uint32_t>(seconds) : 0;
}

}  // namespace termshade
