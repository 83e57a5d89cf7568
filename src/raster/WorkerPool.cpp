#include "raster/WorkerPool.h"

#include <algorithm>

#include <csignal>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace termshade {

WorkerPool::WorkerPool(int workers) {
#if defined(__GLIBC__)
  // One malloc arena for every thread: a worker's own arena, once it shrinks,
  // makes glibc read /proc/sys/vm/overcommit_memory, a file outside the
  // model's folder (tests/models/corpus_check.sh); the workers allocate only
  // while their bins grow, so sharing the arena costs nothing measurable.
  mallopt(M_ARENA_MAX, 1);
#endif
  // The workers take no signals (they inherit this mask): the viewer's
  // SIGWINCH and SIGINT stay with the thread that waits for input.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { Loop(w); });
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
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
  if (requested > 0) return requested;
#if defined(__linux__)
  // The cores this process may run on, by a system call: hardware_concurrency
  // reads /sys, a file outside the model's folder (tests/models/corpus_check.sh).
  cpu_set_t cores;
  CPU_ZERO(&cores);
  if (sched_getaffinity(0, sizeof(cores), &cores) == 0) return std::max(1, CPU_COUNT(&cores));
  return 1;
#else
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
#endif
}

}  // namespace termshade
