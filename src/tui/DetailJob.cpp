#include "tui/DetailJob.h"

namespace termshade {

DetailJob::DetailJob(std::shared_ptr<const Scene> scene)
    : scene_(std::move(scene)), shared_(std::make_shared<Shared>()) {
  worker_ = StartWorkerThread([shared = shared_, scene = scene_] {
    DetailBuildOptions options;
    options.cancel = &shared->cancel;
    shared->result = std::make_shared<const DetailLevels>(BuildDetailLevels(*scene, options));
    shared->finished.store(true);
    shared->ready.Notify();
  });
}

std::shared_ptr<const DetailLevels> DetailJob::Take() {
  if (worker_.joinable()) worker_.join();
  shared_->ready.Drain();
  return std::move(shared_->result);
}

DetailJob::~DetailJob() {
  if (!worker_.joinable()) return;
  if (Finished()) {
    worker_.join();
  } else {
    shared_->cancel.store(true);
    worker_.detach();  // it holds its own references to the scene and the shared state
  }
}

}  // namespace termshade
