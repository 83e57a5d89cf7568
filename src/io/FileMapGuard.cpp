#include "io/FileMapGuard.h"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <mutex>

namespace termshade {
namespace {

constexpr int kSlots = 16;

// One watched range: [begin, end), 0/0 when free.
struct WatchedRange {
  std::atomic<uintptr_t> begin{0};
  std::atomic<uintptr_t> end{0};
  std::atomic<bool> shrank{false};
};

// The signal handler can reach only globals: the watched ranges, the page
// size and the action it passes foreign signals on to.
// NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables)
WatchedRange gRanges[kSlots];
std::atomic<uintptr_t> gPageBytes{4096};
struct sigaction gPrevious {};
std::mutex gInstallMutex;
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables)

// Async-signal-safe: atomics, mmap, sigaction.
extern "C" void OnBusError(int signalNumber, siginfo_t* info, void* context) {
  const auto address = reinterpret_cast<uintptr_t>(info->si_addr);
  for (WatchedRange& range : gRanges) {
    if (address < range.begin.load() || address >= range.end.load()) continue;
    const uintptr_t page = address & ~(gPageBytes.load() - 1);
    void* zeros = mmap(reinterpret_cast<void*>(page), gPageBytes.load(), PROT_READ,
                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0);
    if (zeros == MAP_FAILED) break;
    range.shrank.store(true);
    return;  // the read is tried again and finds zeros
  }
  // Not ours: the previous handler, or the default action (the fault repeats).
  if ((gPrevious.sa_flags & SA_SIGINFO) != 0 && gPrevious.sa_sigaction != nullptr) {
    gPrevious.sa_sigaction(signalNumber, info, context);
    return;
  }
  if (gPrevious.sa_handler != SIG_DFL && gPrevious.sa_handler != SIG_IGN &&
      gPrevious.sa_handler != nullptr) {
    gPrevious.sa_handler(signalNumber);
    return;
  }
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  sigaction(signalNumber, &fallback, nullptr);
}

void InstallHandler() {
  const std::lock_guard<std::mutex> lock(gInstallMutex);
  struct sigaction current {};
  if (sigaction(SIGBUS, nullptr, &current) == 0 && (current.sa_flags & SA_SIGINFO) != 0 &&
      current.sa_sigaction == OnBusError) {
    return;
  }
  gPageBytes.store(static_cast<uintptr_t>(sysconf(_SC_PAGESIZE)));
  struct sigaction action {};
  action.sa_sigaction = OnBusError;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_NODEFER;
  struct sigaction previous {};
  if (sigaction(SIGBUS, &action, &previous) == 0) gPrevious = previous;
}

}  // namespace

int WatchMappedRange(const void* begin, size_t bytes) {
  InstallHandler();
  const auto first = reinterpret_cast<uintptr_t>(begin);
  for (int slot = 0; slot < kSlots; ++slot) {
    uintptr_t free = 0;
    if (!gRanges[slot].begin.compare_exchange_strong(free, first)) continue;
    gRanges[slot].shrank.store(false);
    gRanges[slot].end.store(first + bytes);
    return slot;
  }
  return -1;
}

bool MappedRangeShrank(int slot) {
  return slot >= 0 && slot < kSlots && gRanges[slot].shrank.load();
}

bool StopWatchingMappedRange(int slot) {
  if (slot < 0 || slot >= kSlots) return false;
  const bool shrank = gRanges[slot].shrank.load();
  gRanges[slot].end.store(0);
  gRanges[slot].begin.store(0);
  return shrank;
}

}  // namespace termshade
