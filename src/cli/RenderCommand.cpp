#include "cli/RenderCommand.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <iostream>

#include "geometry/FitCamera.h"
#include "io/FrameFormats.h"
#include "io/ModelLoader.h"
#include "io/OutputFile.h"
#include "raster/Renderer.h"
#include "tui/TerminalColours.h"

namespace termshade {
namespace {

int UsageError(const std::string& message) {
  std::cerr << "termshade render: " << message << "\n";
  return 2;
}

}  // namespace

int RunRenderCommand(const RenderCommandOptions& options) {
  // Step 1: options that the parser could not check alone.
  const auto method = ParseMethod(options.method);
  if (!method) return UsageError("--method must be zbuffer, painter, cull, wire or auto");
  const auto shade = ParseShadeMode(options.shade);
  if (!shade) return UsageError("--shade must be contrast or lambert");
  const auto glyphs = ParseGlyphMode(options.glyphs);
  if (!glyphs)
    return UsageError("--glyphs must be ramp, ascii, blocks, quadrants, sextants or braille");
  const auto format = ParseFrameFormat(options.format);
  if (!format) return UsageError("--format must be text, ansi or json");
  if (const auto problem = ShadeRamp::Problem(options.ramp))
    return UsageError("--ramp: " + *problem);
  const auto colourMode = options.mono
                              ? std::optional(ColourMode::kNone)
                              : ParseColourMode(options.colour.empty() ? "256" : options.colour);
  if (!colourMode) return UsageError("--color must be none, 256, truecolor or auto");
  if (!std::isfinite(options.theta) || !std::isfinite(options.phi) ||
      !std::isfinite(options.stepRadians) || !std::isfinite(options.rho) || options.rho < 0.0) {
    return UsageError("--theta, --phi and --step must be finite, --rho finite and positive");
  }

  if (!options.outputPath.empty() && options.modelPath != "-" &&
      SameFile(options.outputPath, options.modelPath)) {
    return UsageError("-o " + SanitizeForTerminal(options.outputPath) +
                      " is the model itself; refusing to overwrite it");
  }

  // Step 2: the model.
  LoadOptions loadOptions;
  loadOptions.formatHint = options.inputFormat;
  loadOptions.importerOnly = options.reader == "assimp";
  if (options.memoryBudgetBytes > 0) loadOptions.memoryBudgetBytes = options.memoryBudgetBytes;
  Loaded<Mesh> mesh = LoadModelFile(options.modelPath, loadOptions);
  if (!mesh.Ok()) {
    std::cerr << mesh.Error().ToString() << "\n";
    return 1;
  }
  const Scene scene = PrepareScene(std::move(mesh.Value()));

  // Step 3: the output: a file replaced whole (never half-written), or stdout.
  std::optional<OutputFile> file;
  const auto outputFailed = [&](const std::string& why) {
    std::cerr << SanitizeForTerminal(options.outputPath) << ": " << SanitizeForTerminal(why)
              << "\n";
    return 1;
  };
  if (!options.outputPath.empty()) {
    file.emplace(options.outputPath);
    if (const auto problem = file->Open()) return outputFailed(*problem);
  }

  // Step 4: the frames, one after another.
  RenderOptions renderOptions;
  renderOptions.method = *method;
  renderOptions.shade = *shade;
  renderOptions.ramp = ShadeRamp(options.ramp);
  renderOptions.glyphs = *glyphs;
  renderOptions.twoColour = *format == FrameFormat::kAnsi;  // text and json have no colours
  renderOptions.cullBackFaces = !options.noCull;
  renderOptions.keepDepth = *format == FrameFormat::kJson;  // only json dumps depth
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  view.theta = options.theta;
  view.phi = options.phi;
  if (options.rho > 0.0) view.rho = options.rho;

  Renderer renderer;
  DepthBuffer depth;
  CellBuffer cells;
  depth.Resize(options.widthCells, options.heightCells);
  cells.Resize(options.widthCells, options.heightCells);
  Renderer centerRenderer;  // json of a glyph mode: the one-sample frame beside it
  RenderOptions centerOptions = renderOptions;
  centerOptions.glyphs = GlyphMode::kRamp;
  centerOptions.variant.samples = {1, 1};
  CellBuffer centerCells(options.widthCells, options.heightCells);
  DepthBuffer centerDepth;
  centerDepth.Resize(options.widthCells, options.heightCells);
  std::string text;
  for (int frame = 0; frame < options.frames; ++frame) {
    ViewParams frameView = view;
    frameView.theta = view.theta + frame * options.stepRadians;
    const Camera camera =
        FitCamera(scene, frameView, options.widthCells, options.heightCells, options.cellAspect);
    renderer.Render(scene, camera, renderOptions, depth, cells);
    text.clear();
    if (*format == FrameFormat::kText) AppendTextFrame(cells, text);
    if (*format == FrameFormat::kAnsi) {
      AppendAnsiFrame(cells, scene.mesh.faceColors, renderOptions.ramp.LevelCount(),
                      ResolveColourMode(*colourMode), text);
    }
    if (*format == FrameFormat::kJson && renderer.LastSampleGrid().Count() > 1) {
      // Several samples a cell: faces and depth at the centers come from a one-sample frame.
      centerRenderer.Render(scene, camera, centerOptions, centerDepth, centerCells);
      const JsonSamples samples{renderer.LastSampleGrid(), renderer.Samples(), centerCells,
                                centerDepth};
      AppendJsonFrame(cells, depth, scene, camera, renderOptions, text, &samples);
    } else if (*format == FrameFormat::kJson) {
      AppendJsonFrame(cells, depth, scene, camera, renderOptions, text);
    }
    if (file) {
      if (const auto problem = file->Write(text)) return outputFailed(*problem);
    } else {
      std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
  }
  if (file) {
    if (const auto problem = file->Commit()) return outputFailed(*problem);
    return 0;
  }
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "termshade render: writing the frames to standard output failed\n";
    return 1;
  }
  return 0;
}

}  // namespace termshade
