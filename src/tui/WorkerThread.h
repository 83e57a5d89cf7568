#pragma once

#include <functional>
#include <thread>

namespace termshade {

/// A pipe a worker writes one byte to when done; the event loop polls its
/// read end with its other descriptors. Non-blocking, closed on exec.
class ReadyPipe {
 public:
  ReadyPipe();
  ~ReadyPipe();
  ReadyPipe(const ReadyPipe&) = delete;
  ReadyPipe& operator=(const ReadyPipe&) = delete;
  int ReadFd() const { return fds_[0]; }
  void Notify() const;
  void Drain() const;

 private:
  int fds_[2] = {-1, -1};
};

/// Starts `work` on a thread that never takes the event loop's signals
/// (Ctrl-C, Ctrl-Z, SIGWINCH... stay with the main thread) and has an
/// alternate stack for the fatal-signal handler, as the main thread has.
std::thread StartWorkerThread(std::function<void()> work);

}  // namespace termshade
