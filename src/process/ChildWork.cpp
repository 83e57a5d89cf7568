#include "process/ChildWork.h"

#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <thread>

namespace termshade {
namespace {

constexpr auto kCancelPoll = std::chrono::milliseconds(5);

// Anonymous memory shared with children forked while it is mapped.
class SharedMapping {
 public:
  explicit SharedMapping(size_t bytes) : bytes_(bytes) {
    void* p = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    data_ = p == MAP_FAILED ? nullptr : static_cast<std::byte*>(p);
  }
  ~SharedMapping() {
    if (data_ != nullptr) munmap(data_, bytes_);
  }
  SharedMapping(const SharedMapping&) = delete;
  SharedMapping& operator=(const SharedMapping&) = delete;
  std::byte* Data() const { return data_; }

 private:
  size_t bytes_;
  std::byte* data_ = nullptr;
};

// The child's end: 1 once `work` has returned (the first bytes of the mapping).
struct ChildHeader {
  std::atomic<int> done{0};
};
constexpr size_t kHeaderBytes = 64;
static_assert(sizeof(ChildHeader) <= kHeaderBytes);

// Reaps the child (nothing to do when it was reaped elsewhere: SIGCHLD ignored).
void Reap(pid_t child) {
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
}

// The child's start: this process's signal handlers (the viewer's, which
// restore the terminal), blocked signals and open files left behind, and
// death with the parent. False when the parent is already gone.
bool BecomeQuietChild(pid_t parent) {
  for (int signalNumber = 1; signalNumber < NSIG; ++signalNumber) {
    if (signalNumber != SIGKILL && signalNumber != SIGSTOP) signal(signalNumber, SIG_DFL);
  }
  sigset_t none;
  sigemptyset(&none);
  pthread_sigmask(SIG_SETMASK, &none, nullptr);
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) return false;
  close_range(0, ~0U, 0);
  return true;
}

}  // namespace

ChildOutcome RunInChild(size_t sharedBytes, const std::function<void(std::byte* shared)>& work,
                        const std::function<void(const std::byte* shared)>& take,
                        const std::atomic<bool>& cancel) {
  SharedMapping mapping(kHeaderBytes + sharedBytes);
  if (mapping.Data() == nullptr) return ChildOutcome::kNoChild;
  auto* header = new (mapping.Data()) ChildHeader;
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0) return ChildOutcome::kNoChild;
  if (child == 0) {  // the child: the work, then out without this process's exit handlers
    if (!BecomeQuietChild(parent)) _exit(1);
    try {
      work(mapping.Data() + kHeaderBytes);
    } catch (...) {
      _exit(1);
    }
    header->done.store(1, std::memory_order_release);
    _exit(0);
  }
  // Step 1: wait for the child's answer, its death, or a cancel.
  for (;;) {
    if (header->done.load(std::memory_order_acquire) != 0) break;
    if (cancel.load(std::memory_order_relaxed)) {
      kill(child, SIGKILL);
      Reap(child);
      return ChildOutcome::kCancelled;
    }
    int status = 0;
    const pid_t ended = waitpid(child, &status, WNOHANG);
    if (ended == child || (ended < 0 && errno == ECHILD)) {
      // Ended: its answer counts only if it got as far as writing it.
      if (header->done.load(std::memory_order_acquire) == 0) return ChildOutcome::kDied;
      take(mapping.Data() + kHeaderBytes);
      return ChildOutcome::kAnswered;
    }
    std::this_thread::sleep_for(kCancelPoll);
  }
  Reap(child);
  take(mapping.Data() + kHeaderBytes);
  return ChildOutcome::kAnswered;
}

}  // namespace termshade
