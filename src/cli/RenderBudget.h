#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "raster/RenderOptions.h"

namespace termshade {

/// `render --budget`: the time the whole command may take (loading and
/// frames), from its start. Loading is not cut short (a previewer needs a
/// picture, and a model half loaded gives none); the frames are drawn from a
/// clustered copy when the exact ones, predicted from their triangles, would
/// not fit in what is left.
class RenderBudget {
 public:
  /// budgetSeconds 0: no budget (ExactFits is always true).
  explicit RenderBudget(double budgetSeconds);

  bool Limited() const { return budgetSeconds_ > 0.0; }
  double SpentSeconds() const;
  /// Whether `frames` exact frames of a scene of `triangles` still fit.
  bool ExactFits(size_t triangles, long frames, Method method) const;
  /// A frame's predicted cost: what the frames of a 2M-triangle sphere took
  /// on the development machine (docs/exports.md#a-time-budget---budget), per triangle.
  static double PredictedFrameSeconds(size_t triangles, Method method);
  /// The stderr note when a model's frames were drawn coarse.
  std::string CoarseNote(const std::string& modelName, size_t exactTriangles, size_t drawnTriangles,
                         long frames, Method method) const;

 private:
  double budgetSeconds_;
  std::chrono::steady_clock::time_point start_;
};

/// Scenes below this are always drawn exactly: their frames cost less than building a copy.
constexpr size_t kBudgetExactBelowTriangles = 20000;

}  // namespace termshade
