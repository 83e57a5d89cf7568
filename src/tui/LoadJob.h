#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "geometry/Scene.h"
#include "geometry/UpAxis.h"
#include "io/load/ModelLoader.h"
#include "io/read/LoadError.h"
#include "tui/WorkerThread.h"

namespace termshade {

/// One model load on a worker thread: the file read and PrepareScene, with
/// the loader's cancel flag and progress hooks; or a loaded model prepared
/// again with another up axis. The worker never touches the terminal: it
/// writes one byte to a pipe when done, which the event loop polls with its
/// other descriptors.
class LoadJob {
 public:
  /// upAxis: the viewer's --up, else each file's own (SPEC 10); limits: the
  /// most memory and import time the load may take.
  LoadJob(std::string path, std::optional<UpAxis> upAxis, LoadLimits limits = {});
  /// The scene's model prepared again, turned so that `upAxis` is up.
  LoadJob(std::string path, std::shared_ptr<const Scene> scene, UpAxis upAxis);
  /// Joins a finished worker; stops an unfinished one (Stop) and, if it runs
  /// on, lets it end on its own (the process should then not run static
  /// destructors under it: leave with _Exit).
  ~LoadJob();
  LoadJob(const LoadJob&) = delete;
  LoadJob& operator=(const LoadJob&) = delete;

  const std::string& Path() const { return path_; }
  /// Readable once the worker has finished.
  int ReadyFd() const { return shared_->ready.ReadFd(); }
  bool Finished() const { return shared_->finished.load(); }
  /// Share of the file read, in [0, 1], or negative while the importer has
  /// not said; 1 while the scene is being prepared.
  double Progress() const { return shared_->progress.load(); }
  bool Preparing() const { return shared_->preparing.load(); }
  /// Asks the loader to stop (it polls the flag); returns at once.
  void Cancel() { shared_->cancel.store(true); }
  /// Cancel, then waits up to kStopWaitMs for the worker to end: a load in
  /// the import helper does (the helper killed and reaped), and so does the
  /// scene's preparation, between two of its steps. True when it has ended
  /// (then Take may join it).
  bool Stop();
  static constexpr int kStopWaitMs = 150;
  /// The result, once Finished(); joins the worker.
  Loaded<Scene> Take();

 private:
  struct Shared {
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    std::atomic<bool> preparing{false};
    std::atomic<double> progress{-1.0};
    std::optional<Loaded<Scene>> result;  ///< written by the worker before finished
    ReadyPipe ready;
  };
  static void Load(Shared& shared, const std::string& path, std::optional<UpAxis> upAxis,
                   LoadLimits limits);
  /// PrepareScene, stopped by the job's cancel flag (then a "cancelled" error).
  static void Prepare(Shared& shared, Mesh mesh, std::optional<UpAxis> upAxis);
  static void Finish(Shared& shared);

  std::string path_;
  std::shared_ptr<Shared> shared_;
  std::thread worker_;
};

}  // namespace termshade
