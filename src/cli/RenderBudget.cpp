#include "cli/RenderBudget.h"

#include <cstdio>

namespace termshade {
namespace {

// Seconds a triangle of an exact frame, about twice what 90 frames of the
// 2M-triangle sphere took at 80x24 on 2 cores (docs/exports.md#a-time-budget---budget):
// 3-11 ms a frame by zbuffer (whole clusters culled), 100-130 ms by painter (sorted).
constexpr double kFrameSecondsPerTriangle = 1.0e-8;
constexpr double kPainterSecondsPerTriangle = 1.2e-7;

std::string Seconds(double seconds) {
  char text[32];
  if (seconds < 1.0) {
    std::snprintf(text, sizeof text, "%.3g ms", seconds * 1e3);
  } else {
    std::snprintf(text, sizeof text, "%.2f s", seconds);
  }
  return text;
}

}  // namespace

RenderBudget::RenderBudget(double budgetSeconds)
    : budgetSeconds_(budgetSeconds), start_(std::chrono::steady_clock::now()) {}

double RenderBudget::SpentSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double RenderBudget::PredictedFrameSeconds(size_t triangles, Method method) {
  const double perTriangle =
      method == Method::kPainter ? kPainterSecondsPerTriangle : kFrameSecondsPerTriangle;
  return perTriangle * static_cast<double>(triangles);
}

bool RenderBudget::ExactFits(size_t triangles, long frames, Method method) const {
  if (!Limited() || triangles < kBudgetExactBelowTriangles) return true;
  return SpentSeconds() + static_cast<double>(frames) * PredictedFrameSeconds(triangles, method) <=
         budgetSeconds_;
}

std::string RenderBudget::CoarseNote(const std::string& modelName, size_t exactTriangles,
                                     size_t drawnTriangles, long frames, Method method) const {
  return "termshade render: note: " + modelName + ": --budget " + Seconds(budgetSeconds_) +
         ": drew a clustered copy (" + std::to_string(drawnTriangles) + " of " +
         std::to_string(exactTriangles) + " triangles): " + Seconds(SpentSeconds()) +
         " spent loading, the exact frame" + (frames > 1 ? "s" : "") + " predicted at " +
         Seconds(static_cast<double>(frames) * PredictedFrameSeconds(exactTriangles, method));
}

}  // namespace termshade
