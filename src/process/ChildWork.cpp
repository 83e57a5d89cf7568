#include "process/ChildWork.h"

#include <signal.h>
#include <sys/mman.h>
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

}  // namespace

bool RunInChild(size_t sharedBytes, const std::function<void(std::byte* shared)>& work,
                const std::function<void(const std::byte* shared)>& take,
                const std::atomic<bool>& cancel) {
  SharedMapping mapping(kHeaderBytes + sharedBytes);
  if (mapping.Data() == nullptr) return false;
  auto* header = new (mapping.Data()) ChildHeader;
  const pid_t child = fork();
  if (child < 0) return false;
  if (child == 0) {  // the child: the work, then out without this process's exit handlers
    work(mapping.Data() + kHeaderBytes);
    header->done.store(1, std::memory_order_release);
    _exit(0);
  }
  // Step 1: wait for the child's answer, its death, or a cancel.
  for (;;) {
    if (header->done.load(std::memory_order_acquire) != 0) break;
    if (cancel.load(std::memory_order_relaxed)) {
      kill(child, SIGKILL);
      Reap(child);
      return false;
    }
    int status = 0;
    const pid_t ended = waitpid(child, &status, WNOHANG);
    if (ended == child || (ended < 0 && errno == ECHILD)) {
      // Ended: its answer counts only if it got as far as writing it.
      if (header->done.load(std::memory_order_acquire) == 0) return false;
      take(mapping.Data() + kHeaderBytes);
      return true;
    }
    std::this_thread::sleep_for(kCancelPoll);
  }
  Reap(child);
  take(mapping.Data() + kHeaderBytes);
  return true;
}

}  // namespace termshade
