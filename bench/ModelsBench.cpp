#include "ModelsBench.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <tuple>

#include "FrameTiming.h"
#include "io/load/ModelLoader.h"

namespace termshade {
namespace {

// Tabs and newlines of a message would break the row.
std::string OneField(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\t' || c == '\n'; }, ' ');
  return SanitizeForTerminal(text);
}

size_t DistinctColours(std::vector<Rgb> colours) {
  std::sort(colours.begin(), colours.end(), [](const Rgb& a, const Rgb& b) {
    return std::tie(a.r, a.g, a.b) < std::tie(b.r, b.g, b.b);
  });
  return static_cast<size_t>(std::unique(colours.begin(), colours.end()) - colours.begin());
}

}  // namespace

int RunModelsBench(const ModelsBenchOptions& options) {
  std::cout << "file\tloads\tvertices\tfaces\ttriangles\tup_axis\tfaces_turned_outward\t"
               "face_colours\tframe_ms\terror\n";
  int exitCode = 0;
  for (const std::string& path : options.modelPaths) {
    Loaded<Mesh> mesh = LoadModelFile(path);
    if (!mesh.Ok()) {
      std::cout << OneField(path) << "\tno\t\t\t\t\t\t\t\t" << OneField(mesh.Error().message)
                << "\n";
      exitCode = 1;
      continue;
    }
    const size_t vertices = mesh.Value().verticesFile.size();
    const size_t colours = DistinctColours(mesh.Value().faceColors);
    const Scene scene = PrepareScene(std::move(mesh.Value()), options.upAxis);
    const double frameMs = MedianTurntableFrameMs(scene, options.widthCells, options.heightCells);
    char timing[32];
    std::snprintf(timing, sizeof timing, "%.3f", frameMs);
    std::cout << OneField(path) << "\tyes\t" << vertices << "\t" << scene.FaceCount() << "\t"
              << scene.triangles.size() << "\t" << UpAxisName(scene.upAxis) << "\t"
              << scene.facesTurnedOutward << "\t" << colours << "\t" << timing << "\t\n";
  }
  return exitCode;
}

}  // namespace termshade
