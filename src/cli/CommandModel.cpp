#include "cli/CommandModel.h"

#include <cctype>
#include <sstream>

namespace termshade {

namespace {

constexpr const char* kExamplesHeading = "Examples:";

std::vector<std::string> ChoicesIn(const std::string& typeName) {
  // CLI::IsMember describes itself as "{a,b,c}".
  const size_t open = typeName.find('{'), close = typeName.find('}', open);
  std::vector<std::string> choices;
  if (open == std::string::npos || close == std::string::npos) return choices;
  std::istringstream list(typeName.substr(open + 1, close - open - 1));
  for (std::string choice; std::getline(list, choice, ',');) choices.push_back(choice);
  return choices;
}

ValueKind KindOf(const std::string& type, bool takesValue, bool hasChoices) {
  if (hasChoices) return ValueKind::kChoice;
  if (type == "MODEL") return ValueKind::kModelFile;
  if (type == "FILE") return ValueKind::kFile;
  if (type == "DIR") return ValueKind::kDirectory;
  return takesValue ? ValueKind::kOther : ValueKind::kNone;
}

OptionModel DescribeOption(const CLI::Option& option) {
  OptionModel model;
  for (const std::string& name : option.get_snames()) model.names.push_back("-" + name);
  for (const std::string& name : option.get_lnames()) model.names.push_back("--" + name);
  if (model.names.empty()) model.positionalName = option.get_name();
  model.description = option.get_description();
  const std::string fullType = option.get_type_name();
  const std::string type = fullType.substr(0, fullType.find(':'));
  model.choices = ChoicesIn(fullType);
  const bool takesValue = option.get_expected_max() > 0;
  model.valueKind = KindOf(type, takesValue, !model.choices.empty());
  if (!model.choices.empty()) {
    for (const std::string& choice : model.choices) {
      model.valueName += (model.valueName.empty() ? "" : "|") + choice;
    }
  } else if (!model.positionalName.empty() && type == "TEXT") {
    for (const char c : model.positionalName) model.valueName += static_cast<char>(std::toupper(c));
  } else if (takesValue) {
    model.valueName = type;
  }
  model.required = option.get_required();
  model.repeatable = !model.positionalName.empty() && option.get_expected_max() > 1;
  return model;
}

std::vector<Example> ExamplesIn(const std::string& footer) {
  std::vector<Example> examples;
  const size_t start = footer.find(kExamplesHeading);
  if (start == std::string::npos) return examples;
  std::istringstream lines(footer.substr(start));
  std::string line;
  std::getline(lines, line);  // the heading
  while (std::getline(lines, line)) {
    if (line.rfind("      ", 0) == 0 && !examples.empty()) {
      examples.back().what += (examples.back().what.empty() ? "" : " ") + line.substr(6);
    } else if (line.rfind("  ", 0) == 0) {
      examples.push_back({line.substr(2), ""});
    }
  }
  return examples;
}

}  // namespace

void SetExamples(CLI::App& command, const std::vector<Example>& examples) {
  std::string footer = kExamplesHeading;
  footer += "\n";
  for (const Example& example : examples) {
    footer += "  " + example.command + "\n      " + example.what + "\n";
  }
  command.footer(footer);
}

CommandModel DescribeCommand(const CLI::App& app) {
  CommandModel command;
  for (const CLI::App* at = &app; at != nullptr; at = at->get_parent()) {
    command.path.insert(command.path.begin(),
                        at->get_parent() == nullptr ? "termshade" : at->get_name());
  }
  command.description = app.get_description();
  command.subcommandRequired = app.get_require_subcommand_min() > 0;
  for (const CLI::Option* option : app.get_options()) {
    if (!option->get_group().empty()) command.options.push_back(DescribeOption(*option));
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    command.subcommands.push_back(DescribeCommand(*sub));
  }
  command.examples = ExamplesIn(app.get_footer());
  return command;
}

}  // namespace termshade
