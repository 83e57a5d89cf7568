#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace termshade {

/// Threads kept for the life of the pool: Run hands the same job to every
/// one of them (the caller's thread is worker 0) and returns when all are
/// done, so a frame loop creates no threads per frame.
class WorkerPool {
 public:
  explicit WorkerPool(int workers);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int Workers() const { return static_cast<int>(threads_.size()) + 1; }
  /// Calls job(worker) once for each worker 0 .. Workers() - 1, concurrently
  /// (no allocation: the job is passed by reference).
  template <typename Job>
  void Run(Job& job) {
    RunErased([](void* context, int worker) { (*static_cast<Job*>(context))(worker); }, &job);
  }

 private:
  using ErasedJob = void (*)(void* context, int worker);
  void RunErased(ErasedJob job, void* context);
  void Loop(int worker);

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  ErasedJob job_ = nullptr;
  void* context_ = nullptr;
  unsigned long generation_ = 0;
  int running_ = 0;
  bool stop_ = false;
};

/// The thread count a frame uses for `requested` (0: every core).
int ResolvedThreadCount(int requested);

}  // namespace termshade
