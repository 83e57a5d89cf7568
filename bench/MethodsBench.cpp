#include "MethodsBench.h"

#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "SpeedErrorPlot.h"
#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "geometry/RayCast.h"
#include "geometry/ViewingTransform.h"
#include "io/load/ModelLoader.h"
#include "io/read/LoadError.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/DetailPick.h"
#include "raster/FrameError.h"
#include "raster/FrameFidelity.h"
#include "raster/Renderer.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

struct MethodCase {
  MethodCase(std::string name, RenderOptions options, bool measuresFaces = true,
             bool plotted = true, std::optional<double> lodSamplesPerTriangle = std::nullopt)
      : name(std::move(name)),
        options(std::move(options)),
        measuresFaces(measuresFaces),
        plotted(plotted),
        lodSamplesPerTriangle(lodSamplesPerTriangle) {}
  std::string name;
  RenderOptions options;
  bool measuresFaces = true;  ///< supersampled variants have no single sample per cell
  bool plotted = true;        ///< the noise control repeats the default: table only
  /// Set: a level of detail where the mean projected triangle reaches this many samples.
  std::optional<double> lodSamplesPerTriangle;
};

std::vector<MethodCase> Methods() {
  auto with = [](Method method, auto change) {
    RenderOptions options;
    options.method = method;
    options.shade = ShadeMode::kLambert;  // stable across frames: shade error means something
    options.keepDepth = false;            // as the viewer draws
    options.threads = 1;                  // methods against methods; bench frame times threads
    change(options.variant);
    return options;
  };
  auto same = [](RenderVariant&) {};
  return {
      {"zbuffer (1/z float, default)", with(Method::kZBuffer, same)},
      {"zbuffer again (noise control)", with(Method::kZBuffer, same), true, false},
      {"auto", with(Method::kAuto, same)},
      {"cull", with(Method::kCull, same)},
      {"painter", with(Method::kPainter, same)},
      {"zbuffer linear z",
       with(Method::kZBuffer, [](RenderVariant& v) { v.depthFormat = DepthFormat::kLinearZ; })},
      {"zbuffer 1/z 16-bit fixed",
       with(Method::kZBuffer,
            [](RenderVariant& v) { v.depthFormat = DepthFormat::kFixed16InverseZ; })},
      {"zbuffer scanline", with(Method::kZBuffer, [](RenderVariant& v) { v.scanline = true; })},
      {"zbuffer float geometry",
       with(Method::kZBuffer, [](RenderVariant& v) { v.floatGeometry = true; })},
      {"zbuffer 2x2 samples",
       with(Method::kZBuffer,
            [](RenderVariant& v) {
              v.samples = {2, 2};
            }),
       false},
      {"zbuffer 4x4 samples",
       with(Method::kZBuffer,
            [](RenderVariant& v) {
              v.samples = {4, 4};
            }),
       false},
      {"lod auto (1/4 sample a tri)", with(Method::kZBuffer, same), true, true,
       DetailTarget{}.samplesPerTriangle},
      {"lod coarse (1 sample a tri)", with(Method::kZBuffer, same), true, true, 1.0},
  };
}

struct NamedScene {
  std::string name;
  Scene scene;
  bool nearlyHeadOn = false;  ///< views within a few degrees of the +x axis, not a turntable
  DetailLevels levels{};      ///< built by Scenes
  double levelsBuildSeconds = 0.0;
};

// The scene a method draws in this view: the exact one, or its level of detail.
const Scene& DrawnScene(const NamedScene& named, const MethodCase& method, const Camera& camera) {
  if (!method.lodSamplesPerTriangle) return named.scene;
  return *PickDetail(&named.levels, named.scene, camera, method.options,
                     *method.lodSamplesPerTriangle)
              .scene;
}

Mesh CrossingQuads() {
  Mesh mesh;
  mesh.verticesFile = {{-1, -1, -1}, {1, -1, 1}, {1, 1, 1},  {-1, 1, -1},
                       {-1, -1, 1},  {-1, 1, 1}, {1, 1, -1}, {1, -1, -1}};
  for (uint32_t base : {0U, 4U}) {
    mesh.AddFace(std::array<uint32_t, 4>{base, base + 1, base + 2, base + 3});
    mesh.AddFace(std::array<uint32_t, 4>{base + 3, base + 2, base + 1, base});
  }
  return mesh;
}

// A large plate and a smaller one `gap` in front of it, both facing +x.
Mesh ParallelPlates(double gap) {
  Mesh mesh;
  mesh.verticesFile = {{0, -2, -2},   {0, 2, -2},   {0, 2, 2},   {0, -2, 2},
                       {gap, -1, -1}, {gap, 1, -1}, {gap, 1, 1}, {gap, -1, 1}};
  mesh.AddFace(std::array<uint32_t, 4>{0, 1, 2, 3});
  mesh.AddFace(std::array<uint32_t, 4>{4, 5, 6, 7});
  return mesh;
}

std::vector<NamedScene> Scenes(const std::string& dataDirectory) {
  std::vector<NamedScene> scenes;
  for (const char* name : {"cube", "beams", "letter_l", "surface", "sphere_cone"}) {
    Loaded<Mesh> mesh = LoadModelFile(dataDirectory + "/" + name + ".dat");
    if (!mesh.Ok()) {
      std::cerr << mesh.Error().ToString() << "\n";
      continue;
    }
    scenes.push_back({name, PrepareScene(std::move(mesh.Value()))});
  }
  scenes.push_back({"crossing quads", PrepareScene(CrossingQuads())});
  scenes.push_back({"plates gap 1e-4", PrepareScene(ParallelPlates(1e-4)), true});
  scenes.push_back({"sphere 20k tris", PrepareScene(GenerateSphere(100, 100))});
  scenes.push_back({"sphere 200k tris", PrepareScene(GenerateSphere(317, 317))});
  scenes.push_back({"sphere 2M tris", PrepareScene(GenerateTriangleSphere(2000000))});
  for (NamedScene& named : scenes) {
    const auto start = Clock::now();
    named.levels = BuildDetailLevels(named.scene);
    named.levelsBuildSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return scenes;
}

// Reference shade of each cell: the mean Lambert intensity of 4 x 4 exact ray
// casts (background 0), as a ramp level (-1 for a blank cell).
std::vector<double> ReferenceLevels(const Scene& scene, const Camera& camera,
                                    const RenderOptions& options, int width, int height) {
  ReferenceRayCaster exact(scene, camera, options.cullBackFaces);
  exact.BinFaces(width, height);
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  const Vec3 eyeWorld = EyePositionWorld(camera.view);
  std::vector<double> levels(static_cast<size_t>(width) * height, -1.0);
  constexpr int kSamples = 4;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      double sum = 0.0;
      int covered = 0;
      for (int j = 0; j < kSamples; ++j) {
        for (int i = 0; i < kSamples; ++i) {
          const RaySample hit = exact.Cast(col + (i + 0.5) / kSamples, row + (j + 0.5) / kSamples);
          if (hit.faceNumber == 0) continue;
          ++covered;
          const size_t f = hit.faceNumber - 1;
          const Vec3 n = scene.facePlanesWorld[f].normal;
          const bool front = scene.facePlanesWorld[f].FacesPoint(eyeWorld);
          const Vec3 nEye = TransformDirection(eyeFromWorld, front ? n : -n);
          sum += LambertIntensity(Dot(nEye, options.sunEye), options.ambient);
        }
      }
      if (covered > 0) {
        levels[static_cast<size_t>(row) * width + col] =
            options.ramp.LevelFor(sum / (kSamples * kSamples));
      }
    }
  }
  return levels;
}

struct CaseResult {
  double medianMs = 0.0;
  double ssim = 0.0;           ///< blurred SSIM against the exact image (SPEC 12), views 0 and 1
  double meanTriangles = 0.0;  ///< of the scene drawn
  double faceError = 0.0;      ///< share of compared cells; < 0 when not measured
  double shadeErrorLevels = 0.0;
  int compared = 0;
};

// Frame times of every method: the median in milliseconds and, against the
// default (method 0), the median over turns of the ratio of the two methods'
// medians within the turn.
struct MethodTiming {
  double medianMs = 0.0;
  double vsDefault = 1.0;
};

// Methods take turns, in a shuffled order, until the budget is spent, so drift and noise fall on
// all alike, and ratios pair frames drawn close together in time. Each turn
// draws the turntable once untimed (warming the caches the previous method
// cooled), then times it. One renderer and one pair of buffers serve every
// method, as in the viewer.
std::vector<MethodTiming> TimeMethods(const NamedScene& named,
                                      const std::vector<MethodCase>& methods,
                                      const std::vector<Camera>& cameras,
                                      const MethodsBenchOptions& options) {
  Renderer renderer;
  CellBuffer cells(options.widthCells, options.heightCells);
  DepthBuffer depth;
  depth.Resize(options.widthCells, options.heightCells);
  std::vector<std::vector<double>> allMs(methods.size());
  std::vector<std::vector<double>> turnMedianMs(methods.size());
  std::vector<double> turnMs;
  std::vector<size_t> order(methods.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::mt19937 shuffler(12345);
  const auto deadline =
      Clock::now() + std::chrono::duration<double>(options.secondsPerCase * methods.size());
  for (int turn = 0; turn < 3 || (Clock::now() < deadline && turn < 1000); ++turn) {
    // A new order each turn, so no method always follows the same one.
    std::shuffle(order.begin(), order.end(), shuffler);
    for (const size_t m : order) {
      turnMs.clear();
      for (int pass = 0; pass < 2; ++pass) {
        for (const Camera& camera : cameras) {
          const auto start = Clock::now();  // choosing the level is part of the frame
          renderer.Render(DrawnScene(named, methods[m], camera), camera, methods[m].options, depth,
                          cells);
          const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
          if (pass > 0) turnMs.push_back(ms);
        }
      }
      allMs[m].insert(allMs[m].end(), turnMs.begin(), turnMs.end());
      turnMedianMs[m].push_back(Median(turnMs));
    }
  }
  std::vector<MethodTiming> timings(methods.size());
  for (size_t m = 0; m < methods.size(); ++m) {
    std::vector<double> ratios;
    for (size_t t = 0; t < turnMedianMs[m].size(); ++t) {
      ratios.push_back(turnMedianMs[m][t] / turnMedianMs[0][t]);
    }
    timings[m] = {Median(std::move(allMs[m])), Median(std::move(ratios))};
  }
  return timings;
}

// Face and shade error of one method on every frame.
CaseResult Measure(const NamedScene& named, const MethodCase& method,
                   const std::vector<std::vector<double>>& referenceLevels,
                   const std::vector<InkImage>& exactImages, const std::vector<Camera>& cameras,
                   const MethodsBenchOptions& options) {
  Renderer renderer;
  CellBuffer cells(options.widthCells, options.heightCells);
  DepthBuffer depth;
  depth.Resize(options.widthCells, options.heightCells);
  CaseResult result;
  // Error on every frame.
  long wrong = 0, compared = 0;
  double squared = 0.0;
  long cellsTotal = 0;
  const double inkRange = InkRange(method.options, false, DefaultInkTable());
  for (size_t f = 0; f < cameras.size(); ++f) {
    const Scene& drawn = DrawnScene(named, method, cameras[f]);
    result.meanTriangles += static_cast<double>(drawn.triangles.size()) / cameras.size();
    renderer.Render(drawn, cameras[f], method.options, depth, cells);
    if (f < exactImages.size()) {
      InkImage exact = exactImages[f];
      for (float& p : exact.pixels) p = static_cast<float>(p * inkRange);
      result.ssim +=
          CompareImages(exact, GlyphImage(cells, DefaultInkTable(), false), inkRange).ssim /
          exactImages.size();
    }
    // A level's faces are its own: the face error compares the exact scene's faces.
    if (method.measuresFaces && !method.lodSamplesPerTriangle) {
      const FaceErrorReport report =
          MeasureFaceError(named.scene, cameras[f], method.options.cullBackFaces, cells);
      wrong += report.wrongCells;
      compared += report.comparedCells;
    }
    for (size_t i = 0; i < cells.Levels().size(); ++i) {
      const double level = cells.FaceNumbers()[i] == 0 ? -1.0 : cells.Levels()[i];
      const double difference = level - referenceLevels[f][i];
      squared += difference * difference;
      ++cellsTotal;
    }
  }
  result.faceError = compared > 0 ? double(wrong) / compared : -1.0;
  result.compared = static_cast<int>(compared);
  result.shadeErrorLevels = std::sqrt(squared / std::max(1L, cellsTotal));
  return result;
}

}  // namespace

std::string MachineDescription() {
  utsname name{};
  uname(&name);
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return model + ", " + name.sysname + " " + name.release + ", 1 thread";
}

int RunMethodsBench(const MethodsBenchOptions& options) {
  const std::vector<NamedScene> scenes = Scenes(options.dataDirectory);
  if (scenes.size() < 3) {
    std::cerr << "termshade bench: run it from the source tree (or pass --data DIR)\n";
    return 1;
  }
  const std::vector<MethodCase> methods = Methods();
  std::ofstream csv(options.csvPath);
  if (!csv) {
    std::cerr << "termshade bench: cannot write " << SanitizeForTerminal(options.csvPath)
              << " (run it from the source tree, or pass --csv and --svg)\n";
    return 1;
  }
  csv << "scene,method,triangles,median_ms,time_vs_default,ns_per_cell,face_error,"
         "shade_error_levels,compared_cells,ssim,triangles_drawn\n";
  std::printf("termshade bench methods: %dx%d cells, %d turntable frames per scene, %s\n",
              options.widthCells, options.heightCells, options.frames,
              MachineDescription().c_str());
  std::printf("%-16s %-30s %9s %8s %9s %10s %9s %7s %9s\n", "scene", "method", "median ms",
              "x default", "ns/cell", "face err %", "shade RMS", "SSIM", "tris");
  std::vector<PlotPoint> points;
  for (const NamedScene& named : scenes) {
    // The same frames for every method: a turntable, alternating elevations.
    std::vector<Camera> cameras;
    std::vector<std::vector<double>> referenceLevels;
    std::vector<InkImage> exactImages;  // at ink range 1, for the first two views
    const double rho = DefaultView(named.scene.diagonalModelUnits).rho;
    RenderOptions lambert;
    lambert.shade = ShadeMode::kLambert;
    for (int f = 0; f < options.frames; ++f) {
      ViewParams view{rho, 0.3 + f * 2.0 * std::numbers::pi / options.frames, f % 2 ? 0.7 : 1.3};
      if (named.nearlyHeadOn) {
        view = {rho, 0.02 * std::sin(f), std::numbers::pi / 2 + 0.02 * std::cos(f)};
      }
      cameras.push_back(FitCamera(named.scene, view, options.widthCells, options.heightCells, 2.0));
      referenceLevels.push_back(ReferenceLevels(named.scene, cameras.back(), lambert,
                                                options.widthCells, options.heightCells));
      if (f < 2) {
        exactImages.push_back(ExactImage(named.scene, cameras.back(), lambert, options.widthCells,
                                         options.heightCells, 1.0));
      }
    }
    if (!named.levels.levels.empty()) {
      std::printf("%-16s levels of detail:", named.name.c_str());
      for (const DetailLevel& level : named.levels.levels) {
        std::printf(" %zu", level.scene.triangles.size());
      }
      std::printf(" triangles, built in %.2f s\n", named.levelsBuildSeconds);
    }
    const std::vector<MethodTiming> timings = TimeMethods(named, methods, cameras, options);
    for (size_t m = 0; m < methods.size(); ++m) {
      const MethodCase& method = methods[m];
      CaseResult result = Measure(named, method, referenceLevels, exactImages, cameras, options);
      result.medianMs = timings[m].medianMs;
      const double nsPerCell = 1e6 * result.medianMs / (options.widthCells * options.heightCells);
      char faceText[32] = "-";
      if (result.faceError >= 0)
        std::snprintf(faceText, sizeof faceText, "%.3f", 100 * result.faceError);
      const double vsDefault = timings[m].vsDefault;
      std::printf("%-16s %-30s %9.4f %8.2f %9.2f %10s %9.3f %7.4f %9.0f\n", named.name.c_str(),
                  method.name.c_str(), result.medianMs, vsDefault, nsPerCell, faceText,
                  result.shadeErrorLevels, result.ssim, result.meanTriangles);
      csv << '"' << named.name << "\",\"" << method.name << "\"," << named.scene.triangles.size()
          << ',' << result.medianMs << ',' << vsDefault << ',' << nsPerCell << ','
          << (result.faceError >= 0 ? std::to_string(result.faceError) : "") << ','
          << result.shadeErrorLevels << ',' << result.compared << ',' << result.ssim << ','
          << result.meanTriangles << "\n";
      if (method.plotted) {
        points.push_back(
            {named.name, method.name, result.medianMs, result.faceError, result.shadeErrorLevels});
      }
    }
  }
  WriteSpeedErrorPlot(points, MachineDescription(), options.svgPath);
  std::printf("wrote %s and %s\n", options.csvPath.c_str(), options.svgPath.c_str());
  return csv ? 0 : 1;
}

}  // namespace termshade
