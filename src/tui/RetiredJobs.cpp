#include "tui/RetiredJobs.h"

#include <algorithm>

#include "process/HeapPolicy.h"

namespace termshade {

bool RetiredJobs::Busy() {
  const size_t before = jobs_.size();
  std::erase_if(jobs_, [](const Entry& entry) { return entry.finished(); });
  // The worker trimmed the heap as it ended; what its job still held goes back here.
  if (jobs_.size() < before) ReturnFreedMemory();
  return !jobs_.empty();
}

}  // namespace termshade
