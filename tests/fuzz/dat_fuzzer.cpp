// libFuzzer target: any bytes through the .dat reader, and whatever it
// accepts through the whole pipeline (hostile geometry: NaN-free but huge,
// tiny, degenerate, self-intersecting) at a few views and sizes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/FitCamera.h"
#include "io/DatReader.h"
#include "raster/Renderer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace termshade;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Loaded<Mesh> mesh = ParseDat(text, "fuzz.dat");
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
