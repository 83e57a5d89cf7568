#include "cli/ConfigFile.h"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <sstream>
#include <string_view>

#include "io/read/LoadError.h"

namespace termshade {
namespace {

// A configuration is a few lines: anything longer is not one.
constexpr std::streamsize kMostConfigBytes = 64 * 1024;

// Options the viewer and render both take: a key outside any section sets both.
constexpr std::array<std::string_view, 13> kSharedKeys{
    "method",     "shade", "ramp",          "glyphs",         "no-cull", "threads", "color",
    "background", "mono",  "memory-budget", "import-seconds", "lod",     "textures"};

// TOML as CLI11 reads it, at most kMostConfigBytes, with the shared keys
// outside a section copied into [render].
class SharedKeysToml : public CLI::ConfigTOML {
 public:
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override {
    std::string text(static_cast<size_t>(kMostConfigBytes) + 1, '\0');
    input.read(text.data(), kMostConfigBytes + 1);
    text.resize(static_cast<size_t>(input.gcount()));
    if (text.size() > static_cast<size_t>(kMostConfigBytes))
      throw CLI::ConfigError("over 64 KiB, not a configuration file");
    std::istringstream bounded(text);
    std::vector<CLI::ConfigItem> items = CLI::ConfigTOML::from_config(bounded);
    const auto inRender = [&](const std::string& name) {
      return std::any_of(items.begin(), items.end(), [&](const CLI::ConfigItem& item) {
        return item.parents == std::vector<std::string>{"render"} && item.name == name;
      });
    };
    std::vector<CLI::ConfigItem> copies;
    for (const CLI::ConfigItem& item : items) {
      const bool shared =
          std::find(kSharedKeys.begin(), kSharedKeys.end(), item.name) != kSharedKeys.end();
      if (item.parents.empty() && shared && !inRender(item.name)) {
        CLI::ConfigItem copy = item;
        copy.parents = {"render"};
        copies.push_back(std::move(copy));
      }
    }
    items.insert(items.end(), copies.begin(), copies.end());
    return items;
  }
};

}  // namespace

std::string UserConfigPath() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg != nullptr && xdg[0] == '/') return std::string(xdg) + "/termshade/config.toml";
  const char* home = std::getenv("HOME");
  if (home != nullptr && home[0] == '/')
    return std::string(home) + "/.config/termshade/config.toml";
  return {};
}

ConfigChoice ChooseConfig(int argc, char** argv) {
  ConfigChoice choice;
  choice.argv.assign(argv, argv + argc);
  // Step 1: the subcommand, the first argument that is one (before "--").
  int subcommandAt = -1;
  bool noConfig = false;
  int configAt = -1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;
    if (subcommandAt < 0 &&
        (arg == "render" || arg == "generate" || arg == "bench" || arg == "info"))
      subcommandAt = i;
    if (arg == "--no-config") noConfig = true;
    if (arg == "--config" && i + 1 < argc) configAt = i;
    if (arg.starts_with("--config=")) configAt = i;
  }
  // Step 2: a named file; after render it moves before it, where the option is.
  if (configAt >= 0) {
    const std::string_view arg = argv[configAt];
    choice.named = true;
    choice.path = arg == "--config" ? argv[configAt + 1] : std::string(arg.substr(9));
    const bool hasValue = arg == "--config";
    if (subcommandAt >= 0 && configAt > subcommandAt &&
        std::string_view(argv[subcommandAt]) == "render") {
      const auto first = choice.argv.begin() + configAt;
      std::vector<char*> moved(first, first + (hasValue ? 2 : 1));
      choice.argv.erase(first, first + (hasValue ? 2 : 1));
      choice.argv.insert(choice.argv.begin() + subcommandAt, moved.begin(), moved.end());
    }
    return choice;
  }
  // Step 3: the user's file, for the viewer alone.
  if (subcommandAt < 0 && !noConfig) choice.path = UserConfigPath();
  return choice;
}

std::optional<std::string> ConfigFileProblem(const ConfigChoice& choice) {
  if (choice.path.empty()) return std::nullopt;
  struct stat status {};
  if (stat(choice.path.c_str(), &status) != 0) {
    if (!choice.named) return std::nullopt;  // no user file: the defaults
    return SanitizeForTerminal(choice.path) + ": no such configuration file";
  }
  if (!S_ISREG(status.st_mode))
    return SanitizeForTerminal(choice.path) + ": not a regular file (a configuration is one)";
  if (status.st_size > kMostConfigBytes)
    return SanitizeForTerminal(choice.path) + ": over 64 KiB, not a configuration file";
  return std::nullopt;
}

void AddConfigOptions(CLI::App& app, const ConfigChoice& choice, bool& printConfig) {
  app.config_formatter(std::make_shared<SharedKeysToml>());
  // A key no option has is a mistake to report, not to skip (subcommands
  // made after this inherit it).
  app.allow_config_extras(CLI::config_extras_mode::error);
  app.set_config("--config", choice.path,
                 "read default options from FILE (TOML: keys named as the long options, "
                 "[render] for render's; the viewer reads $XDG_CONFIG_HOME/termshade/config.toml "
                 "by default, render only a file named here)")
      ->type_name("FILE");
  // Acted on before parsing (ChooseConfig); registered so the parser takes it.
  app.add_flag_callback(
      "--no-config", [] {}, "the viewer: do not read the user's configuration file");
  app.add_flag("--print-config", printConfig,
               "print the effective configuration (defaults, file and command line) and exit");
}

std::string EffectiveConfig(const CLI::App& app) {
  return app.config_to_str(true, false);
}

}  // namespace termshade
