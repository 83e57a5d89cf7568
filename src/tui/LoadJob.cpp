#include "tui/LoadJob.h"

#include <poll.h>

#include <chrono>

#include "io/load/ModelLoader.h"
#include "process/HeapPolicy.h"
#include "tui/ViewerState.h"

namespace termshade {

LoadJob::LoadJob(std::string path, std::optional<UpAxis> upAxis, LoadLimits limits)
    : path_(std::move(path)), shared_(std::make_shared<Shared>()) {
  // The worker holds its own reference to the shared state (see ~LoadJob).
  worker_ = StartWorkerThread([shared = shared_, path = path_, upAxis, limits] {
    Load(*shared, path, upAxis, limits);
    Finish(*shared);
  });
}

LoadJob::LoadJob(std::string path, std::shared_ptr<const Scene> scene, UpAxis upAxis)
    : path_(std::move(path)), shared_(std::make_shared<Shared>()) {
  shared_->preparing.store(true);
  worker_ = StartWorkerThread([shared = shared_, scene = std::move(scene), upAxis]() mutable {
    Mesh mesh = scene->SourceMesh();  // the shown scene stays whole until the new one replaces it
    scene.reset();
    Prepare(*shared, std::move(mesh), upAxis);
    Finish(*shared);
  });
}

void LoadJob::Load(Shared& shared, const std::string& path, std::optional<UpAxis> upAxis,
                   LoadLimits limits) {
  LoadOptions options(limits);
  options.cancel = &shared.cancel;
  options.progress = [&shared](double share) { shared.progress.store(share); };
  Loaded<Mesh> mesh = LoadViewerMesh(path, options);
  if (mesh.Ok()) {
    shared.preparing.store(true);
    Prepare(shared, std::move(mesh.Value()), upAxis);
  } else {
    shared.result.emplace(mesh.Error());
  }
}

void LoadJob::Prepare(Shared& shared, Mesh mesh, std::optional<UpAxis> upAxis) {
  std::optional<Scene> scene = PrepareScene(std::move(mesh), upAxis, shared.cancel);
  if (scene) {
    shared.result.emplace(std::move(*scene));
  } else {
    shared.result.emplace(LoadError{"", 0, 0, "cancelled"});  // dropped by the canceller
  }
}

void LoadJob::Finish(Shared& shared) {
  shared.finished.store(true);
  shared.ready.Notify();
  // Abandoned (see ~LoadJob): nobody takes the result, so its memory goes back now.
  if (shared.cancel.load()) {
    shared.result.reset();
    ReturnFreedMemory();
  }
}

Loaded<Scene> LoadJob::Take() {
  if (worker_.joinable()) worker_.join();
  shared_->ready.Drain();
  if (!shared_->result) return LoadError{path_, 0, 0, "the load did not finish"};
  Loaded<Scene> result = std::move(*shared_->result);
  shared_->result.reset();
  return result;
}

bool LoadJob::Stop() {
  // Cancel before looking at finished, as Finish sets finished before looking at cancel:
  // one of the two sees the other's store, so an abandoned worker always returns its memory.
  Cancel();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(kStopWaitMs);
  while (!Finished()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd ready{ReadyFd(), POLLIN, 0};
    poll(&ready, 1, static_cast<int>(left.count()));
  }
  return Finished();
}

LoadJob::~LoadJob() {
  if (!worker_.joinable()) return;
  if (Stop()) {
    worker_.join();
  } else {
    worker_.detach();  // it holds its own reference to the shared state
  }
}

}  // namespace termshade
