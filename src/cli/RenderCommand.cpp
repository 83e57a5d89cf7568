#include "cli/RenderCommand.h"

#include <langinfo.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "cli/RenderBudget.h"
#include "geometry/FitCamera.h"
#include "geometry/LevelOfDetail.h"
#include "geometry/RayBvh.h"
#include "io/load/ExtrasBudget.h"
#include "io/load/ModelExtensions.h"
#include "io/load/ModelLoader.h"
#include "io/write/AnsiCells.h"
#include "io/write/AsciicastRecording.h"
#include "io/write/FrameFormats.h"
#include "io/write/OutputFile.h"
#include "io/write/SvgFrame.h"
#include "raster/DetailPick.h"
#include "raster/RayCastStage.h"
#include "raster/Renderer.h"
#include "shade/Lighting.h"
#include "tui/TerminalColours.h"

namespace termshade {
namespace {

// Frames of one scene from which render builds its hierarchy: at 2M
// triangles and 160x48 the build (0.7-0.9 s) costs about what 100 frames
// by rays save (render of the 2M sphere as PLY, 30 / 60 / 100 frames: 0.3 s
// slower, 0.35 s slower, the same wall time).
constexpr int kHierarchyFromFrames = 100;

// --glyphs auto: what the viewer picks for this terminal (TERM, TERM_PROGRAM,
// the locale's UTF-8), given whether the frames carry colour.
GlyphMode AutoGlyphs(bool colour) {
  std::setlocale(LC_CTYPE, "");
  const bool utf8 = std::string_view(nl_langinfo(CODESET)) == "UTF-8";
  const char* term = std::getenv("TERM");
  const char* termProgram = std::getenv("TERM_PROGRAM");
  return PickGlyphMode(utf8, colour, term != nullptr ? term : "",
                       termProgram != nullptr ? termProgram : "");
}

// The largest turntable step: with 100000 frames, theta stays below 1e11
// radians, where a double still resolves 1e-5.
constexpr double kMostStepRadians = 1e6;

int UsageError(const std::string& message) {
  std::cerr << "termshade render: " << message << "\n";
  return 2;
}

// The frame size: --size, else the terminal's when the frames go to one.
std::pair<int, int> FrameSizeCells(const RenderCommandOptions& options) {
  if (options.widthCells > 0 && options.heightCells > 0) {
    return {options.widthCells, options.heightCells};
  }
  winsize size{};
  if (options.outputPath.empty() && isatty(STDOUT_FILENO) == 1 &&
      ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 && size.ws_row > 1) {
    return {std::min<int>(size.ws_col, 4096), std::min<int>(size.ws_row - 1, 2048)};
  }
  return {kDefaultWidthCells, kDefaultHeightCells};
}

// What the frames are drawn into and written to, reused from model to model.
struct FrameSink {
  Renderer renderer;
  DepthBuffer depth;
  CellBuffer cells;
  Renderer centerRenderer;  ///< json of a glyph mode: the one-sample frame beside it
  DepthBuffer centerDepth;
  CellBuffer centerCells;
  std::string text;
  AnsiCells ansiCells;                       ///< the frame a recording is made from
  std::optional<AsciicastRecording> record;  ///< --format asciicast: the recording
  std::optional<OutputFile> file;            ///< unset: standard output
};

// What one frame becomes in the chosen format.
void AppendFrame(const Scene& scene, const Camera& camera, const RenderOptions& renderOptions,
                 FrameFormat format, ColourMode colourMode, Background background,
                 FrameSink& sink) {
  std::string& text = sink.text;
  if (format == FrameFormat::kText) AppendTextFrame(sink.cells, text);
  if (format == FrameFormat::kAnsi) {
    AppendAnsiFrame(sink.cells, scene.source.faceColors, renderOptions.ramp.LevelCount(),
                    colourMode, text, background);
  }
  if (format == FrameFormat::kSvg) {
    const SvgFrameStyle style{camera.projection.cellAspect, colourMode, background,
                              ThemeFor(background)};
    AppendSvgFrame(sink.cells, scene.source.faceColors, renderOptions.ramp.LevelCount(), style,
                   text);
  }
  if (format == FrameFormat::kAsciicast) {
    FillAnsiCells(sink.cells, scene.source.faceColors, renderOptions.ramp.LevelCount(), colourMode,
                  sink.ansiCells, background);
    sink.record->AppendFrame(sink.ansiCells, text);
  }
  if (format != FrameFormat::kJson) return;
  if (sink.renderer.LastSampleGrid().Count() <= 1) {
    AppendJsonFrame(sink.cells, sink.depth, scene, camera, renderOptions, text);
    return;
  }
  // Several samples a cell: faces and depth at the centers come from a one-sample frame.
  RenderOptions centerOptions = renderOptions;
  centerOptions.glyphs = GlyphMode::kRamp;
  centerOptions.variant.samples = {1, 1};
  sink.centerRenderer.Render(scene, camera, centerOptions, sink.centerDepth, sink.centerCells);
  const JsonSamples samples{sink.renderer.LastSampleGrid(), sink.renderer.Samples(),
                            sink.centerCells, sink.centerDepth};
  AppendJsonFrame(sink.cells, sink.depth, scene, camera, renderOptions, text, &samples);
}

// Frame `frame` of the turntable: theta advancing by the step, fitted as asked.
Camera FrameCamera(const Scene& scene, const RenderCommandOptions& options, int frame,
                   int widthCells, int heightCells) {
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  view.theta = options.theta + frame * options.stepRadians;
  view.phi = options.phi;
  if (options.rho > 0.0) view.rho = options.rho;
  const double fitRho =
      options.fitRho > 0.0 ? options.fitRho : DefaultView(scene.diagonalModelUnits).rho;
  const Framing framing = options.fit ? Framing::kOrbit : Framing::kSpec;
  return FitCameraAt(scene, view, fitRho, widthCells, heightCells, options.cellAspect, framing);
}

// The turntable of one model: options.frames frames. Returns the output's
// error, if any.
std::optional<std::string> WriteFrames(const Scene& scene, const DetailLevels* levels,
                                       const RenderCommandOptions& options,
                                       const RenderOptions& renderOptions, FrameFormat format,
                                       ColourMode colourMode, Background background,
                                       FrameSink& sink) {
  const int widthCells = sink.cells.WidthCells(), heightCells = sink.cells.HeightCells();
  for (int frame = 0; frame < options.frames; ++frame) {
    const Camera camera = FrameCamera(scene, options, frame, widthCells, heightCells);
    // --lod auto: a simplified copy where its triangles are far below a sample.
    const Scene& drawn = *PickDetail(levels, scene, camera, renderOptions).scene;
    sink.renderer.Render(drawn, camera, renderOptions, sink.depth, sink.cells);
    sink.text.clear();
    AppendFrame(drawn, camera, renderOptions, format, colourMode, background, sink);
    // The first failed write ends the run (a closed pipe, a full disk).
    if (auto problem =
            sink.file ? sink.file->Write(sink.text) : WriteWhole(STDOUT_FILENO, sink.text)) {
      return problem;
    }
  }
  return std::nullopt;
}

}  // namespace

int RunRenderCommand(const RenderCommandOptions& options) {
  const RenderBudget budget(options.budgetSeconds);  // from here: the command's start
  // Step 1: options that the parser could not check alone.
  const auto method = ParseMethod(options.method);
  if (!method) return UsageError("--method must be zbuffer, painter, cull, wire or auto");
  const auto shade = ParseShadeMode(options.shade);
  if (!shade) return UsageError("--shade must be contrast or lambert");
  const auto glyphs =
      options.glyphs == "auto" ? std::optional(GlyphMode::kRamp) : ParseGlyphMode(options.glyphs);
  if (!glyphs)
    return UsageError("--glyphs must be ramp, ascii, blocks, quadrants, sextants, braille or auto");
  const auto detail = ParseDetailMode(options.lod.empty() ? "off" : options.lod);
  if (!detail) return UsageError("--lod must be auto or off");
  const auto format = ParseFrameFormat(options.format);
  if (!format) return UsageError("--format must be text, ansi, json, svg or asciicast");
  if (*format == FrameFormat::kSvg && options.frames * options.modelPaths.size() > 1)
    return UsageError("--format svg draws one frame: one model and --frames 1");
  if (!std::isfinite(options.framesPerSecond) || options.framesPerSecond <= 0.0)
    return UsageError("--fps must be a positive number");
  if (const auto problem = ShadeRamp::Problem(options.ramp))
    return UsageError("--ramp: " + *problem);
  const auto colourMode = options.mono
                              ? std::optional(ColourMode::kNone)
                              : ParseColourMode(options.colour.empty() ? "256" : options.colour);
  if (!colourMode) return UsageError("--color must be none, 16, 256, truecolor or auto");
  const auto background = ParseBackground(options.background.empty() ? "dark" : options.background);
  if (!background) return UsageError("--background must be dark or light");
  if (!std::isfinite(options.theta) || !std::isfinite(options.phi) ||
      !std::isfinite(options.stepRadians) || !std::isfinite(options.rho) || options.rho < 0.0) {
    return UsageError("--theta, --phi and --step must be finite, --rho finite and positive");
  }
  // Every frame's theta stays a finite, meaningful angle (1e308 twice over is infinite).
  if (std::fabs(options.stepRadians) > kMostStepRadians) {
    return UsageError("--step: must be at most 1e6 radians either way");
  }
  if (!options.inputFormat.empty()) {
    const std::vector<std::string> known = ModelFileExtensions();
    std::string format =
        options.inputFormat.front() == '.' ? options.inputFormat.substr(1) : options.inputFormat;
    std::transform(format.begin(), format.end(), format.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (!std::binary_search(known.begin(), known.end(), format)) {
      std::string list;
      for (const std::string& extension : known) list += (list.empty() ? "" : " ") + extension;
      return UsageError("--input-format: unknown format '" +
                        SanitizeForTerminal(options.inputFormat) + "' (known: " + list + ")");
    }
  }
  for (const std::string& modelPath : options.modelPaths) {
    if (!options.outputPath.empty() && modelPath != "-" &&
        SameFile(options.outputPath, modelPath)) {
      return UsageError("-o " + SanitizeForTerminal(options.outputPath) +
                        " is the model itself; refusing to overwrite it");
    }
  }

  // Step 2: the output, opened once a model has loaded (a bad model leaves no
  // file): a file replaced whole (never half-written), or stdout.
  FrameSink sink;
  const auto outputFailed = [&](const std::string& why) {
    std::cerr << (options.outputPath.empty() ? "termshade render: standard output"
                                             : SanitizeForTerminal(options.outputPath))
              << ": " << SanitizeForTerminal(why) << "\n";
    return 1;
  };
  bool opened = false;
  const auto openOutput = [&]() -> std::optional<std::string> {
    if (opened || options.outputPath.empty()) return std::nullopt;
    opened = true;
    sink.file.emplace(options.outputPath);
    auto problem = sink.file->Open();
    if (!problem && !sink.file->InPlaceReason().empty()) {
      std::cerr << "termshade render: note: " << SanitizeForTerminal(options.outputPath)
                << " is written in place, not replaced whole: "
                << SanitizeForTerminal(sink.file->InPlaceReason()) << "\n";
    }
    return problem;
  };

  // Step 3: each model's frames, one model after another; a model that
  // cannot be read is reported and the others are still drawn.
  RenderOptions renderOptions;
  renderOptions.method = *method;
  renderOptions.shade = *shade;
  renderOptions.ramp = ShadeRamp(options.ramp);
  // Text and json have no colours; ansi and the pictures made from it do,
  // unless --color none asks for none (then their glyphs are the mono ones).
  renderOptions.twoColour = (*format == FrameFormat::kAnsi || *format == FrameFormat::kSvg ||
                             *format == FrameFormat::kAsciicast) &&
                            ResolveColourMode(*colourMode) != ColourMode::kNone;
  renderOptions.glyphs = options.glyphs == "auto" ? AutoGlyphs(renderOptions.twoColour) : *glyphs;
  // (json reports SPEC's intensities, not ink: never turned for a light background.)
  renderOptions.background = *format == FrameFormat::kJson ? Background::kDark : *background;
  renderOptions.cullBackFaces = !options.noCull;
  // (Textures colour cells: not a frame without colours.)
  renderOptions.textures =
      options.textures != "off" && ResolveColourMode(*colourMode) != ColourMode::kNone;
  if (options.lightRadians)
    renderOptions.sunEye = SunFromAngles(options.lightRadians->first, options.lightRadians->second);
  renderOptions.threads = options.threads;
  renderOptions.keepDepth = *format == FrameFormat::kJson;  // only json dumps depth
  const auto [widthCells, heightCells] = FrameSizeCells(options);
  sink.depth.Resize(widthCells, heightCells);
  sink.cells.Resize(widthCells, heightCells);
  sink.centerDepth.Resize(widthCells, heightCells);
  sink.centerCells.Resize(widthCells, heightCells);
  if (*format == FrameFormat::kAsciicast)
    sink.record.emplace(widthCells, heightCells, options.framesPerSecond, ThemeFor(*background));
  LoadOptions loadOptions(options.loadLimits);
  loadOptions.formatHint = options.inputFormat;
  loadOptions.importerOnly = options.reader == "assimp";
  int exitCode = 0;
  for (const std::string& modelPath : options.modelPaths) {
    Loaded<Mesh> mesh = LoadModelFile(modelPath, loadOptions);
    if (!mesh.Ok()) {
      std::cerr << mesh.Error().ToString() << "\n";
      exitCode = 1;
      continue;
    }
    const Scene exact = PrepareScene(std::move(mesh.Value()), options.upAxis);
    // --budget: a clustered copy where the exact frames would not fit in what is left.
    std::optional<DetailLevel> coarse;
    if (*method != Method::kWire &&
        !budget.ExactFits(exact.triangles.size(), options.frames, *method)) {
      coarse.emplace(ClusteredLevelFor(
          exact, FrameCamera(exact, options, 0, widthCells, heightCells), renderOptions));
      std::cerr << budget.CoarseNote(SanitizeForTerminal(modelPath), exact.triangles.size(),
                                     coarse->scene.triangles.size(), options.frames, *method)
                << "\n";
    }
    const Scene& scene = coarse ? coarse->scene : exact;
    const size_t budgetBytes = loadOptions.memoryBudgetBytes;
    // A long turntable of a big scene: the hierarchy pays for its build (same
    // frames). Built on this thread, so only where the rays were quicker, and
    // only within the memory budget.
    if (options.frames >= kHierarchyFromFrames && *detail == DetailMode::kOff &&
        RayCastStage::WouldCast(scene, widthCells, heightCells, renderOptions,
                                RayCastStage::kFasterFromTrianglesPerSample) &&
        !ExtraOverBudget("the ray hierarchy", EstimateRayBvhBytes(scene), scene, 0, budgetBytes)) {
      scene.hierarchy.Attach(std::make_shared<const RayBvh>(BuildRayBvh(scene)));
    }
    std::optional<DetailLevels> levels;
    if (*detail == DetailMode::kAuto && !coarse) {
      // Levels beyond the budget are left out: the exact frames, said once.
      if (const auto reason = ExtraOverBudget("level of detail", EstimateDetailBuildBytes(scene),
                                              scene, 0, budgetBytes)) {
        std::cerr << "termshade render: note: " << SanitizeForTerminal(modelPath) << ": " << *reason
                  << "\n";
      } else {
        levels.emplace(BuildDetailLevels(scene));
      }
    }
    if (const auto problem = openOutput()) return outputFailed(*problem);
    if (const auto problem =
            WriteFrames(scene, levels ? &*levels : nullptr, options, renderOptions, *format,
                        ResolveColourMode(*colourMode), *background, sink)) {
      return outputFailed(*problem);
    }
  }

  // Step 4: a recording's closing event, then the file committed whole
  // (stdout was written frame by frame).
  if (sink.record) {
    sink.text.clear();
    sink.record->AppendEnd(sink.text);
    if (const auto problem =
            sink.file ? sink.file->Write(sink.text) : WriteWhole(STDOUT_FILENO, sink.text)) {
      return outputFailed(*problem);
    }
  }

  if (sink.file) {
    if (const auto problem = sink.file->Commit()) return outputFailed(*problem);
  }
  return exitCode;
}

}  // namespace termshade
