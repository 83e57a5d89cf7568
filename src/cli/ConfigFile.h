#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace termshade {

/// The user's configuration file: $XDG_CONFIG_HOME/termshade/config.toml,
/// else $HOME/.config/termshade/config.toml; empty when neither is set.
std::string UserConfigPath();

/// The file a command line reads options from, decided before parsing:
/// `--config FILE` wherever it stands; else, for the viewer alone and
/// without `--no-config`, the user's file where it exists. `render` reads
/// only a file --config names, so a dump never depends on who runs it.
struct ConfigChoice {
  std::string path;         ///< empty: no file
  bool named = false;       ///< given by --config (a missing file is then an error)
  std::vector<char*> argv;  ///< the arguments, --config moved before a subcommand
};
ConfigChoice ChooseConfig(int argc, char** argv);

/// What is wrong with the chosen file (not a regular file, unreadable, too
/// big), naming it; nullopt when it can be read, or is absent and not named.
std::optional<std::string> ConfigFileProblem(const ConfigChoice& choice);

/// Registers --config FILE, --no-config and --print-config on the app and
/// reads the chosen file with it: TOML keys named as the long options,
/// `[render]` for render's own; a key outside any section that both the
/// viewer and render take (glyphs, color, shade, ...) sets render's too,
/// unless `[render]` sets it. The command line wins over the file.
void AddConfigOptions(CLI::App& app, const ConfigChoice& choice, bool& printConfig);

/// The effective configuration, as a file that --config would read.
std::string EffectiveConfig(const CLI::App& app);

}  // namespace termshade
