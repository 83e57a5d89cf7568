#pragma once

#include <csignal>

namespace termshade {

/// The cores this process may run on (at least 1), by a system call:
/// hardware_concurrency reads /sys, a file outside the model's folder
/// (tests/models/corpus_check.sh).
int UsableCores();

/// While alive, threads started by this thread take no signals but the
/// synchronous faults (SIGBUS, SIGSEGV, SIGFPE, SIGILL, SIGTRAP, which go to
/// the thread that raised them; the viewer's SIGWINCH and SIGINT stay with
/// the thread that waits for input), and every
/// thread shares one malloc arena: a thread's own arena, once it shrinks,
/// makes glibc read /proc/sys/vm/overcommit_memory, another file outside the
/// model's folder.
class QuietThreadStart {
 public:
  QuietThreadStart();
  ~QuietThreadStart();
  QuietThreadStart(const QuietThreadStart&) = delete;
  QuietThreadStart& operator=(const QuietThreadStart&) = delete;

 private:
  sigset_t previousMask_{};
};

}  // namespace termshade
