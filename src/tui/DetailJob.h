#pragma once

#include <atomic>
#include <memory>
#include <thread>

#include "geometry/LevelOfDetail.h"
#include "geometry/Scene.h"
#include "tui/WorkerThread.h"

namespace termshade {

/// The levels of detail of one scene, built on a worker thread while the
/// viewer goes on drawing the exact scene. Done: one byte on ReadyFd.
class DetailJob {
 public:
  explicit DetailJob(std::shared_ptr<const Scene> scene);
  /// Joins a finished worker; asks an unfinished one to stop and lets it end alone.
  ~DetailJob();
  DetailJob(const DetailJob&) = delete;
  DetailJob& operator=(const DetailJob&) = delete;

  /// The scene the levels are of.
  const std::shared_ptr<const Scene>& ForScene() const { return scene_; }
  int ReadyFd() const { return shared_->ready.ReadFd(); }
  bool Finished() const { return shared_->finished.load(); }
  /// The levels, once Finished(); joins the worker.
  std::shared_ptr<const DetailLevels> Take();

 private:
  struct Shared {
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    std::shared_ptr<const DetailLevels> result;  ///< written by the worker before finished
    ReadyPipe ready;
  };

  std::shared_ptr<const Scene> scene_;
  std::shared_ptr<Shared> shared_;
  std::thread worker_;
};

}  // namespace termshade
