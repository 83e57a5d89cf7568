#include "raster/WorkerPool.h"

#include "geometry/ThreadStart.h"

namespace termshade {

WorkerPool::WorkerPool(int workers) {
  // Workers inherit no signals; all threads share one arena (the workers
  // allocate only while their bins grow, so sharing costs nothing measurable).
  const QuietThreadStart quiet;
  for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { Loop(w); });
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void WorkerPool::RunErased(ErasedJob job, void* context) {
  {
    const std::lock_guard lock(mutex_);
    job_ = job;
    context_ = context;
    running_ = static_cast<int>(threads_.size());
    ++generation_;
  }
  start_.notify_all();
  job(context, 0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return running_ == 0; });
  job_ = nullptr;
  context_ = nullptr;
}

void WorkerPool::Loop(int worker) {
  unsigned long seen = 0;
  for (;;) {
    ErasedJob job = nullptr;
    void* context = nullptr;
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      job = job_;
      context = context_;
    }
    job(context, worker);
    {
      const std::lock_guard lock(mutex_);
      --running_;
    }
    done_.notify_one();
  }
}

int ResolvedThreadCount(int requested) {
  return requested > 0 ? requested : UsableCores();
}

}  // namespace termshade
