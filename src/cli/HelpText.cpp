#include "cli/HelpText.h"

#include <algorithm>
#include <exception>
#include <iostream>
#include <vector>

#include "cli/CommandModel.h"
#include "cli/Completions.h"
#include "cli/ManPage.h"
#include "io/load/ModelExtensions.h"
#include "io/read/LoadError.h"
#include "tui/ViewerKeys.h"

namespace termshade {

namespace {

/// Levenshtein distance (insertions, deletions, substitutions).
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

size_t CommonPrefix(const std::string& a, const std::string& b) {
  size_t length = 0;
  while (length < a.size() && length < b.size() && a[length] == b[length]) ++length;
  return length;
}

/// The known names closest to `given`: those it begins (sorted), else the
/// nearest within half its length (at least 2 edits), ties to the longer
/// shared beginning; empty when none is near.
std::vector<std::string> Nearest(const std::string& given, const std::vector<std::string>& known) {
  std::vector<std::string> extending;
  for (const std::string& name : known) {
    if (given.size() >= 3 && name.rfind(given, 0) == 0) extending.push_back(name);
  }
  if (!extending.empty()) {
    std::sort(extending.begin(), extending.end());
    return extending;
  }
  std::string best;
  size_t bestDistance = std::max<size_t>(2, given.size() / 2) + 1, bestPrefix = 0;
  for (const std::string& name : known) {
    const size_t distance = EditDistance(given, name), prefix = CommonPrefix(given, name);
    if (distance < bestDistance ||
        (distance == bestDistance && !best.empty() && prefix > bestPrefix)) {
      bestDistance = distance;
      bestPrefix = prefix;
      best = name;
    }
  }
  if (best.empty()) return {};
  return {best};
}

struct CommandExamples {
  const char* path;  ///< subcommand names after "termshade", space-separated
  std::vector<Example> examples;
};

const std::vector<CommandExamples>& AllExamples() {
  static const std::vector<CommandExamples> kExamples{
      {"",
       {{"termshade", "the viewer on the embedded demo scene"},
        {"termshade car.obj plane.stl", "the viewer on two models; n and p switch"},
        {"termshade --method wire --mono part.ply", "wireframe, without colour"},
        {"termshade --lod off scan.ply", "every frame from the full model (no level of detail)"}}},
      {"render",
       {{"termshade render car.obj", "one 80x24 text frame to stdout"},
        {"termshade render car.obj --size 120x40 --theta 0.8 --phi 1.1 --shade lambert",
         "a bigger frame from another side, shaded as the viewer does"},
        {"termshade render car.obj --format ansi --frames 36 --step 0.1745 -o spin.txt",
         "a turntable of 36 coloured frames, 10 degrees apart, into a file"},
        {"termshade render part.stl --format json --method auto", "one frame as a JSON object"},
        {"termshade render bunny.obj --up z --theta 30deg",
         "a z-up file read as such, angle in degrees"},
        {"termshade render a.obj b.stl --size 60x20", "two models, one frame each, in turn"},
        {"termshade render duck.dae --fit", "framed as the viewer frames it (larger, orbit-safe)"},
        {"termshade render part.stl --expect part.snap",
         "snapshot test: compare with the golden (write it once with --update)"}}},
      {"info",
       {{"termshade info car.obj",
         "reader, counts, bounds, up axis, open edges, colours, load "
         "time and peak memory"},
        {"termshade info --format json parts/*.stl", "one JSON object a model, for scripts"}}},
      {"generate",
       {{"termshade generate sphere_cone", "the demo scene as .dat to stdout"},
        {"termshade generate all -o data", "every shipped scene into data/"},
        {"termshade generate sphere --triangles 2000000 -o big.stl",
         "a test sphere of about 2 million triangles as binary STL"}}},
      {"bench",
       {{"termshade bench terminal", "what the viewer sends to the terminal"},
        {"termshade bench methods", "speed against error of every method"}}},
      {"bench terminal",
       {{"termshade bench terminal", "the demo scene at 160x48, 10 s idle"},
        {"termshade bench terminal car.obj --cols 100 --rows 30 --idle-seconds 2 --no-strace",
         "another model and size, without strace"},
        {"termshade bench terminal big.ply --lod off --settle-seconds 20 --no-strace",
         "turntable pacing of a big model drawn in full"}}},
      {"bench load",
       {{"termshade bench load",
         "load time, peak memory and frame time, 0.2 and 2 million triangles"},
        {"termshade bench load --triangles 100000 --formats stl --repeats 1", "one quick case"}}},
      {"bench frame",
       {{"termshade bench frame",
         "ms per frame: demo, 0.2 and 2 million triangles x 80x24, 160x48, 400x120; 1 thread, all"},
        {"termshade bench frame --models scan.ply --sizes 160x48 --threads 2",
         "one model, one size, 2 threads against 1"}}},
      {"bench snapshots",
       {{"termshade bench snapshots",
         "detection rate of render --expect, shipped and corpus models"},
        {"termshade bench snapshots --models part.stl --trials 50 --tolerances 0 0.5%",
         "one model, more moves, two tolerances"}}},
      {"bench fidelity",
       {{"termshade bench fidelity",
         "in the source folder: every glyph mode's SSIM, time and flicker, CSV and SVG"},
        {"termshade bench fidelity --frames 1 --seconds 0.05", "one quick pass"},
        {"termshade bench fidelity --scene sphere_cone --timing-only --seconds 1",
         "frame times of every mode on one scene, interleaved"}}},
      {"bench models",
       {{"termshade bench models car.obj part.stl",
         "per file: loads?, up axis, faces turned outward, colours, ms per frame (TSV)"},
        {"termshade bench models scan.ply --up z", "the same with the up axis given"}}},
      {"bench methods",
       {{"termshade bench methods",
         "in the source folder: a table, docs/bench-methods.csv and .svg"},
        {"termshade bench methods --frames 2 --seconds 0.05 --csv m.csv --svg m.svg",
         "a quick, rougher run"}}},
  };
  return kExamples;
}

void AddExamplesTo(CLI::App& command, const std::string& path) {
  for (const CommandExamples& entry : AllExamples()) {
    if (path == entry.path) SetExamples(command, entry.examples);
  }
  for (CLI::App* sub : command.get_subcommands([](CLI::App*) { return true; })) {
    AddExamplesTo(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name());
  }
}

void ListCommands(const CommandModel& command) {
  std::string path;
  for (size_t i = 1; i < command.path.size(); ++i) path += (i > 1 ? " " : "") + command.path[i];
  std::cout << path << "\n";
  for (const CommandModel& sub : command.subcommands) ListCommands(sub);
}

/// The deepest command the arguments chose.
const CLI::App& ChosenCommand(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) return ChosenCommand(*sub);
  return app;
}

}  // namespace

void AddExamples(CLI::App& app) {
  AddExamplesTo(app, "");
}

void SetUpHelp(CLI::App& app, const std::string& version, std::string& generateWhat) {
  app.set_help_all_flag("--help-all", "all commands' options");
  app.set_version_flag("-V,--version", "termshade " + version, "print the version and exit");
  app.footer(
      [] { return "Keys in the viewer (? shows them there too):\n" + FormatViewerKeys("  "); });
  app.add_option("--generate", generateWhat, "write the man page or a shell completion script")
      ->check(CLI::IsMember({"man", "bash", "zsh", "fish", "commands"}))
      ->group("");  // hidden: the build uses it
}

int RunGenerate(const CLI::App& app, const std::string& version, const std::string& what) {
  const CommandModel root = DescribeCommand(app);
  std::vector<std::string> extensions;
  if (what != "commands") {
    // The man page and completions list Assimp's formats: they need its module.
    try {
      extensions = ModelFileExtensions();
    } catch (const std::exception& e) {
      std::cerr << "termshade: --generate " << what << ": " << SanitizeForTerminal(e.what())
                << "\n";
      return 1;
    }
  }
  if (what == "man") WriteManPage(root, version, extensions, std::cout);
  if (what == "bash") WriteBashCompletion(root, extensions, std::cout);
  if (what == "zsh") WriteZshCompletion(root, extensions, std::cout);
  if (what == "fish") WriteFishCompletion(root, extensions, std::cout);
  if (what == "commands") ListCommands(root);
  std::cout.flush();
  return std::cout ? 0 : 1;
}

std::string NearestOptionHint(const CLI::App& app) {
  const CLI::App& command = ChosenCommand(app);
  std::vector<std::string> known;
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_group().empty()) continue;
    for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
  }
  for (const std::string& argument : app.remaining(true)) {
    if (argument.rfind("--", 0) != 0 || argument.size() < 3) continue;
    const std::string given = argument.substr(0, argument.find('='));
    const std::vector<std::string> nearest = Nearest(given, known);
    if (nearest.empty()) continue;
    std::string hint = "did you mean " + nearest.front();
    for (size_t i = 1; i < nearest.size(); ++i) {
      hint += i + 1 == nearest.size() ? " or " : ", ";
      hint += nearest[i];
    }
    return hint + "?";
  }
  return "";
}

}  // namespace termshade
