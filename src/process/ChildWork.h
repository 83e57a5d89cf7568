#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace termshade {

/// How work run in a child process ended.
enum class ChildOutcome {
  kAnswered,   ///< work returned in the child; `take` has run here
  kCancelled,  ///< the cancel flag was set: the child was killed
  kNoChild,    ///< no child could be made (fork or shared memory failed): run it here
  kDied,       ///< the child ended without an answer (killed, out of memory, a crash):
               ///< running the same work here would likely end this process the same way
};

/// Runs `work` in a child process (fork) so that a set `cancel` can stop it
/// at once (SIGKILL), however long a library call inside it runs. The child
/// sees this process's memory as it was (copy on write), with every signal
/// at its default and unblocked, no file descriptors, and death with this
/// process (so nothing of it reaches the terminal and it never outlives
/// the viewer); it writes its answer into `sharedBytes` bytes shared with
/// this process, given to `work` zeroed, and must not start threads. Waits
/// for the child, polling `cancel` every few milliseconds, then gives the
/// shared bytes to `take` here.
ChildOutcome RunInChild(size_t sharedBytes, const std::function<void(std::byte* shared)>& work,
                        const std::function<void(const std::byte* shared)>& take,
                        const std::atomic<bool>& cancel);

}  // namespace termshade
