#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace termshade {

/// Runs `work` in a child process (fork) so that a set `cancel` can stop it
/// at once (SIGKILL), however long a library call inside it runs. The child
/// sees this process's memory as it was (copy on write) and writes its
/// answer into `sharedBytes` bytes shared with this process, given to
/// `work` zeroed; it must not start threads. Waits for the child, polling
/// `cancel` every few milliseconds, then gives the shared bytes to `take`
/// here. True when `work` returned in the child (and `take` ran); false when
/// cancelled, or when the child could not start or died (out of memory, a
/// crash): the caller then has no answer and decides (cancelled: nothing;
/// died: run it here, or give up).
bool RunInChild(size_t sharedBytes, const std::function<void(std::byte* shared)>& work,
                const std::function<void(const std::byte* shared)>& take,
                const std::atomic<bool>& cancel);

}  // namespace termshade
