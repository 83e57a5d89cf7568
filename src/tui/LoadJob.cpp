#include "tui/LoadJob.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <vector>

#include "io/ModelLoader.h"
#include "tui/ViewerState.h"

namespace termshade {

LoadJob::Shared::Shared() {
  if (pipe(readyPipe) != 0) return;
  for (int fd : readyPipe) {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
}

LoadJob::Shared::~Shared() {
  for (int fd : readyPipe) {
    if (fd >= 0) close(fd);
  }
}

LoadJob::LoadJob(std::string path, std::optional<UpAxis> upAxis)
    : path_(std::move(path)), shared_(std::make_shared<Shared>()) {
  // The event loop's signals (Ctrl-C, Ctrl-Z...) go to the main thread: block
  // them while the worker starts, so it inherits the mask.
  sigset_t loopSignals, previous;
  sigemptyset(&loopSignals);
  for (int signalNumber : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGTSTP, SIGCONT, SIGWINCH}) {
    sigaddset(&loopSignals, signalNumber);
  }
  pthread_sigmask(SIG_BLOCK, &loopSignals, &previous);
  worker_ = std::thread(Work, shared_, path_, upAxis);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

void LoadJob::Work(const std::shared_ptr<Shared>& shared, const std::string& path,
                   std::optional<UpAxis> upAxis) {
  // A stack for the fatal-signal handler, as the main thread has: a crash in
  // an importer still gives the terminal back.
  std::vector<char> alternateStack(size_t{64} * 1024);
  stack_t alternate{};
  alternate.ss_sp = alternateStack.data();
  alternate.ss_size = alternateStack.size();
  sigaltstack(&alternate, nullptr);

  LoadOptions options;
  options.cancel = &shared->cancel;
  options.progress = [&shared](double share) { shared->progress.store(share); };
  Loaded<Mesh> mesh = LoadViewerMesh(path, options);
  if (mesh.Ok()) {
    shared->preparing.store(true);
    shared->result.emplace(PrepareScene(std::move(mesh.Value()), upAxis));
  } else {
    shared->result.emplace(mesh.Error());
  }

  stack_t off{};
  off.ss_flags = SS_DISABLE;
  sigaltstack(&off, nullptr);
  shared->finished.store(true);
  const char byte = 1;
  [[maybe_unused]] const ssize_t written = write(shared->readyPipe[1], &byte, 1);
}

Loaded<Scene> LoadJob::Take() {
  if (worker_.joinable()) worker_.join();
  char byte;
  [[maybe_unused]] const ssize_t drained = read(shared_->readyPipe[0], &byte, 1);
  if (!shared_->result) return LoadError{path_, 0, 0, "the load did not finish"};
  Loaded<Scene> result = std::move(*shared_->result);
  shared_->result.reset();
  return result;
}

LoadJob::~LoadJob() {
  if (!worker_.joinable()) return;
  if (Finished()) {
    worker_.join();
  } else {
    Cancel();
    worker_.detach();  // it holds its own reference to the shared state
  }
}

}  // namespace termshade
