#include "cli/SnapshotCheck.h"

#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "geometry/Scene.h"
#include "io/load/ModelLoader.h"
#include "io/read/SnapshotGoldenReader.h"
#include "io/write/OutputFile.h"
#include "io/write/SnapshotGoldenWriter.h"
#include "io/write/SnapshotReport.h"

namespace termshade {
namespace {

int Usage(const std::string& message) {
  std::cerr << "termshade render: " << SanitizeForTerminal(message, 1000) << "\n";
  return 2;
}

bool UpdateFromEnvironment() {
  const char* value = std::getenv("TERMSHADE_UPDATE");
  return value != nullptr && *value != '\0' && std::strcmp(value, "0") != 0;
}

bool ColourOnStderr() {
  const char* term = std::getenv("TERM");
  return isatty(STDERR_FILENO) == 1 && std::getenv("NO_COLOR") == nullptr && term != nullptr &&
         std::strcmp(term, "dumb") != 0;
}

std::optional<std::vector<std::string>> ParseViews(const std::string& text) {
  std::vector<std::string> views;
  if (text == "all") {
    for (const std::string_view name : SnapshotViewNames()) views.emplace_back(name);
    return views;
  }
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    if (!SnapshotViewFor(name, 0.0, 0.0)) return std::nullopt;
    if (std::find(views.begin(), views.end(), name) != views.end()) return std::nullopt;
    views.push_back(name);
    start = end + 1;
  }
  return views;
}

std::string JoinViews(const std::vector<std::string>& views) {
  std::string out;
  for (const std::string& view : views) out += (out.empty() ? "" : ",") + view;
  return out;
}

// The snapshot's settings from the command line (for a new golden).
std::optional<std::string> SettingsFromCommandLine(const RenderCommandOptions& render,
                                                   SnapshotSettings& settings) {
  if (render.widthCells > 0) {
    settings.widthCells = render.widthCells;
    settings.heightCells = render.heightCells;
  }
  settings.cellAspect = render.cellAspect;
  settings.theta = render.theta;
  settings.phi = render.phi;
  const auto method = ParseMethod(render.method);
  const auto shade = ParseShadeMode(render.shade);
  const auto glyphs = ParseGlyphMode(render.glyphs);
  if (!method || !shade || !glyphs) return "--method, --shade or --glyphs is not known";
  settings.method = *method;
  settings.shade = *shade;
  settings.glyphs = *glyphs;
  if (const auto problem = ShadeRamp::Problem(render.ramp)) return "--ramp: " + *problem;
  settings.ramp = render.ramp;
  settings.cullBackFaces = !render.noCull;
  return std::nullopt;
}

// The first option given on the command line that says otherwise than the golden.
std::optional<std::string> Contradiction(const RenderCommandOptions& render,
                                         const std::optional<UpAxis>& upAxis,
                                         const SnapshotGolden& golden, const CLI::App& command) {
  SnapshotSettings given = golden.settings;
  SettingsFromCommandLine(render, given);  // its problems were reported before
  const SnapshotSettings& s = golden.settings;
  const auto differs = [&](const char* option, bool different, const std::string& recorded) {
    return command.count(option) > 0 && different
               ? std::optional<std::string>(std::string(option) + " contradicts the golden's " +
                                            recorded)
               : std::nullopt;
  };
  std::optional<std::string> problem;
  for (auto check : {
           differs("--size", given.widthCells != s.widthCells || given.heightCells != s.heightCells,
                   "size " + std::to_string(s.widthCells) + "x" + std::to_string(s.heightCells)),
           differs("--cell-aspect", given.cellAspect != s.cellAspect,
                   "cell-aspect " + SnapshotNumber(s.cellAspect)),
           differs("--theta", given.theta != s.theta, "theta " + SnapshotNumber(s.theta)),
           differs("--phi", given.phi != s.phi, "phi " + SnapshotNumber(s.phi)),
           differs("--method", given.method != s.method,
                   "method " + std::string(MethodName(s.method))),
           differs("--shade", given.shade != s.shade,
                   "shade " + std::string(ShadeModeName(s.shade))),
           differs("--glyphs", given.glyphs != s.glyphs,
                   "glyphs " + std::string(GlyphModeName(s.glyphs))),
           differs("--ramp", given.ramp != s.ramp, "ramp " + s.ramp),
           differs("--no-cull", given.cullBackFaces != s.cullBackFaces, "culling"),
           differs("--up", upAxis != golden.upAxis,
                   "up " + (golden.upAxis ? std::string(UpAxisName(*golden.upAxis)) : "auto")),
       }) {
    if (check && !problem) problem = check;
  }
  return problem;
}

// An existing golden's options, with those given on the command line in
// their place (--update keeps what the command line does not say).
SnapshotSettings WithGivenOptions(SnapshotSettings base, const SnapshotSettings& given,
                                  const CLI::App& command) {
  const auto isGiven = [&](const char* option) { return command.count(option) > 0; };
  if (isGiven("--size")) {
    base.widthCells = given.widthCells;
    base.heightCells = given.heightCells;
  }
  if (isGiven("--cell-aspect")) base.cellAspect = given.cellAspect;
  if (isGiven("--theta")) base.theta = given.theta;
  if (isGiven("--phi")) base.phi = given.phi;
  if (isGiven("--method")) base.method = given.method;
  if (isGiven("--shade")) base.shade = given.shade;
  if (isGiven("--glyphs")) base.glyphs = given.glyphs;
  if (isGiven("--ramp")) base.ramp = given.ramp;
  if (isGiven("--no-cull")) base.cullBackFaces = given.cullBackFaces;
  return base;
}

std::optional<std::string> WriteWhole(const std::string& path, const std::string& text) {
  OutputFile file(path);
  if (auto problem = file.Open()) return problem;
  if (auto problem = file.Write(text)) return problem;
  return file.Commit();
}

// Removes a GOLDEN.new left by an earlier run, once the golden matches or is rewritten.
void RemoveStaleNew(const std::string& newPath) {
  struct stat info {};
  if (lstat(newPath.c_str(), &info) == 0 && S_ISREG(info.st_mode)) unlink(newPath.c_str());
}

}  // namespace

void AddSnapshotOptions(CLI::App& renderCommand, SnapshotCommandOptions& options) {
  renderCommand
      .add_option("--expect", options.expectPath,
                  "snapshot test: render the views recorded in GOLDEN with its options and compare "
                  "(exit 0 match, 1 differs; the actual frames go to GOLDEN.new)")
      ->type_name("GOLDEN");
  renderCommand.add_flag("--update", options.update,
                         "with --expect: write GOLDEN from this model (also TERMSHADE_UPDATE=1)");
  renderCommand
      .add_option("--tolerance", options.tolerance,
                  "with --expect: samples a view may differ by after edges and lone samples are "
                  "forgiven: a count (default 0) or N% of the model's samples")
      ->type_name("N[%]");
  renderCommand
      .add_option("--views", options.views,
                  "with --expect: the views a new golden holds, comma-separated: default, "
                  "opposite, top, bottom (default: all four)")
      ->type_name("LIST");
}

int RunSnapshotCommand(const RenderCommandOptions& render, const SnapshotCommandOptions& snapshot,
                       const CLI::App& renderCommand) {
  // Step 1: the options, checked before anything is read.
  if (snapshot.expectPath.empty()) return Usage("--update needs --expect GOLDEN");
  const bool update = snapshot.update || UpdateFromEnvironment();
  for (const char* option : {"--output", "--format", "--frames", "--step", "--fps", "--rho"}) {
    if (renderCommand.count(option) > 0) {
      return Usage(std::string(option) +
                   " cannot be used with --expect: a golden holds text frames of its own views");
    }
  }
  if (render.lod == "auto") return Usage("--lod auto cannot be used with --expect (exact frames)");
  if (render.modelPaths.size() != 1) return Usage("--expect compares one model a golden");
  const auto tolerance =
      ParseSnapshotTolerance(snapshot.tolerance.empty() ? "0" : snapshot.tolerance);
  if (!tolerance) return Usage("--tolerance must be a count of samples (12) or a share (0.5%)");
  std::optional<std::vector<std::string>> views;
  if (!snapshot.views.empty()) {
    views = ParseViews(snapshot.views);
    if (!views) return Usage("--views must be `all` or names from default,opposite,top,bottom");
  }
  SnapshotGolden golden;
  golden.upAxis = render.upAxis;
  if (const auto problem = SettingsFromCommandLine(render, golden.settings)) return Usage(*problem);
  if (views) golden.settings.views = *views;
  const std::string& goldenPath = snapshot.expectPath;
  const std::string newPath = goldenPath + ".new";
  const std::string shownGolden = SanitizeForTerminal(goldenPath, 1000);
  if (!render.modelPaths.empty() && render.modelPaths[0] != "-" &&
      (SameFile(goldenPath, render.modelPaths[0]) || SameFile(newPath, render.modelPaths[0]))) {
    return Usage("--expect " + goldenPath + " is the model itself");
  }

  // Step 2: the golden, whose options make the frames. Options that say
  // otherwise are refused, unless --update: then they replace the golden's.
  bool haveGolden = false;
  struct stat info {};
  if (stat(goldenPath.c_str(), &info) == 0 || errno != ENOENT) {
    Loaded<SnapshotGolden> read = ReadSnapshotGolden(goldenPath);
    if (!read.Ok() && !update) {
      std::cerr << read.Error().ToString(true) << "\n";
      return 1;
    }
    if (read.Ok() && update) {
      golden.settings = WithGivenOptions(read.Value().settings, golden.settings, renderCommand);
      golden.settings.views = views ? *views : read.Value().settings.views;
      if (renderCommand.count("--up") == 0) golden.upAxis = read.Value().upAxis;
    } else if (read.Ok()) {
      if (const auto problem = Contradiction(render, render.upAxis, read.Value(), renderCommand)) {
        return Usage(*problem + " (drop the option, or pass --update to rewrite the golden)");
      }
      if (views && *views != read.Value().settings.views) {
        return Usage("--views " + snapshot.views + " contradicts the golden's views " +
                     JoinViews(read.Value().settings.views));
      }
      golden = std::move(read.Value());
      haveGolden = true;
    }
  }
  SnapshotSettings& settings = golden.settings;
  settings.threads = render.threads;
  const int64_t perView = int64_t{settings.widthCells} * settings.samples.across *
                          settings.heightCells * settings.samples.down;
  if (perView > kMaxSnapshotViewSamples) {
    return Usage("--size is too large for a snapshot: at most " +
                 std::to_string(kMaxSnapshotViewSamples / settings.samples.Count()) +
                 " cells (e.g. 160x48)");
  }

  // Step 3: the model, drawn in every view.
  LoadOptions loadOptions(render.loadLimits);
  loadOptions.formatHint = render.inputFormat;
  loadOptions.importerOnly = render.reader == "assimp";
  Loaded<Mesh> mesh = LoadModelFile(render.modelPaths[0], loadOptions);
  if (!mesh.Ok()) {
    std::cerr << mesh.Error().ToString() << "\n";
    return 1;
  }
  const Scene scene = PrepareScene(std::move(mesh.Value()), golden.upAxis);
  SnapshotGolden actual;
  actual.settings = settings;
  actual.upAxis = golden.upAxis;
  actual.frames = RenderSnapshot(scene, settings);
  const std::string actualText = FormatSnapshotGolden(actual);

  // Step 4: written, or compared.
  if (update) {
    if (const auto problem = WriteWhole(goldenPath, actualText)) {
      std::cerr << shownGolden << ": " << SanitizeForTerminal(*problem) << "\n";
      return 1;
    }
    RemoveStaleNew(newPath);
    std::cerr << "termshade: wrote " << shownGolden << " (" << actual.frames.size()
              << " views: " << JoinViews(settings.views) << ")\n";
    return 0;
  }
  const auto writeNew = [&]() -> bool {
    if (const auto problem = WriteWhole(newPath, actualText)) {
      std::cerr << SanitizeForTerminal(newPath, 1000) << ": " << SanitizeForTerminal(*problem)
                << "\n";
      return false;
    }
    return true;
  };
  if (!haveGolden) {
    const bool written = writeNew();
    std::cerr << shownGolden << ": no golden yet: run with --update";
    if (written)
      std::cerr << " (or review " << SanitizeForTerminal(newPath, 1000) << " and rename it)";
    std::cerr << "\n";
    return 1;
  }
  const SnapshotOutcome outcome = CompareSnapshotFrames(golden.frames, actual.frames, *tolerance);
  if (outcome.Passed()) {
    RemoveStaleNew(newPath);
    return 0;
  }
  std::cerr << SnapshotReport(outcome, golden.frames, actual.frames, settings, *tolerance,
                              ColourOnStderr());
  const auto failing = std::count_if(outcome.views.begin(), outcome.views.end(),
                                     [](const SnapshotViewOutcome& v) { return !v.within; });
  std::cerr << shownGolden << ": " << failing << " of " << outcome.views.size() << " views differ";
  if (writeNew()) {
    std::cerr << "; the actual frames are in " << SanitizeForTerminal(newPath, 1000)
              << " (review: diff " << shownGolden << " " << SanitizeForTerminal(newPath, 1000)
              << "; accept: mv it over the golden, or run with --update)";
  }
  std::cerr << "\n";
  return 1;
}

}  // namespace termshade
