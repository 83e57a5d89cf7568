#include "tui/WorkerThread.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <vector>

namespace termshade {

ReadyPipe::ReadyPipe() {
  if (pipe(fds_) != 0) return;
  for (int fd : fds_) {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
}

ReadyPipe::~ReadyPipe() {
  for (int fd : fds_) {
    if (fd >= 0) close(fd);
  }
}

void ReadyPipe::Notify() const {
  const char byte = 1;
  [[maybe_unused]] const ssize_t written = write(fds_[1], &byte, 1);
}

void ReadyPipe::Drain() const {
  char byte;
  [[maybe_unused]] const ssize_t drained = read(fds_[0], &byte, 1);
}

std::thread StartWorkerThread(std::function<void()> work) {
  // Block the loop's signals while the worker starts, so it inherits the mask.
  sigset_t loopSignals, previous;
  sigemptyset(&loopSignals);
  for (int signalNumber : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGTSTP, SIGCONT, SIGWINCH}) {
    sigaddset(&loopSignals, signalNumber);
  }
  pthread_sigmask(SIG_BLOCK, &loopSignals, &previous);
  std::thread worker([work = std::move(work)] {
    // A crash in an importer still gives the terminal back.
    std::vector<char> alternateStack(size_t{64} * 1024);
    stack_t alternate{};
    alternate.ss_sp = alternateStack.data();
    alternate.ss_size = alternateStack.size();
    sigaltstack(&alternate, nullptr);
    work();
    stack_t off{};
    off.ss_flags = SS_DISABLE;
    sigaltstack(&off, nullptr);
  });
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return worker;
}

}  // namespace termshade
