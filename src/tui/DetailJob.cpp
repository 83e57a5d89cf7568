#include "tui/DetailJob.h"

#include "geometry/HeapPolicy.h"

namespace termshade {

DetailJob::DetailJob(std::shared_ptr<const Scene> scene)
    : scene_(std::move(scene)), shared_(std::make_shared<Shared>()) {
  worker_ = StartWorkerThread([shared = shared_, scene = scene_]() mutable {
    DetailBuildOptions options;
    options.cancel = &shared->cancel;
    shared->result = std::make_shared<const DetailLevels>(BuildDetailLevels(*scene, options));
    shared->finished.store(true);
    shared->ready.Notify();
    // Abandoned (see ~DetailJob): nobody takes the levels; the scene may be the last reference.
    if (shared->cancel.load()) {
      shared->result.reset();
      scene.reset();
      ReturnFreedMemory();
    }
  });
}

std::shared_ptr<const DetailLevels> DetailJob::Take() {
  if (worker_.joinable()) worker_.join();
  shared_->ready.Drain();
  return std::move(shared_->result);
}

DetailJob::~DetailJob() {
  if (!worker_.joinable()) return;
  // Cancel before looking at finished, as the worker sets finished before looking at cancel:
  // one of the two sees the other's store, so an abandoned worker always returns its memory.
  shared_->cancel.store(true);
  if (Finished()) {
    worker_.join();
  } else {
    worker_.detach();  // it holds its own references to the scene and the shared state
  }
}

}  // namespace termshade
