#pragma once

#include <cstddef>
#include <functional>

namespace termshade {

/// How many threads a load step of `items` items uses: every core (at most
/// 8), one below kMinItemsPerThread items a thread, where starting a thread
/// costs more than it saves.
int LoadThreadCount(size_t items);

/// Runs work(0) .. work(threads - 1) (nothing for threads < 1), work(0) on the calling thread, the
/// rest on threads started for the call and joined before it returns. The started threads take no
/// signals (the viewer's SIGWINCH and SIGINT stay with the thread that waits for input) and work
/// must not allocate or throw there.
void RunOnLoadThreads(int threads, const std::function<void(int)>& work);

}  // namespace termshade
