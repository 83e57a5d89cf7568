// termshade-import: runs one Assimp import for termshade in its own process
// (io/import/IsolatedImport.h), under the limits its arguments give.
// Usage: termshade-import ADDRESS_SPACE_BYTES CPU_SECONDS PARENT_PID
//   fd 0: the request; fd 3: the frames (io/import/ImportWire.h).
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/import/ImportHelper.h"

namespace {

bool ParseCount(const char* text, uint64_t& value) {
  try {
    size_t used = 0;
    value = std::stoull(text, &used);
    return text[used] == '\0' && text[0] != '-';
  } catch (...) {
    return false;
  }
}

}  // namespace

int main(int argc, char** argv) {
  uint64_t addressSpaceBytes = 0, dataBytes = 0, cpuSeconds = 0, parent = 0;
  if (argc != 5 || !ParseCount(argv[1], addressSpaceBytes) || !ParseCount(argv[2], dataBytes) ||
      !ParseCount(argv[3], cpuSeconds) || !ParseCount(argv[4], parent)) {
    std::fputs("termshade-import: started by termshade to import one model; not for use alone\n",
               stderr);
    return 2;
  }
  // Step 1: end with termshade, and take no more than it allows.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (static_cast<uint64_t>(getppid()) != parent) return 1;  // it ended before that took hold
  termshade::LimitImportProcess(addressSpaceBytes, dataBytes, cpuSeconds);
  // Step 2: the import.
  return termshade::ServeImportRequest(STDIN_FILENO, 3);
}
