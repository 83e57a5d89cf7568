#include "raster/WorkerPool.h"

#include <chrono>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "process/ThreadStart.h"

namespace termshade {
namespace {

// How long a thread spins for the next job, or for the workers to finish,
// before it blocks: longer than the gaps between a frame loop's jobs, short
// enough that an idle viewer's spinning costs well under 1% of a core.
constexpr std::chrono::microseconds kSpinTime{200};

void Pause() {
#if defined(__SSE2__)
  _mm_pause();
#endif
}

// Spins until done() or kSpinTime has passed; true if done(). Between
// short bursts it yields, so another thread ready on this core (another
// pool's worker, another program) runs instead of waiting for the spin.
template <typename Done>
bool SpinUntil(Done done) {
  const auto deadline = std::chrono::steady_clock::now() + kSpinTime;
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (done()) return true;
      Pause();
    }
    if (std::chrono::steady_clock::now() > deadline) return done();
    std::this_thread::yield();
  }
}

}  // namespace

WorkerPool::WorkerPool(int workers) {
  // Workers inherit no signals; all threads share one arena (the workers
  // allocate only while their bins grow, so sharing costs nothing measurable).
  const QuietThreadStart quiet;
  for (int w = 1; w < workers; ++w) threads_.emplace_back([this, w] { Loop(w); });
}

WorkerPool::~WorkerPool() {
  stop_ = true;
  generation_.fetch_add(1, std::memory_order_seq_cst);
  generation_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

// Sleeping workers and the publishing caller pair up as in Dekker's
// algorithm (seq_cst on both sides): a worker counts itself sleeping, then
// reads the generation; the caller bumps the generation, then reads the
// count. At least one of them sees the other's write, so no wake-up is lost,
// and no system call is made while every worker spins.
void WorkerPool::RunErased(ErasedJob job, void* context) {
  job_ = job;
  context_ = context;
  running_.store(static_cast<int>(threads_.size()), std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_seq_cst);
  if (sleepingWorkers_.load(std::memory_order_seq_cst) > 0) generation_.notify_all();
  job(context, 0);
  AwaitWorkersDone();
}

void WorkerPool::AwaitWorkersDone() {
  if (SpinUntil([this] { return running_.load(std::memory_order_acquire) == 0; })) return;
  callerSleeping_.store(true, std::memory_order_seq_cst);
  for (int left = running_.load(std::memory_order_seq_cst); left != 0;
       left = running_.load(std::memory_order_seq_cst)) {
    running_.wait(left, std::memory_order_seq_cst);
  }
  callerSleeping_.store(false, std::memory_order_relaxed);
}

uint32_t WorkerPool::AwaitGeneration(uint32_t seen) {
  if (SpinUntil([&] { return generation_.load(std::memory_order_acquire) != seen; })) {
    return generation_.load(std::memory_order_acquire);
  }
  sleepingWorkers_.fetch_add(1, std::memory_order_seq_cst);
  uint32_t now = generation_.load(std::memory_order_seq_cst);
  for (; now == seen; now = generation_.load(std::memory_order_seq_cst)) {
    generation_.wait(seen, std::memory_order_seq_cst);
  }
  sleepingWorkers_.fetch_sub(1, std::memory_order_relaxed);
  return now;
}

void WorkerPool::Loop(int worker) {
  uint32_t seen = 0;
  for (;;) {
    seen = AwaitGeneration(seen);
    if (stop_) return;
    job_(context_, worker);
    // The same pairing as RunErased's, the other way round.
    if (running_.fetch_sub(1, std::memory_order_seq_cst) == 1 &&
        callerSleeping_.load(std::memory_order_seq_cst)) {
      running_.notify_one();
    }
  }
}

int ResolvedThreadCount(int requested) {
  return requested > 0 ? requested : UsableCores();
}

}  // namespace termshade
