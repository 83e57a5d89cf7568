// libFuzzer target: what a user (or a hostile script, or a shared config
// file) hands termshade's option and environment parsing. Byte 0 picks the
// parser, the rest is its text:
//   0 byte counts (--memory-budget), 1 import seconds (--import-seconds),
//   2 the environment (TERMSHADE_MEMORY_BUDGET, TERMSHADE_IMPORT_SECONDS),
//   3 mode names (--color, --glyphs, --lod, --background),
//   4 number checks (FiniteIn, FinitePositive: --rho, --step, ...),
//   5 a configuration file (TOML, read by CLI11 with our formatter).
// Each must end, accept only values in its documented range, and say what
// it refuses in text that, escaped, carries no control bytes.
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "cli/ConfigFile.h"
#include "cli/NumberChecks.h"
#include "geometry/LevelOfDetail.h"
#include "io/read/LoadBudget.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"
#include "shade/Background.h"
#include "shade/ColourMode.h"
#include "shade/GlyphMode.h"

namespace {

using namespace termshade;

void Require(bool condition) {
  if (!condition) std::abort();
}

// Escaped text: no byte below 0x20, no DEL, nothing above 0x7f (keepUtf8 off).
void RequireEscaped(const std::string& text) {
  for (const char c : SanitizeForTerminal(text, 1 << 20)) {
    const auto byte = static_cast<unsigned char>(c);
    Require(byte >= 0x20 && byte != 0x7f && byte < 0x80);
  }
}

void ByteCounts(std::string_view text) {
  if (const auto bytes = ParseByteCount(text)) {
    Require(*bytes >= 1 && *bytes <= (size_t{64} << 40));
  }
}

void ImportSeconds(std::string_view text) {
  if (const auto seconds = ParseImportSeconds(text)) Require(*seconds >= 1 && *seconds <= 86400);
}

// What a front end does first: the variables checked; a valid one is what
// the defaults then use, an invalid one is named in the message.
void Environment(const std::string& text) {
  const std::string value = text.substr(0, text.find('\0'));
  setenv("TERMSHADE_MEMORY_BUDGET", value.c_str(), 1);
  setenv("TERMSHADE_IMPORT_SECONDS", value.c_str(), 1);
  const auto problem = LoadEnvironmentProblem();
  if (problem) {
    Require(problem->find("TERMSHADE_") != std::string::npos);
    RequireEscaped(*problem);
  } else if (!value.empty()) {
    Require(ParseByteCount(value) && ParseImportSeconds(value));
    Require(DefaultMemoryBudgetBytes() == *ParseByteCount(value));
    Require(DefaultImportCpuSeconds() == *ParseImportSeconds(value));
  }
  unsetenv("TERMSHADE_MEMORY_BUDGET");
  unsetenv("TERMSHADE_IMPORT_SECONDS");
}

// A name accepted is a name given back the same (no prefix or case games).
void ModeNames(std::string_view text) {
  if (const auto mode = ParseColourMode(text)) Require(ColourModeName(*mode) == text);
  if (const auto mode = ParseGlyphMode(text)) Require(GlyphModeName(*mode) == text);
  if (const auto mode = ParseDetailMode(text)) Require(DetailModeName(*mode) == text);
  if (const auto background = ParseBackground(text)) Require(BackgroundName(*background) == text);
}

// Accepted numbers are finite and in range, whatever the spelling.
void NumberChecks(const std::string& text) {
  const std::string value = text.substr(0, text.find('\0'));
  CLI::Validator inRange = FiniteIn(-10.0, 10.0), positive = FinitePositive();
  std::string input = value;
  const std::string rangeError = inRange(input);
  input = value;
  const std::string positiveError = positive(input);
  double number = 0;
  const bool parsed = CLI::detail::lexical_cast(value, number);
  if (rangeError.empty()) Require(parsed && std::isfinite(number) && std::abs(number) <= 10.0);
  if (positiveError.empty()) Require(parsed && std::isfinite(number) && number > 0.0);
  RequireEscaped(rangeError);
  RequireEscaped(positiveError);
}

// A configuration file as the front ends read it: parsed, or refused with a
// CLI11 error; never anything else.
void ConfigFile(std::string_view text) {
  const int fd = memfd_create("config.toml", 0);
  if (fd < 0) return;
  if (write(fd, text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
    close(fd);
    return;
  }
  std::string program = "termshade", config = "--config",
              path = "/proc/self/fd/" + std::to_string(fd);
  char* argv[] = {program.data(), config.data(), path.data(), nullptr};
  ConfigChoice choice = ChooseConfig(3, argv);
  CLI::App app("fuzz");
  bool printConfig = false;
  AddConfigOptions(app, choice, printConfig);
  std::string glyphs, colour;
  double rho = 0;
  app.add_option("--glyphs", glyphs);
  app.add_option("--color", colour);
  app.add_option("--rho", rho)->check(FinitePositive());
  CLI::App* render = app.add_subcommand("render");
  std::string renderGlyphs;
  render->add_option("--glyphs", renderGlyphs);
  try {
    app.parse(static_cast<int>(choice.argv.size()), choice.argv.data());
    Require(rho == 0 || (std::isfinite(rho) && rho > 0));
  } catch (const CLI::Error& error) {
    RequireEscaped(error.what());
  }
  close(fd);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 6) {
    case 0:
      ByteCounts(text);
      break;
    case 1:
      ImportSeconds(text);
      break;
    case 2:
      Environment(text);
      break;
    case 3:
      ModeNames(text);
      break;
    case 4:
      NumberChecks(text);
      break;
    default:
      ConfigFile(text);
      break;
  }
  return 0;
}
