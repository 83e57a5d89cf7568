#include "process/ThreadStart.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace termshade {

int UsableCores() {
  cpu_set_t cores;
  CPU_ZERO(&cores);
  if (sched_getaffinity(0, sizeof(cores), &cores) != 0) return 1;
  return std::max(1, CPU_COUNT(&cores));
}

QuietThreadStart::QuietThreadStart() {
#if defined(__GLIBC__)
  mallopt(M_ARENA_MAX, 1);
#endif
  // Every signal but the synchronous ones: a fault that is blocked is forced
  // to its default action (the mapped-file guard's SIGBUS handler would
  // never run on a load thread).
  sigset_t quiet;
  sigfillset(&quiet);
  for (const int fault : {SIGBUS, SIGSEGV, SIGFPE, SIGILL, SIGTRAP}) sigdelset(&quiet, fault);
  pthread_sigmask(SIG_SETMASK, &quiet, &previousMask_);
}

QuietThreadStart::~QuietThreadStart() {
  pthread_sigmask(SIG_SETMASK, &previousMask_, nullptr);
}

}  // namespace termshade
