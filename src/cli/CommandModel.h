#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace termshade {

/// What an option's value is, for completions: from its CLI11 type name
/// (MODEL, FILE, DIR) or its IsMember check (CHOICE).
enum class ValueKind { kNone, kChoice, kModelFile, kFile, kDirectory, kOther };

/// One option or positional argument as the help, man page and completions see it.
struct OptionModel {
  std::vector<std::string> names;  ///< "-o", "--output"; empty for a positional
  std::string positionalName;      ///< "model"; empty for a named option
  std::string valueName;           ///< "COLSxROWS", "FILE", "zbuffer|painter|..."
  std::string description;
  ValueKind valueKind = ValueKind::kNone;
  std::vector<std::string> choices;
  bool repeatable = false;  ///< positional taking several values (MODEL...)
  bool required = false;
};

/// An example command line and what it does.
struct Example {
  std::string command;
  std::string what;
};

/// A command (the program itself or a subcommand) with what it offers.
struct CommandModel {
  std::vector<std::string> path;  ///< {"termshade", "bench", "terminal"}
  std::string description;
  std::vector<OptionModel> options;  ///< visible ones, help and version included
  std::vector<CommandModel> subcommands;
  std::vector<Example> examples;
  bool subcommandRequired = false;
};

/// Sets the command's help footer to its examples (read back by DescribeCommand).
void SetExamples(CLI::App& command, const std::vector<Example>& examples);

/// The command tree CLI11 was given: every visible option, value and example.
CommandModel DescribeCommand(const CLI::App& app);

}  // namespace termshade
