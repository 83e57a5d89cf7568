#include "io/read/FileMapGuard.h"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <mutex>

namespace termshade {
namespace {

constexpr int kSlots = 16;
// Handlers saved: one more each time something replaced ours (a later
// watch then reads its file instead of mapping it).
constexpr int kMostInstalls = 64;

// One watched range: [begin, end), 0/0 when free.
struct WatchedRange {
  std::atomic<uintptr_t> begin{0};
  std::atomic<uintptr_t> end{0};
  std::atomic<bool> shrank{false};
};

// The signal handler can reach only globals: the watched ranges, the page
// size and the actions it passes other signals on to. Each saved action is
// written once, before it is published in gPreviousAt and before the
// handler that reads it is installed, and never written again.
// NOLINTBEGIN(cppcoreguidelines-avoid-non-const-global-variables)
WatchedRange gRanges[kSlots];
std::atomic<uintptr_t> gPageBytes{4096};
struct sigaction gPrevious[kMostInstalls];
std::atomic<int> gPreviousAt{-1};
int gInstalls = 0;  // guarded by gInstallMutex
std::mutex gInstallMutex;
// NOLINTEND(cppcoreguidelines-avoid-non-const-global-variables)

// Maps a page of zeros over the faulting page of a watched range; false
// when the address is in none. mmap is async-signal-safe in practice on
// Linux (glibc's mmap is the plain system call, POSIX does not list it).
bool ReplaceLostPage(uintptr_t address) {
  for (WatchedRange& range : gRanges) {
    if (address < range.begin.load() || address >= range.end.load()) continue;
    const uintptr_t page = address & ~(gPageBytes.load() - 1);
    void* zeros = mmap(reinterpret_cast<void*>(page), gPageBytes.load(), PROT_READ,
                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0);
    if (zeros == MAP_FAILED) return false;
    range.shrank.store(true);
    return true;
  }
  return false;
}

// A signal that is not a watched page's: what the action before ours does
// with it. A handler is called; an ignored signal stays ignored when it was
// sent (kill, raise), while a fault, which the kernel never lets a process
// ignore, and the default action end the process: the default is restored,
// a fault repeats on return, a sent signal is raised again.
void PassOn(int signalNumber, siginfo_t* info, void* context) {
  const int at = gPreviousAt.load(std::memory_order_acquire);
  const struct sigaction* previous = at >= 0 ? &gPrevious[at] : nullptr;
  const bool sent = info == nullptr || info->si_code <= 0;
  if (previous != nullptr && (previous->sa_flags & SA_SIGINFO) != 0 &&
      previous->sa_sigaction != nullptr) {
    previous->sa_sigaction(signalNumber, info, context);
    return;
  }
  if (previous != nullptr && previous->sa_handler == SIG_IGN && sent) return;
  if (previous != nullptr && previous->sa_handler != SIG_DFL && previous->sa_handler != SIG_IGN &&
      previous->sa_handler != nullptr) {
    previous->sa_handler(signalNumber);
    return;
  }
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  sigaction(signalNumber, &fallback, nullptr);
  if (sent) raise(signalNumber);
}

// Async-signal-safe: atomics, mmap (see ReplaceLostPage), sigaction, raise.
// Only a fault at an address past a file's end (BUS_ADRERR: also an I/O
// error reading a mapped page) inside a watched range is taken.
extern "C" void OnBusError(int signalNumber, siginfo_t* info, void* context) {
  const int savedErrno = errno;
  if (info != nullptr && info->si_code == BUS_ADRERR &&
      ReplaceLostPage(reinterpret_cast<uintptr_t>(info->si_addr))) {
    errno = savedErrno;
    return;  // the read is tried again and finds zeros
  }
  errno = savedErrno;
  PassOn(signalNumber, info, context);
}

// Installs OnBusError unless it is the handler now; false when it cannot
// (the action it would replace cannot be saved).
bool InstallHandler() {
  const std::lock_guard<std::mutex> lock(gInstallMutex);
  struct sigaction current {};
  if (sigaction(SIGBUS, nullptr, &current) != 0) return false;
  if ((current.sa_flags & SA_SIGINFO) != 0 && current.sa_sigaction == OnBusError) return true;
  if (gInstalls >= kMostInstalls) return false;
  gPageBytes.store(static_cast<uintptr_t>(sysconf(_SC_PAGESIZE)));
  // Saved and published first: the handler never reads a slot being written.
  gPrevious[gInstalls] = current;
  gPreviousAt.store(gInstalls, std::memory_order_release);
  ++gInstalls;
  struct sigaction action {};
  action.sa_sigaction = OnBusError;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_NODEFER;
  return sigaction(SIGBUS, &action, nullptr) == 0;
}

}  // namespace

int WatchMappedRange(const void* begin, size_t bytes) {
  if (!InstallHandler()) return -1;
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
