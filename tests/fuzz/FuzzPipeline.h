#pragma once

#include <utility>

#include "geometry/FitCamera.h"
#include "io/read/LoadError.h"
#include "raster/Renderer.h"

namespace termshade {

/// What both fuzzers do with a loaded mesh: its error made into text, or the
/// whole pipeline (every hidden-surface method, a normal view and one with the
/// eye inside the model) on a small frame. Always returns 0 (libFuzzer's rule).
inline int DrawEveryMethod(Loaded<Mesh>& mesh) {
  if (!mesh.Ok()) {
    (void)mesh.Error().ToString();
    return 0;
  }
  if (mesh.Value().faceCorners.size() > 20000) return 0;  // keep each run fast
  const Scene scene = PrepareScene(std::move(mesh.Value()));
  Renderer renderer;
  CellBuffer cells(23, 11);
  DepthBuffer depth;
  depth.Resize(23, 11);
  for (Method method : {Method::kZBuffer, Method::kPainter, Method::kWire, Method::kAuto}) {
    RenderOptions options;
    options.method = method;
    options.cullBackFaces = method != Method::kPainter;
    options.keepDepth = method != Method::kAuto;  // auto as the viewer draws it
    ViewParams view = DefaultView(scene.diagonalModelUnits);
    for (double rhoScale : {1.0, 0.05}) {  // the second puts the eye inside the model
      view.rho = DefaultView(scene.diagonalModelUnits).rho * rhoScale;
      view.theta += 0.7;
      renderer.Render(scene, FitCamera(scene, view, 23, 11, 2.0), options, depth, cells);
    }
  }
  return 0;
}

}  // namespace termshade
