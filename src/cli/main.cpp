// termshade: the command-line front end (SPEC 9). Parses arguments and hands
// over to the viewer, the headless renderer or the scene generator.
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cmath>
#include <exception>
#include <iostream>
#include <regex>

#include "FidelityBench.h"
#include "LoadBench.h"
#include "MethodsBench.h"
#include "TerminalBench.h"
#include "cli/GenerateCommand.h"
#include "cli/RenderCommand.h"
#include "tui/Viewer.h"

namespace {

using termshade::RenderCommandOptions;

// CLI11's own exit codes are not ours: help is 0, every usage error 2.
int ParseOrExit(CLI::App& app, int argc, char** argv, bool& done) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    done = true;
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    done = true;
    return 0;
  } catch (const CLI::CallForVersion& version) {
    std::cout << version.what() << "\n";
    done = true;
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << "termshade: " << e.what() << "\nRun 'termshade --help' for the options.\n";
    done = true;
    return 2;
  }
  done = false;
  return 0;
}

// This program's own file, for benches that run it in a child process.
std::string SelfPath() {
  char path[4096];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof path - 1);
  if (length <= 0) return "/proc/self/exe";
  return {path, static_cast<size_t>(length)};
}

void AddSizeOption(CLI::App& command, RenderCommandOptions& options) {
  command
      .add_option_function<std::string>(
          "--size",
          [&options](const std::string& text) {
            static const std::regex kSize("([0-9]{1,5})x([0-9]{1,5})");
            std::smatch match;
            if (!std::regex_match(text, match, kSize)) {
              throw CLI::ValidationError("--size", "expected COLSxROWS, e.g. 80x24");
            }
            const int cols = std::stoi(match[1]), rows = std::stoi(match[2]);
            if (cols < 1 || rows < 1 || cols > 4096 || rows > 2048) {
              throw CLI::ValidationError("--size", "COLS must be 1..4096 and ROWS 1..2048");
            }
            options.widthCells = cols;
            options.heightCells = rows;
          },
          "frame size in cells, COLSxROWS (default 80x24)")
      ->type_name("COLSxROWS");
}

void AddViewOptions(CLI::App& command, RenderCommandOptions& options) {
  AddSizeOption(command, options);
  command.add_option("--cell-aspect", options.cellAspect, "cell height / cell width (default 2.0)")
      ->check(CLI::Range(0.25, 8.0));
  command.add_option("--theta", options.theta, "eye azimuth, radians (default 0.3)");
  command.add_option("--phi", options.phi, "eye polar angle from +z, radians (default 1.3)");
  command
      .add_option("--rho", options.rho,
                  "eye distance, model units (default 3 x 0.6 x bounding-box diagonal)")
      ->check(CLI::PositiveNumber);
}

void AddLookOptions(CLI::App& command, RenderCommandOptions& options) {
  command
      .add_option("--method", options.method,
                  "zbuffer (default), painter, cull, wire, or auto (the cheapest exact one)")
      ->check(CLI::IsMember({"zbuffer", "painter", "cull", "wire", "auto"}));
  command.add_option("--shade", options.shade, "contrast (default) or lambert")
      ->check(CLI::IsMember({"contrast", "lambert"}));
  command.add_option("--ramp", options.ramp,
                     "shade characters from dark to bright, UTF-8, one cell wide each "
                     "(default .:-=+*#%@; block elements, box drawing, braille and Latin-1 too)");
  command
      .add_option("--glyphs", options.glyphs,
                  "ramp, ascii (shape-matched), blocks, quadrants, sextants or braille "
                  "(render: default ramp; viewer: picked for the terminal; g cycles)")
      ->check(CLI::IsMember({"ramp", "ascii", "blocks", "quadrants", "sextants", "braille"}));
  command.add_flag("--no-cull", options.noCull,
                   "draw back faces too (shaded from their back side)");
}

int RunViewerFrom(const RenderCommandOptions& look, const std::vector<std::string>& models,
                  double cellAspectOption, bool mono) {
  termshade::ViewerOptions viewer;
  viewer.modelPaths = models;
  if (cellAspectOption > 0.0) viewer.cellAspect = cellAspectOption;
  viewer.monochrome = mono;
  viewer.render.method = *termshade::ParseMethod(look.method);
  viewer.render.shade = *termshade::ParseShadeMode(look.shade);
  if (const auto problem = termshade::ShadeRamp::Problem(look.ramp)) {
    std::cerr << "termshade: --ramp: " << *problem << "\n";
    return 2;
  }
  viewer.render.ramp = termshade::ShadeRamp(look.ramp);
  viewer.render.cullBackFaces = !look.noCull;
  if (!look.glyphs.empty()) viewer.glyphs = termshade::ParseGlyphMode(look.glyphs);
  return termshade::RunViewer(viewer);
}

int Run(int argc, char** argv) {
  CLI::App app{
      "termshade: shaded 3D polygon models in a terminal.\n"
      "With no command, opens the interactive viewer on MODEL files (the demo scene if none);\n"
      "press ? in the viewer for its keys."};
  app.set_help_all_flag("--help-all", "all commands' options");
  app.set_version_flag("--version", std::string("termshade ") + TERMSHADE_VERSION);
  app.require_subcommand(0, 1);

  // The viewer: termshade [MODEL...]
  RenderCommandOptions viewerLook;
  viewerLook.glyphs.clear();  // the viewer picks one for the terminal unless asked
  std::vector<std::string> models;
  double viewerAspect = 0.0;
  bool mono = false;
  app.add_option("models", models, "model files (.dat, or .obj .stl .ply .off ... via Assimp)");
  app.add_option("--cell-aspect", viewerAspect,
                 "cell height / cell width (default: from the terminal, else 2.0)")
      ->check(CLI::Range(0.25, 8.0));
  app.add_flag("--mono", mono, "no colour (also when NO_COLOR is set)");
  AddLookOptions(app, viewerLook);

  // Headless frames: termshade render MODEL [options]
  RenderCommandOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "render frames to stdout or a file");
  renderCommand->add_option("model", render.modelPath, "model file")->required();
  AddViewOptions(*renderCommand, render);
  AddLookOptions(*renderCommand, render);
  renderCommand->add_option("--format", render.format, "text (default), ansi or json")
      ->check(CLI::IsMember({"text", "ansi", "json"}));
  renderCommand->add_option("-o,--output", render.outputPath, "write to FILE instead of stdout");
  renderCommand->add_option("--frames", render.frames, "turntable: number of frames (default 1)")
      ->check(CLI::Range(1, 100000));
  renderCommand->add_option("--step", render.stepRadians,
                            "turntable: theta step between frames, radians (default 0.1)");

  // Scene files: termshade generate NAME [-o FILE]
  termshade::GenerateCommandOptions generate;
  CLI::App* generateCommand = app.add_subcommand(
      "generate", "write a shipped scene (data/*.dat) from its generator, or a test sphere");
  generateCommand
      ->add_option("scene", generate.name,
                   "scene name, 'all' (with -o DIRECTORY), or 'sphere' (see --triangles)")
      ->required();
  generateCommand->add_option(
      "-o,--output", generate.outputPath,
      "file: .dat, .obj, binary .stl or binary .ply by extension (directory for 'all')");
  generateCommand
      ->add_option("--triangles", generate.triangles, "sphere: about N triangles (default 200000)")
      ->check(CLI::Range(size_t{8}, size_t{50000000}));

  // Measurements: termshade bench terminal [options]
  CLI::App* benchCommand = app.add_subcommand("bench", "measure the program (see README)");
  benchCommand->require_subcommand(1);
  termshade::TerminalBenchOptions terminalBench;
  CLI::App* terminalCommand = benchCommand->add_subcommand(
      "terminal",
      "bytes and write() calls the viewer sends per frame, idle CPU (runs it in a pty)");
  terminalCommand->add_option("model", terminalBench.modelPath,
                              "model file (default: the demo scene)");
  terminalCommand->add_option("--cols", terminalBench.widthCells, "terminal width (default 160)")
      ->check(CLI::Range(20, 1000));
  terminalCommand->add_option("--rows", terminalBench.heightCells, "terminal height (default 48)")
      ->check(CLI::Range(4, 500));
  terminalCommand
      ->add_option("--idle-seconds", terminalBench.idleSeconds, "idle period (default 10)")
      ->check(CLI::Range(0.5, 600.0));
  terminalCommand
      ->add_option("--turntable-seconds", terminalBench.turntableSeconds,
                   "turntable period (default 4)")
      ->check(CLI::Range(0.5, 600.0));
  terminalCommand->add_flag("!--no-strace", terminalBench.traceWrites,
                            "do not count write() calls");

  termshade::MethodsBenchOptions methodsBench;
  CLI::App* methodsCommand = benchCommand->add_subcommand(
      "methods", "speed against error of every method on the same frames (table, CSV, SVG plot)");
  methodsCommand
      ->add_option("--frames", methodsBench.frames, "turntable frames per scene (default 8)")
      ->check(CLI::Range(1, 360));
  methodsCommand
      ->add_option("--seconds", methodsBench.secondsPerCase,
                   "timing budget per method and scene (default 0.3)")
      ->check(CLI::Range(0.01, 60.0));
  methodsCommand->add_option("--csv", methodsBench.csvPath,
                             "CSV output (default bench-methods.csv)");
  methodsCommand->add_option("--svg", methodsBench.svgPath,
                             "plot output (default bench-methods.svg)");
  methodsCommand->add_option("--data", methodsBench.dataDirectory,
                             "the scenes' directory (default data)");

  termshade::LoadBenchOptions loadBench;
  CLI::App* loadCommand = benchCommand->add_subcommand(
      "load", "load time, peak memory and frame time of generated big models (OBJ, STL, PLY)");
  loadCommand->add_option("--triangles", loadBench.triangleCounts,
                          "model sizes in triangles (default 200000 2000000)");
  loadCommand->add_option("--formats", loadBench.formats, "obj, stl, ply (default all three)")
      ->check(CLI::IsMember({"obj", "stl", "ply"}));
  loadCommand->add_option("--repeats", loadBench.repeats, "runs per model (default 3)")
      ->check(CLI::Range(1, 100));
  loadCommand->add_option("--dir", loadBench.directory,
                          "folder for the generated models (default: a temporary folder)");
  termshade::FidelityBenchOptions fidelityBench;
  CLI::App* fidelityCommand = benchCommand->add_subcommand(
      "fidelity",
      "blurred SSIM against the exact image, frame time and flicker of every glyph mode");
  fidelityCommand->add_option("--frames", fidelityBench.frames, "views per scene (default 2)")
      ->check(CLI::Range(1, 64));
  fidelityCommand
      ->add_option("--seconds", fidelityBench.secondsPerCase,
                   "timing budget per mode and scene (default 0.2)")
      ->check(CLI::Range(0.01, 60.0));
  fidelityCommand->add_option("--csv", fidelityBench.csvPath,
                              "CSV output (default bench-fidelity.csv)");
  fidelityCommand->add_option("--svg", fidelityBench.svgPath,
                              "plot output (default bench-fidelity.svg)");
  fidelityCommand->add_option("--data", fidelityBench.dataDirectory,
                              "the scenes' directory (default data)");

  bool done = false;
  const int parseCode = ParseOrExit(app, argc, argv, done);
  if (done) return parseCode;
  if (renderCommand->parsed()) return termshade::RunRenderCommand(render);
  if (generateCommand->parsed()) return termshade::RunGenerateCommand(generate);
  if (methodsCommand->parsed()) return termshade::RunMethodsBench(methodsBench);
  if (fidelityCommand->parsed()) return termshade::RunFidelityBench(fidelityBench);
  if (terminalCommand->parsed()) {
    terminalBench.viewerPath = SelfPath();
    return termshade::RunTerminalBench(terminalBench);
  }
  if (loadCommand->parsed()) {
    loadBench.executablePath = SelfPath();
    return termshade::RunLoadBench(loadBench);
  }
  return RunViewerFrom(viewerLook, models, viewerAspect, mono);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "termshade: internal error: " << e.what() << "\n";
  } catch (...) {
    std::cerr << "termshade: internal error\n";
  }
  return 3;
}
