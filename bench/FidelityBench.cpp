#include "FidelityBench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "FidelityScenes.h"
#include "MethodsBench.h"
#include "SpeedErrorPlot.h"
#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "io/read/LoadError.h"
#include "raster/FrameFidelity.h"
#include "raster/Renderer.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

struct ModeCase {
  GlyphMode mode;
  bool colour;
  bool textures = true;  ///< false: a textured scene drawn without (what textures bring)
  std::string Name() const {
    return std::string(GlyphModeName(mode)) + (colour ? " colour" : " mono") +
           (textures ? "" : " untextured");
  }
};

// Every mode, mono and colour; on a textured scene also each colour mode
// without its textures, against the same textured exact image.
std::vector<ModeCase> Cases(const Scene& scene) {
  std::vector<ModeCase> cases;
  for (int m = 0; m < kGlyphModeCount; ++m) {
    for (bool colour : {false, true}) cases.push_back({static_cast<GlyphMode>(m), colour});
    if (scene.textures.Colour()) cases.push_back({static_cast<GlyphMode>(m), true, false});
  }
  return cases;
}

RenderOptions OptionsFor(const ModeCase& c) {
  RenderOptions options;
  options.shade = ShadeMode::kLambert;  // the reference's shading
  options.keepDepth = false;            // as the viewer draws
  options.glyphs = c.mode;
  options.twoColour = c.colour;
  options.textures = c.textures;
  return options;
}

// Median frame time of every case in ms, the cases interleaved (one frame of
// each in turn, in a shuffled order) so that load from other processes falls
// on all of them alike.
std::vector<double> MedianFrameMs(const NamedScene& named, const std::vector<ModeCase>& cases,
                                  const std::vector<Camera>& cameras,
                                  const FidelityBenchOptions& bench) {
  struct Timed {
    Renderer renderer;
    CellBuffer cells;
    DepthBuffer depth;
    std::vector<double> ms;
  };
  std::vector<Timed> timed(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    timed[i].cells.Resize(bench.widthCells, bench.heightCells);
    timed[i].depth.Resize(bench.widthCells, bench.heightCells);
    for (const Camera& camera : cameras) {  // warm-up: scratch arrays, caches
      timed[i].renderer.Render(named.scene, camera, OptionsFor(cases[i]), timed[i].depth,
                               timed[i].cells);
    }
  }
  const auto deadline =
      Clock::now() + std::chrono::duration<double>(bench.secondsPerCase * cases.size());
  // A new order of the cases every round (fixed seed): no case always runs
  // straight after the same one, warm from its sibling's code and data.
  std::vector<size_t> order(cases.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::mt19937 shuffle(12345);
  for (int round = 0; round < 10 || (Clock::now() < deadline && round < 20000); ++round) {
    std::shuffle(order.begin(), order.end(), shuffle);
    for (const Camera& camera : cameras) {
      for (const size_t i : order) {
        const RenderOptions options = OptionsFor(cases[i]);
        const auto start = Clock::now();
        timed[i].renderer.Render(named.scene, camera, options, timed[i].depth, timed[i].cells);
        timed[i].ms.push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      }
    }
  }
  std::vector<double> medians;
  for (Timed& t : timed) medians.push_back(Median(std::move(t.ms)));
  return medians;
}

InkImage Scaled(const InkImage& image, double factor) {
  InkImage out = image;
  for (float& p : out.pixels) p = static_cast<float>(p * factor);
  return out;
}

struct CaseResult {
  double ms = 0.0, ssim = 0.0, mse = 0.0, ssimUnifont = 0.0, flicker = 0.0;
};

}  // namespace

int RunFidelityBench(const FidelityBenchOptions& options) {
  std::vector<NamedScene> scenes = FidelityScenes(options.dataDirectory);
  if (scenes.size() < 3) {
    std::cerr << "termshade bench: run it from the source tree (or pass --data DIR)\n";
    return 1;
  }
  if (!options.sceneName.empty()) {
    std::erase_if(scenes, [&](const NamedScene& s) { return s.name != options.sceneName; });
    if (scenes.empty()) {
      std::cerr << "termshade bench: no scene named " << options.sceneName << "\n";
      return 2;
    }
  }
  const int cols = options.widthCells, rows = options.heightCells;
  std::ofstream csv;
  if (!options.timingOnly) csv.open(options.csvPath);
  if (!options.timingOnly && !csv) {
    std::cerr << "termshade bench: cannot write " << SanitizeForTerminal(options.csvPath)
              << " (run it from the source tree, or pass --csv and --svg)\n";
    return 1;
  }
  if (!options.timingOnly)
    csv << "scene,mode,median_ms,time_vs_ramp,ssim,mse,ssim_unifont,flicker\n";
  std::printf(
      "termshade bench fidelity: %dx%d cells, %d views per scene, blurred SSIM and MSE "
      "against the exact 8x16-per-cell image, %s\n",
      cols, rows, options.frames, MachineDescription().c_str());
  std::printf("%-15s %-28s %9s %7s %7s %9s %8s %9s\n", "scene", "mode", "median ms", "x ramp",
              "SSIM", "MSE", "SSIM uf", "flicker %");
  std::vector<FidelityPoint> points;
  for (const NamedScene& named : scenes) {
    // Step 1: the views and their exact images (at ink range 1; scaled per mode).
    std::vector<Camera> cameras, nudged;
    std::vector<InkImage> exact;
    const double rho = DefaultView(named.scene.diagonalModelUnits).rho;
    for (int f = 0; f < options.frames; ++f) {
      ViewParams view{rho, 0.3 + f * 2.0 * std::numbers::pi / options.frames, f % 2 ? 0.9 : 1.3};
      cameras.push_back(FitCamera(named.scene, view, cols, rows, 2.0));
      view.theta += 0.01;
      nudged.push_back(FitCamera(named.scene, view, cols, rows, 2.0));
      if (options.timingOnly) continue;
      exact.push_back(ExactImage(named.scene, cameras.back(), OptionsFor({GlyphMode::kRamp, true}),
                                 cols, rows, 1.0));
    }
    // Step 2: every mode's frame time, interleaved, then its fidelity on those views.
    const std::vector<ModeCase> cases = Cases(named.scene);
    const std::vector<double> medianMs = MedianFrameMs(named, cases, cameras, options);
    double rampMs[2] = {0.0, 0.0};
    for (size_t i = 0; i < cases.size(); ++i) {
      if (cases[i].mode == GlyphMode::kRamp && cases[i].textures) {
        rampMs[cases[i].colour ? 1 : 0] = medianMs[i];
      }
    }
    for (size_t i = 0; i < cases.size(); ++i) {
      const ModeCase& c = cases[i];
      const RenderOptions renderOptions = OptionsFor(c);
      CaseResult result;
      result.ms = medianMs[i];
      if (options.timingOnly) {
        std::printf("%-15s %-28s %9.4f %7.2f\n", named.name.c_str(), c.Name().c_str(), result.ms,
                    result.ms / rampMs[c.colour ? 1 : 0]);
        continue;
      }
      Renderer renderer;
      CellBuffer cells(cols, rows), moved(cols, rows);
      DepthBuffer depth;
      depth.Resize(cols, rows);
      for (size_t f = 0; f < cameras.size(); ++f) {
        renderer.Render(named.scene, nudged[f], renderOptions, depth, moved);
        renderer.Render(named.scene, cameras[f], renderOptions, depth, cells);
        result.flicker += ChangedShare(cells, moved, c.colour) / cameras.size();
        for (const GlyphInkTable* table : {&DefaultInkTable(), &UnifontInkTable()}) {
          const double range = InkRange(renderOptions, c.colour, *table);
          const Fidelity fidelity =
              CompareImages(Scaled(exact[f], range), GlyphImage(cells, *table, c.colour), range);
          if (table == &DefaultInkTable()) {
            result.ssim += fidelity.ssim / cameras.size();
            result.mse += fidelity.mse / cameras.size();
          } else {
            result.ssimUnifont += fidelity.ssim / cameras.size();
          }
        }
      }
      const double vsRamp = result.ms / rampMs[c.colour ? 1 : 0];
      std::printf("%-15s %-28s %9.4f %7.2f %7.4f %9.6f %8.4f %9.2f\n", named.name.c_str(),
                  c.Name().c_str(), result.ms, vsRamp, result.ssim, result.mse, result.ssimUnifont,
                  100 * result.flicker);
      csv << '"' << named.name << "\",\"" << c.Name() << "\"," << result.ms << ',' << vsRamp << ','
          << result.ssim << ',' << result.mse << ',' << result.ssimUnifont << ',' << result.flicker
          << "\n";
      if (c.textures) points.push_back({named.name, c.Name(), result.ms, result.ssim});
    }
    std::fflush(stdout);
  }
  if (options.timingOnly) return 0;
  WriteSpeedFidelityPlot(points, MachineDescription(), options.svgPath);
  std::printf("wrote %s and %s\n", options.csvPath.c_str(), options.svgPath.c_str());
  return csv ? 0 : 1;
}

}  // namespace termshade
