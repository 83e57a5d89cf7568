// termshade: the command-line front end (SPEC 9). Parses arguments and hands
// over to the viewer, the headless renderer or the scene generator.
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <exception>
#include <iostream>
#include <optional>
#include <regex>

#include "FidelityBench.h"
#include "FrameBench.h"
#include "LoadBench.h"
#include "MethodsBench.h"
#include "ModelsBench.h"
#include "SnapshotBench.h"
#include "TerminalBench.h"
#include "cli/ConfigFile.h"
#include "cli/GenerateCommand.h"
#include "cli/HelpText.h"
#include "cli/InfoCommand.h"
#include "cli/NumberChecks.h"
#include "cli/RenderCommand.h"
#include "cli/SnapshotCheck.h"
#include "geometry/Angle.h"
#include "geometry/UpAxis.h"
#include "io/load/ModelLoader.h"
#include "io/read/LoadBudget.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"
#include "process/HeapPolicy.h"
#include "process/StandardDescriptors.h"
#include "tui/Viewer.h"

namespace {

using termshade::RenderCommandOptions;

// CLI11's own exit codes are not ours: help is 0, every usage error 2. Its
// text quotes the command line, so it is escaped before reaching a terminal.
int ParseOrExit(CLI::App& app, int argc, char** argv, const std::string& configPath, bool& done) {
  using termshade::SanitizeForTerminal;
  using termshade::SanitizeLinesForTerminal;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << SanitizeLinesForTerminal(app.help());
    done = true;
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << SanitizeLinesForTerminal(app.help("", CLI::AppFormatMode::All));
    done = true;
    return 0;
  } catch (const CLI::CallForVersion& version) {
    std::cout << SanitizeLinesForTerminal(version.what()) << "\n";
    done = true;
    return 0;
  } catch (const CLI::ConfigError& e) {  // a key or section of the file
    std::cerr << "termshade: " << SanitizeForTerminal(configPath) << ": "
              << SanitizeLinesForTerminal(e.what()) << "\n";
    done = true;
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "termshade: " << SanitizeLinesForTerminal(e.what()) << "\n";
    if (const std::string hint = termshade::NearestOptionHint(app); !hint.empty()) {
      std::cerr << "termshade: " << SanitizeLinesForTerminal(hint) << "\n";
    }
    std::cerr << "Run 'termshade --help' for the options.\n";
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
            static const std::regex kSize("([0-9]+)x([0-9]+)");
            std::smatch match;
            if (!std::regex_match(text, match, kSize)) {
              throw CLI::ValidationError("--size", "expected COLSxROWS, e.g. 80x24");
            }
            // Leading zeros do not count; more than 9 digits is out of range
            // anyway (and past what stoi takes).
            auto count = [](std::string digits) {
              digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
              return digits.size() > 9 ? INT32_MAX : std::stoi(digits);
            };
            const int cols = count(match[1]), rows = count(match[2]);
            if (cols < 1 || rows < 1 || cols > 4096 || rows > 2048) {
              throw CLI::ValidationError("--size", "COLS must be 1..4096 and ROWS 1..2048");
            }
            options.widthCells = cols;
            options.heightCells = rows;
          },
          "frame size in cells, COLSxROWS (default: the terminal's, one row less, when "
          "stdout is one; else 80x24)")
      ->type_name("COLSxROWS");
}

// An angle in radians, or in degrees with a `deg` suffix.
void AddAngleOption(CLI::App& command, const std::string& name, double& radians,
                    const std::string& description) {
  command
      .add_option_function<std::string>(
          name,
          [&radians, name](const std::string& text) {
            const auto angle = termshade::ParseAngleRadians(text);
            if (!angle) {
              throw CLI::ValidationError(name, "expected radians (0.3) or degrees (30deg)");
            }
            radians = *angle;
          },
          description)
      ->type_name("ANGLE");
}

// -o FILE: - is standard output (left empty); an empty name is a usage error.
void AddOutputOption(CLI::App& command, std::string& path, const std::string& description) {
  command
      .add_option_function<std::string>(
          "-o,--output",
          [&path](const std::string& text) {
            if (text.empty()) {
              throw CLI::ValidationError("--output",
                                         "the file name is empty (- is standard output)");
            }
            path = text == "-" ? std::string() : text;
          },
          description)
      ->type_name("FILE");
}

void AddUpOption(CLI::App& command, std::optional<termshade::UpAxis>& upAxis) {
  command
      .add_option_function<std::string>(
          "--up",
          [&upAxis](const std::string& text) {
            upAxis = termshade::ParseUpAxis(text);
            if (!upAxis) throw CLI::ValidationError("--up", "expected x, y, z, -x, -y or -z");
          },
          "the file's up axis, turned to the screen's up: x|y|z|-x|-y|-z "
          "(default: what the file declares, else its format's convention)")
      ->type_name("AXIS");
}

void AddLoadLimitOptions(CLI::App& command, termshade::LoadLimits& limits) {
  size_t& budgetBytes = limits.memoryBudgetBytes;
  command
      .add_option_function<std::string>(
          "--memory-budget",
          [&budgetBytes](const std::string& text) {
            const auto bytes = termshade::ParseByteCount(text);
            if (!bytes) {
              throw CLI::ValidationError("--memory-budget",
                                         "expected a size such as 4G, 512M or 1000000 (bytes)");
            }
            budgetBytes = *bytes;
          },
          "most memory loading may take, e.g. 4G or 512M (default: TERMSHADE_MEMORY_BUDGET, "
          "else 2G); a model needing more is refused")
      ->type_name("SIZE");
  command
      .add_option("--import-seconds", limits.importCpuSeconds,
                  "processor seconds the import helper (Assimp) may take on a file (default: "
                  "TERMSHADE_IMPORT_SECONDS, else 30 s and 1 s a MiB)")
      ->check(CLI::Range(1, 86400))
      ->type_name("SECONDS");
}

void AddViewOptions(CLI::App& command, RenderCommandOptions& options) {
  AddSizeOption(command, options);
  command.add_option("--cell-aspect", options.cellAspect, "cell height / cell width (default 2.0)")
      ->check(termshade::FiniteIn(0.25, 8.0));
  AddAngleOption(command, "--theta", options.theta,
                 "eye azimuth about the up axis, radians or Ndeg (default 0.3)");
  AddAngleOption(command, "--phi", options.phi,
                 "eye polar angle from the up axis, radians or Ndeg (default 1.3)");
  command
      .add_option("--rho", options.rho,
                  "eye distance, model units (default 3 x 0.6 x bounding-box diagonal)")
      ->check(termshade::FinitePositive());
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
                  "ramp, ascii (shape-matched), blocks, quadrants, sextants, braille, or auto "
                  "(picked for the terminal: the viewer's default; render's is ramp; g cycles)")
      ->check(
          CLI::IsMember({"ramp", "ascii", "blocks", "quadrants", "sextants", "braille", "auto"}));
  command.add_flag("--no-cull", options.noCull,
                   "draw back faces too (shaded from their back side)");
  command
      .add_option("--threads", options.threads,
                  "threads drawing each frame of a big model (default 0: every core); the frame "
                  "is the same with any count")
      ->check(CLI::Range(0, 256));
  command
      .add_option("--color", options.colour,
                  "cell colours: none, 16 (the ANSI colours, SGR 30-37 and 90-97), 256 (nearest "
                  "xterm cube or grey entry), truecolor, or auto (from NO_COLOR, COLORTERM, "
                  "terminfo and, in the viewer, the terminal's answer; the viewer's default; "
                  "render's is 256)")
      ->check(CLI::IsMember({"none", "16", "256", "truecolor", "24bit", "auto"}));
  command.add_flag("--mono", options.mono, "no colour: --color none");
  command
      .add_option("--background", options.background,
                  "the terminal's background the shades are made for: dark or light (render: "
                  "dark; viewer: the terminal's answer (OSC 11), else COLORFGBG, else dark); "
                  "without colour, on light the ink follows each face's darkness")
      ->check(CLI::IsMember({"dark", "light"}));
  command
      .add_option("--lod", options.lod,
                  "level of detail: auto (a simplified copy of a big model where its triangles "
                  "are far below a sample; the viewer's default) or off (exact; render's default)")
      ->check(CLI::IsMember({"auto", "off"}));
  command
      .add_option("--textures", options.textures,
                  "on (default): where colours are shown, faces with a base-colour texture take "
                  "its colours, sample by sample; off: their face colour")
      ->check(CLI::IsMember({"on", "off"}));
}

int RunViewerFrom(const RenderCommandOptions& look, const std::vector<std::string>& models,
                  double cellAspectOption, const std::string& recordPath) {
  termshade::ViewerOptions viewer;
  viewer.modelPaths = models;
  if (cellAspectOption > 0.0) viewer.cellAspect = cellAspectOption;
  viewer.colour = look.mono
                      ? termshade::ColourMode::kNone
                      : *termshade::ParseColourMode(look.colour.empty() ? "auto" : look.colour);
  if (!look.background.empty()) viewer.background = termshade::ParseBackground(look.background);
  viewer.render.method = *termshade::ParseMethod(look.method);
  viewer.render.textures = look.textures != "off";
  viewer.render.shade = *termshade::ParseShadeMode(look.shade);
  if (const auto problem = termshade::ShadeRamp::Problem(look.ramp)) {
    std::cerr << "termshade: --ramp: " << *problem << "\n";
    return 2;
  }
  viewer.render.ramp = termshade::ShadeRamp(look.ramp);
  viewer.render.cullBackFaces = !look.noCull;
  viewer.render.threads = look.threads;
  if (!look.glyphs.empty() && look.glyphs != "auto")
    viewer.glyphs = termshade::ParseGlyphMode(look.glyphs);
  viewer.upAxis = look.upAxis;
  viewer.loadLimits = look.loadLimits;
  viewer.detail = *termshade::ParseDetailMode(look.lod.empty() ? "auto" : look.lod);
  viewer.theta = look.theta;
  viewer.phi = look.phi;
  viewer.recordPath = recordPath;
  return termshade::RunViewer(viewer);
}

int Run(int argc, char** argv) {
  CLI::App app{
      "termshade: shaded 3D polygon models in a terminal.\n"
      "With no command, opens the interactive viewer on MODEL files (the demo scene if none);\n"
      "press ? in the viewer for its keys.",
      "termshade"};  // named here, so a hostile argv[0] never reaches the help text
  std::string generateWhat;
  termshade::SetUpHelp(app, TERMSHADE_VERSION, generateWhat);
  // Defaults from a configuration file: the user's for the viewer, a named one for render.
  termshade::ConfigChoice config = termshade::ChooseConfig(argc, argv);
  if (const auto problem = termshade::ConfigFileProblem(config)) {
    std::cerr << "termshade: " << *problem << "\n";
    return 2;
  }
  bool printConfig = false;
  termshade::AddConfigOptions(app, config, printConfig);
  app.require_subcommand(0, 1);

  // The viewer: termshade [MODEL...]
  RenderCommandOptions viewerLook;
  viewerLook.glyphs.clear();  // the viewer picks one for the terminal unless asked
  std::vector<std::string> models;
  double viewerAspect = 0.0;
  app.add_option("models", models, "model files (.dat, or .obj .stl .ply .off ... via Assimp)")
      ->type_name("MODEL");
  app.add_option("--cell-aspect", viewerAspect,
                 "cell height / cell width (default: from the terminal, else 2.0)")
      ->check(termshade::FiniteIn(0.25, 8.0));
  AddLookOptions(app, viewerLook);
  AddUpOption(app, viewerLook.upAxis);
  AddLoadLimitOptions(app, viewerLook.loadLimits);
  AddAngleOption(app, "--theta", viewerLook.theta, "starting eye azimuth, radians or Ndeg (0.3)");
  AddAngleOption(app, "--phi", viewerLook.phi, "starting eye polar angle, radians or Ndeg (1.3)");
  std::string recordPath;
  app.add_option("--record", recordPath,
                 "record what the viewer shows as an asciinema v2 file (FILE.cast), written "
                 "whole when the viewer ends")
      ->type_name("FILE");

  // Headless frames: termshade render MODEL [options]
  RenderCommandOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "render frames to stdout or a file");
  renderCommand
      ->add_option("model", render.modelPaths,
                   "model file(s), or - for standard input; several are rendered one after another")
      ->required()
      ->type_name("MODEL");
  AddViewOptions(*renderCommand, render);
  AddLookOptions(*renderCommand, render);
  renderCommand
      ->add_option("--format", render.format,
                   "text (default), ansi, json, svg (a picture of the frame) or asciicast (an "
                   "asciinema recording of the turntable)")
      ->check(CLI::IsMember({"text", "ansi", "json", "svg", "asciicast"}));
  AddOutputOption(*renderCommand, render.outputPath,
                  "write to FILE instead of stdout (- is stdout); a regular file is replaced "
                  "whole, through its links");
  renderCommand->add_option("--frames", render.frames, "turntable: number of frames (default 1)")
      ->check(CLI::Range(1, 100000));
  renderCommand
      ->add_option("--fps", render.framesPerSecond,
                   "asciicast: frames a second of the recording (default 25, the viewer's)")
      ->check(CLI::Range(0.01, 1000.0));
  AddAngleOption(*renderCommand, "--step", render.stepRadians,
                 "turntable: theta step between frames, radians or Ndeg (default 0.1)");
  renderCommand
      ->add_option_function<std::string>(
          "--light",
          [&render](const std::string& text) {
            const size_t comma = text.find(',');
            const auto azimuth = termshade::ParseAngleRadians(text.substr(0, comma));
            const auto elevation = comma == std::string::npos
                                       ? std::nullopt
                                       : termshade::ParseAngleRadians(text.substr(comma + 1));
            if (!azimuth || !elevation) {
              throw CLI::ValidationError("--light",
                                         "expected AZIMUTH,ELEVATION, radians or Ndeg (0.4,-0.2)");
            }
            render.lightRadians = {*azimuth, *elevation};
          },
          "the sun as two angles about the eye's axes, radians or Ndeg: AZIMUTH,ELEVATION "
          "(default 0,0: from the upper left front; the viewer's L mode moves it)")
      ->type_name("AZ,EL");
  renderCommand
      ->add_option_function<std::string>(
          "--budget",
          [&render](const std::string& text) {
            const auto seconds = termshade::ParseDurationSeconds(text);
            if (!seconds) {
              throw CLI::ValidationError(
                  "--budget", "expected a duration above zero and at most a day: 300ms or 1.5s");
            }
            render.budgetSeconds = *seconds;
          },
          "time for the whole command, e.g. 300ms or 2s: when a big model's exact frames would "
          "not fit in what loading left, a clustered copy is drawn (a note says so); loading "
          "itself is not cut short")
      ->type_name("DURATION");
  renderCommand->add_flag("--fit", render.fit,
                          "the viewer's framing: the model as large as stays inside the frame at "
                          "every orbit angle (default: the bounding sphere at 9/10 of the smaller "
                          "half-extent, as dumps and goldens are made)");
  renderCommand
      ->add_option("--fit-rho", render.fitRho,
                   "fit the frame as if the eye were at this distance, model units (the "
                   "viewer's f; default: the default distance)")
      ->check(termshade::FinitePositive());
  AddUpOption(*renderCommand, render.upAxis);
  renderCommand
      ->add_option("--input-format", render.inputFormat,
                   "the model's format as an extension (stl, obj, ...) where the name and "
                   "content cannot tell it (standard input)")
      ->type_name("EXT");
  AddLoadLimitOptions(*renderCommand, render.loadLimits);
  renderCommand->add_flag("--print-config", printConfig,
                          "print the effective configuration (defaults, --config FILE and the "
                          "command line) and exit");

  renderCommand
      ->add_option("--reader", render.reader,
                   "auto (default): dedicated readers for binary STL, PLY and OBJ, Assimp for "
                   "the rest; assimp: Assimp for everything (the reference)")
      ->check(CLI::IsMember({"auto", "assimp"}));
  termshade::SnapshotCommandOptions snapshot;
  termshade::AddSnapshotOptions(*renderCommand, snapshot);

  // A model's report: termshade info MODEL... [--format json]
  termshade::InfoCommandOptions info;
  CLI::App* infoCommand = app.add_subcommand(
      "info",
      "what a model file holds: reader, counts, bounds, up axis, open edges, colours, "
      "load time and peak memory; nothing drawn");
  infoCommand->add_option("model", info.modelPaths, "model file(s)")
      ->required()
      ->type_name("MODEL");
  infoCommand->add_option("--format", info.format, "text (default) or json (one object a line)")
      ->check(CLI::IsMember({"text", "json"}));
  AddUpOption(*infoCommand, info.upAxis);
  AddLoadLimitOptions(*infoCommand, info.loadLimits);
  infoCommand
      ->add_option("--reader", info.reader,
                   "auto (default): dedicated readers where they exist; assimp: Assimp for all")
      ->check(CLI::IsMember({"auto", "assimp"}));

  // Scene files: termshade generate NAME [-o FILE]
  termshade::GenerateCommandOptions generate;
  CLI::App* generateCommand = app.add_subcommand(
      "generate", "write a shipped scene (data/*.dat) from its generator, or a test sphere");
  generateCommand
      ->add_option("scene", generate.name,
                   "scene name, 'all' (with -o DIRECTORY), or 'sphere' (see --triangles)")
      ->required();
  AddOutputOption(*generateCommand, generate.outputPath,
                  "file: .dat, .obj, binary .stl or binary .ply by extension (directory for 'all'; "
                  "- is stdout)");
  generateCommand
      ->add_option("--triangles", generate.triangles, "sphere: about N triangles (default 200000)")
      ->check(CLI::Range(size_t{8}, size_t{50000000}));

  // Measurements: termshade bench terminal [options]
  CLI::App* benchCommand =
      app.add_subcommand("bench", "measure the program (see docs/performance.md)");
  benchCommand->require_subcommand(1);
  termshade::TerminalBenchOptions terminalBench;
  CLI::App* terminalCommand = benchCommand->add_subcommand(
      "terminal",
      "bytes and write() calls the viewer sends per frame, idle CPU (runs it in a pty)");
  terminalCommand
      ->add_option("model", terminalBench.modelPath, "model file (default: the demo scene)")
      ->type_name("MODEL");
  terminalCommand->add_option("--cols", terminalBench.widthCells, "terminal width (default 160)")
      ->check(CLI::Range(20, 1000));
  terminalCommand->add_option("--rows", terminalBench.heightCells, "terminal height (default 48)")
      ->check(CLI::Range(4, 500));
  terminalCommand
      ->add_option("--idle-seconds", terminalBench.idleSeconds, "idle period (default 10)")
      ->check(termshade::FiniteIn(0.5, 600.0));
  terminalCommand
      ->add_option("--turntable-seconds", terminalBench.turntableSeconds,
                   "turntable period (default 4)")
      ->check(termshade::FiniteIn(0.5, 600.0));
  terminalCommand->add_flag("!--no-strace", terminalBench.traceWrites,
                            "do not count write() calls");
  terminalCommand->add_option("--lod", terminalBench.lod, "the viewer's --lod: auto or off")
      ->check(CLI::IsMember({"auto", "off"}));
  terminalCommand
      ->add_option("--settle-seconds", terminalBench.settleSeconds,
                   "wait after the first screen before measuring, for a big model's load and "
                   "levels of detail (default 0)")
      ->check(termshade::FiniteIn(0.0, 600.0));
  terminalCommand
      ->add_option("--glyphs", terminalBench.glyphs, "the viewer's --glyphs (default: its pick)")
      ->check(CLI::IsMember({"ramp", "ascii", "blocks", "quadrants", "sextants", "braille"}));
  terminalCommand
      ->add_option("--color", terminalBench.colour, "the viewer's --color (default: auto)")
      ->check(CLI::IsMember({"none", "16", "256", "truecolor", "auto"}));
  std::string linkText;
  terminalCommand
      ->add_option("--link", linkText,
                   "a slow link between viewer and terminal, RATE:DELAY (e.g. 256kbit:50ms, "
                   "1mbit:50ms; delay each way): settle, stop and quit times instead")
      ->check([](const std::string& text) {
        return termshade::ParseLinkSpec(text) ? "" : "not RATE:DELAY, e.g. 256kbit:50ms";
      });
  terminalCommand->add_flag("!--no-answer", terminalBench.answer,
                            "play a terminal that never answers the viewer's DA1 requests");
  terminalCommand->add_option("--viewer", terminalBench.viewerPath,
                              "the termshade program to measure (default: this one; another "
                              "build, to compare)");

  termshade::MethodsBenchOptions methodsBench;
  CLI::App* methodsCommand = benchCommand->add_subcommand(
      "methods", "speed against error of every method on the same frames (table, CSV, SVG plot)");
  methodsCommand
      ->add_option("--frames", methodsBench.frames, "turntable frames per scene (default 8)")
      ->check(CLI::Range(1, 360));
  methodsCommand
      ->add_option("--seconds", methodsBench.secondsPerCase,
                   "timing budget per method and scene (default 0.3)")
      ->check(termshade::FiniteIn(0.01, 60.0));
  methodsCommand
      ->add_option("--csv", methodsBench.csvPath, "CSV output (default docs/bench-methods.csv)")
      ->type_name("FILE");
  methodsCommand
      ->add_option("--svg", methodsBench.svgPath, "plot output (default docs/bench-methods.svg)")
      ->type_name("FILE");
  methodsCommand
      ->add_option("--data", methodsBench.dataDirectory, "the scenes' directory (default data)")
      ->type_name("DIR");

  termshade::ModelsBenchOptions modelsBench;
  CLI::App* modelsCommand = benchCommand->add_subcommand(
      "models", "per model file: loads?, up axis, faces turned outward, colours, frame ms (TSV)");
  modelsCommand->add_option("models", modelsBench.modelPaths, "model files")->required();
  AddUpOption(*modelsCommand, modelsBench.upAxis);

  termshade::LoadBenchOptions loadBench;
  CLI::App* loadCommand = benchCommand->add_subcommand(
      "load", "load time, peak memory and frame time of generated big models (OBJ, STL, PLY)");
  loadCommand->add_option("--triangles", loadBench.triangleCounts,
                          "model sizes in triangles (default 200000 2000000)");
  loadCommand->add_option("--formats", loadBench.formats, "obj, stl, ply (default all three)")
      ->check(CLI::IsMember({"obj", "stl", "ply"}));
  loadCommand
      ->add_option("--readers", loadBench.readers,
                   "render --reader values to compare (default auto assimp), or "
                   "assimp-in-process: Assimp's read time outside its helper process")
      ->check(CLI::IsMember({"auto", "assimp", "assimp-in-process"}));
  loadCommand->add_option("--repeats", loadBench.repeats, "runs per model (default 3)")
      ->check(CLI::Range(1, 100));
  loadCommand
      ->add_option("--dir", loadBench.directory,
                   "folder for the generated models (default: a temporary folder)")
      ->type_name("DIR");
  termshade::FrameBenchOptions frameBench;
  CLI::App* frameCommand = benchCommand->add_subcommand(
      "frame",
      "frame time by triangles x cells: rays through the hierarchy against clusters, 1 thread "
      "against all, "
      "culling on and off, and the measured choice between the two passes (the default)");
  frameCommand
      ->add_option("--models", frameBench.modelPaths,
                   "model files to time (default: the demo scene)")
      ->type_name("FILE");
  frameCommand->add_option("--triangles", frameBench.triangleCounts,
                           "generated spheres, in triangles (with no --models: 200000 2000000)");
  frameCommand->add_option("--sizes", frameBench.sizes, "COLSxROWS (default 80x24 160x48 400x120)");
  frameCommand->add_option("--threads", frameBench.threads, "all threads (default every core)")
      ->check(CLI::Range(0, 256));
  frameCommand->add_option("--frames", frameBench.frames, "turntable frames (default 15)")
      ->check(CLI::Range(1, 1000));
  termshade::FidelityBenchOptions fidelityBench;
  CLI::App* fidelityCommand = benchCommand->add_subcommand(
      "fidelity",
      "blurred SSIM against the exact image, frame time and flicker of every glyph mode");
  fidelityCommand->add_option("--frames", fidelityBench.frames, "views per scene (default 2)")
      ->check(CLI::Range(1, 64));
  fidelityCommand
      ->add_option("--seconds", fidelityBench.secondsPerCase,
                   "timing budget per mode and scene (default 0.2)")
      ->check(termshade::FiniteIn(0.01, 60.0));
  fidelityCommand
      ->add_option("--csv", fidelityBench.csvPath, "CSV output (default docs/bench-fidelity.csv)")
      ->type_name("FILE");
  fidelityCommand
      ->add_option("--svg", fidelityBench.svgPath, "plot output (default docs/bench-fidelity.svg)")
      ->type_name("FILE");
  fidelityCommand
      ->add_option("--data", fidelityBench.dataDirectory, "the scenes' directory (default data)")
      ->type_name("DIR");
  fidelityCommand->add_option("--scene", fidelityBench.sceneName,
                              "only this scene (e.g. sphere_cone)");
  fidelityCommand->add_flag("--timing-only", fidelityBench.timingOnly,
                            "frame times alone (interleaved): no fidelity, CSV or SVG");

  termshade::SnapshotBenchOptions snapshotBench;
  CLI::App* snapshotsCommand = benchCommand->add_subcommand(
      "snapshots", "how often render --expect catches a vertex moved, by move size and tolerance");
  snapshotsCommand->add_option("--models", snapshotBench.modelPaths,
                               "model files (default: data/*.dat and a few corpus models)");
  snapshotsCommand->add_option("--trials", snapshotBench.trials, "moves per model and size (20)")
      ->check(CLI::Range(1, 10000));
  snapshotsCommand->add_option(
      "--moves", snapshotBench.moveShares,
      "move sizes, shares of the diagonal (1e-5 1e-4 1e-3 3e-3 1e-2 3e-2)");
  snapshotsCommand->add_option("--tolerances", snapshotBench.tolerances,
                               "--tolerance values to compare (0 10 100 1%)");
  snapshotsCommand
      ->add_option("--data", snapshotBench.dataDirectory, "the scenes' directory (default data)")
      ->type_name("DIR");

  termshade::AddExamples(app);
  bool done = false;
  const int parseCode =
      ParseOrExit(app, static_cast<int>(config.argv.size()), config.argv.data(), config.path, done);
  if (done) return parseCode;
  // The environment's load limits, checked as their options are (exit 2).
  if (const auto problem = termshade::LoadEnvironmentProblem()) {
    std::cerr << "termshade: " << termshade::SanitizeForTerminal(*problem) << "\n";
    return 2;
  }
  if (printConfig) {
    std::cout << termshade::SanitizeLinesForTerminal(termshade::EffectiveConfig(app));
    return 0;
  }
  if (!generateWhat.empty()) return termshade::RunGenerate(app, TERMSHADE_VERSION, generateWhat);
  if (renderCommand->parsed()) {
    return snapshot.Requested() ? termshade::RunSnapshotCommand(render, snapshot, *renderCommand)
                                : termshade::RunRenderCommand(render);
  }
  if (generateCommand->parsed()) return termshade::RunGenerateCommand(generate);
  if (infoCommand->parsed()) return termshade::RunInfoCommand(info);
  if (methodsCommand->parsed()) return termshade::RunMethodsBench(methodsBench);
  if (frameCommand->parsed()) return termshade::RunFrameBench(frameBench);
  if (fidelityCommand->parsed()) return termshade::RunFidelityBench(fidelityBench);
  if (snapshotsCommand->parsed()) return termshade::RunSnapshotBench(snapshotBench);
  if (terminalCommand->parsed()) {
    if (!terminalBench.modelPath.empty()) {  // a model that cannot load gives no meaningful table
      const termshade::Loaded<termshade::Mesh> mesh =
          termshade::LoadModelFile(terminalBench.modelPath);
      if (!mesh.Ok()) {
        std::cerr << mesh.Error().ToString() << "\n";
        return 1;
      }
    }
    if (terminalBench.viewerPath.empty()) terminalBench.viewerPath = SelfPath();
    if (!linkText.empty()) terminalBench.link = termshade::ParseLinkSpec(linkText);
    return termshade::RunTerminalBench(terminalBench);
  }
  if (modelsCommand->parsed()) return termshade::RunModelsBench(modelsBench);
  if (loadCommand->parsed()) {
    loadBench.executablePath = SelfPath();
    return termshade::RunLoadBench(loadBench);
  }
  return RunViewerFrom(viewerLook, models, viewerAspect, recordPath);
}

}  // namespace

int main(int argc, char** argv) {
  // An ignored SIGCHLD, inherited through exec, would let the kernel reap the
  // import helper before termshade reads how it ended.
  std::signal(SIGCHLD, SIG_DFL);
  termshade::GuardClosedStandardDescriptors();
  termshade::KeepFreedMemoryForReuse();
  try {
    return Run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "termshade: internal error: " << termshade::SanitizeForTerminal(e.what()) << "\n";
  } catch (...) {
    std::cerr << "termshade: internal error\n";
  }
  return 3;
}
