#pragma once

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace termshade {

/// Threads kept for the life of the pool: Run hands the same job to every
/// one of them (the caller's thread is worker 0) and returns when all are
/// done, so a frame loop creates no threads per frame. A worker that has
/// finished a job spins briefly before it sleeps (as OpenMP runtimes do), so
/// back-to-back jobs start without a wake-up's system call and latency.
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
  /// Waits until generation_ differs from `seen` and returns it.
  uint32_t AwaitGeneration(uint32_t seen);
  void AwaitWorkersDone();

  std::vector<std::thread> threads_;
  ErasedJob job_ = nullptr;  ///< published by generation_'s increment
  void* context_ = nullptr;
  bool stop_ = false;
  std::atomic<uint32_t> generation_{0};  ///< bumped for each job (and to stop)
  std::atomic<int> sleepingWorkers_{0};  ///< workers blocked on generation_
  std::atomic<int> running_{0};          ///< workers still in this job
  std::atomic<bool> callerSleeping_{false};
};

/// The thread count a frame uses for `requested` (0: every core).
int ResolvedThreadCount(int requested);

}  // namespace termshade
