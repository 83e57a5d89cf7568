#pragma once

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace termshade {

/// Jobs (LoadJob, SceneJob) asked to stop that may still be running, kept
/// until their workers end instead of detached: the viewer starts no new load
/// or build while one unwinds, so cancelled workers never pile up.
class RetiredJobs {
 public:
  /// Cancels the job and keeps it until it has finished (a finished one is
  /// joined and dropped at once).
  template <typename Job>
  void Keep(std::unique_ptr<Job> job) {
    if (!job) return;
    job->Cancel();
    if (job->Finished()) return;
    Job* raw = job.get();
    jobs_.push_back({[raw] { return raw->Finished(); }, std::shared_ptr<void>(std::move(job))});
  }
  /// Drops (joins) the jobs that have ended; true while one still runs.
  bool Busy();
  /// How many are still kept.
  size_t Count() const { return jobs_.size(); }

 private:
  struct Entry {
    std::function<bool()> finished;
    std::shared_ptr<void> job;  ///< its destructor joins a finished worker
  };
  std::vector<Entry> jobs_;
};

}  // namespace termshade
