#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <thread>
#include <utility>

#include "geometry/Scene.h"
#include "process/HeapPolicy.h"
#include "tui/WorkerThread.h"

namespace termshade {

/// Something built from one scene on a worker thread (its levels of detail,
/// its triangle hierarchy) while the viewer goes on drawing the scene. Done:
/// one byte on ReadyFd. The worker holds its own references to the scene and
/// the shared state, so an abandoned job may end on its own.
template <typename Result>
class SceneJob {
 public:
  /// build(scene, cancel): polls cancel and may return early once it is set.
  using Build = std::function<Result(const Scene&, const std::atomic<bool>& cancel)>;

  SceneJob(std::shared_ptr<const Scene> scene, Build build)
      : scene_(std::move(scene)), shared_(std::make_shared<Shared>()) {
    worker_ =
        StartWorkerThread([shared = shared_, scene = scene_, build = std::move(build)]() mutable {
          shared->result = std::make_shared<const Result>(build(*scene, shared->cancel));
          // The build's own arrays go back to the kernel here, off the event loop (a
          // 10M-triangle scan's levels leave 1.1 GB free in the heap; the trim takes 70 ms).
          ReturnFreedMemory();
          shared->finished.store(true);
          shared->ready.Notify();
          // Abandoned (see ~SceneJob): nobody takes the result; the scene may be the last
          // reference.
          if (shared->cancel.load()) {
            shared->result.reset();
            scene.reset();
            ReturnFreedMemory();
          }
        });
  }
  /// Joins a finished worker; asks an unfinished one to stop and lets it end alone.
  ~SceneJob() {
    if (!worker_.joinable()) return;
    // Cancel before looking at finished, as the worker sets finished before looking at
    // cancel: one of the two sees the other's store, so an abandoned worker returns its memory.
    shared_->cancel.store(true);
    if (Finished()) {
      worker_.join();
    } else {
      worker_.detach();
    }
  }
  SceneJob(const SceneJob&) = delete;
  SceneJob& operator=(const SceneJob&) = delete;

  /// Asks the build to stop and lets go of the scene (the worker drops its
  /// own reference and the result as it ends); ForScene is then empty.
  void Cancel() {
    shared_->cancel.store(true);
    scene_.reset();
  }
  /// The scene the result is of.
  const std::shared_ptr<const Scene>& ForScene() const { return scene_; }
  int ReadyFd() const { return shared_->ready.ReadFd(); }
  bool Finished() const { return shared_->finished.load(); }
  /// The result, once Finished(); joins the worker.
  std::shared_ptr<const Result> Take() {
    if (worker_.joinable()) worker_.join();
    shared_->ready.Drain();
    return std::move(shared_->result);
  }

 private:
  struct Shared {
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    std::shared_ptr<const Result> result;  ///< written by the worker before finished
    ReadyPipe ready;
  };

  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<Shared> shared_;
  std::thread worker_;
};

}  // namespace termshade
