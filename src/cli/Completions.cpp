#include "cli/Completions.h"

#include <functional>

namespace termshade {

namespace {

std::string Join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string joined;
  for (const std::string& part : parts) joined += (joined.empty() ? "" : separator) + part;
  return joined;
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

/// Text inside single quotes in bash and zsh.
std::string SingleQuoted(const std::string& text) {
  return "'" + Replace(text, "'", "'\\''") + "'";
}

void ForEachCommand(const CommandModel& command,
                    const std::function<void(const CommandModel&)>& visit) {
  visit(command);
  for (const CommandModel& sub : command.subcommands) ForEachCommand(sub, visit);
}

/// Every step from a command to a subcommand: ("termshade bench", "terminal",
/// "termshade bench terminal"); the scripts follow them word by word.
void ForEachSubcommandStep(
    const CommandModel& root,
    const std::function<void(const std::string&, const std::string&, const std::string&)>& visit) {
  ForEachCommand(root, [&visit](const CommandModel& command) {
    for (const CommandModel& sub : command.subcommands) {
      visit(Join(command.path, " "), sub.path.back(), Join(sub.path, " "));
    }
  });
}

/// The command's name as a shell identifier: termshade_bench_terminal.
std::string Identifier(const CommandModel& command) {
  return Join(command.path, "_");
}

const OptionModel* Positional(const CommandModel& command) {
  for (const OptionModel& option : command.options) {
    if (!option.positionalName.empty()) return &option;
  }
  return nullptr;
}

std::vector<std::string> SubcommandNames(const CommandModel& command) {
  std::vector<std::string> names;
  for (const CommandModel& sub : command.subcommands) names.push_back(sub.path.back());
  return names;
}

std::string FirstLine(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// ---- bash -------------------------------------------------------------------

void WriteBashValueCases(const CommandModel& command, std::ostream& out) {
  const std::string path = Join(command.path, " ");
  for (const OptionModel& option : command.options) {
    if (option.names.empty() || option.valueKind == ValueKind::kNone) continue;
    std::vector<std::string> patterns;
    for (const std::string& name : option.names) {
      patterns.push_back(SingleQuoted(std::string(path).append("/").append(name)));
    }
    out << "    " << Join(patterns, " | ") << ")\n      ";
    switch (option.valueKind) {
      case ValueKind::kChoice:
        out << "mapfile -t COMPREPLY < <(compgen -W " << SingleQuoted(Join(option.choices, " "))
            << " -- \"$cur\")";
        break;
      case ValueKind::kModelFile:
        out << "_termshade_models \"$cur\"";
        break;
      case ValueKind::kFile:
        out << "_termshade_files -f \"$cur\"";
        break;
      case ValueKind::kDirectory:
        out << "_termshade_files -d \"$cur\"";
        break;
      default:
        out << ":";  // a number or free text: nothing to offer
    }
    out << "\n      return ;;\n";
  }
}

void WriteBashCommandCase(const CommandModel& command, std::ostream& out) {
  std::vector<std::string> optionNames;
  for (const OptionModel& option : command.options) {
    optionNames.insert(optionNames.end(), option.names.begin(), option.names.end());
  }
  out << "    " << SingleQuoted(Join(command.path, " ")) << ")\n";
  out << "      options=" << SingleQuoted(Join(optionNames, " "))
      << " subcommands=" << SingleQuoted(Join(SubcommandNames(command), " "));
  const OptionModel* positional = Positional(command);
  out << " models=" << (positional != nullptr && positional->valueKind == ValueKind::kModelFile)
      << " ;;\n";
}

// ---- zsh --------------------------------------------------------------------

std::string ZshBracketed(const std::string& text) {
  return Replace(Replace(Replace(FirstLine(text), "\\", "\\\\"), "[", "\\["), "]", "\\]");
}

std::string ZshAction(const OptionModel& option) {
  const std::string message =
      Replace(option.valueName.empty() ? option.positionalName : option.valueName, ":", "\\:");
  switch (option.valueKind) {
    case ValueKind::kChoice:
      return message + ":(" + Join(option.choices, " ") + ")";
    case ValueKind::kModelFile:
      return "model file:_termshade_models";
    case ValueKind::kFile:
      return "file:_files";
    case ValueKind::kDirectory:
      return "directory:_files -/";
    default:
      return message + ": ";
  }
}

void WriteZshCommandFunction(const CommandModel& command, std::ostream& out) {
  const std::string id = Identifier(command);
  const OptionModel* positional = Positional(command);
  if (!command.subcommands.empty()) {
    out << "_termshade_arguments_" << id << "() {\n  local -a commands=(\n";
    for (const CommandModel& sub : command.subcommands) {
      out << "    " << SingleQuoted(sub.path.back() + ":" + FirstLine(sub.description)) << "\n";
    }
    out << "  )\n  local ret=1\n  _describe -t commands command commands && ret=0\n";
    if (positional != nullptr && positional->valueKind == ValueKind::kModelFile) {
      out << "  _termshade_models && ret=0\n";
    }
    out << "  return ret\n}\n\n";
  }
  out << "_termshade_command_" << id << "() {\n  _arguments -s -S \\\n";
  for (const OptionModel& option : command.options) {
    if (option.names.empty()) continue;
    const std::string exclusive =
        option.names.size() > 1 ? "(" + Join(option.names, " ") + ")" : "";
    for (const std::string& name : option.names) {
      std::string spec = exclusive + name + "[" + ZshBracketed(option.description) + "]";
      if (option.valueKind != ValueKind::kNone) spec += ":" + ZshAction(option);
      out << "    " << SingleQuoted(spec) << " \\\n";
    }
  }
  if (!command.subcommands.empty()) {
    out << "    "
        << SingleQuoted(std::string(positional != nullptr ? "*" : "1") +
                        ":argument:_termshade_arguments_" + id)
        << "\n}\n\n";
  } else if (positional != nullptr) {
    out << "    "
        << SingleQuoted(std::string(positional->repeatable ? "*" : "1") + ":" +
                        ZshAction(*positional))
        << "\n}\n\n";
  } else {
    out << "\n}\n\n";
  }
}

// ---- fish -------------------------------------------------------------------

std::string FishQuoted(const std::string& text) {
  return "'" + Replace(Replace(text, "\\", "\\\\"), "'", "\\'") + "'";
}

void WriteFishCommand(const CommandModel& command, std::ostream& out) {
  const std::string condition = "-n " + FishQuoted("__termshade_is " + Join(command.path, " "));
  for (const CommandModel& sub : command.subcommands) {
    out << "complete -c termshade " << condition << " -a " << sub.path.back() << " -d "
        << FishQuoted(FirstLine(sub.description)) << "\n";
  }
  for (const OptionModel& option : command.options) {
    out << "complete -c termshade " << condition;
    if (option.names.empty()) {
      if (option.valueKind != ValueKind::kModelFile) {
        out << " -x\n";
        continue;
      }
      out << " -a '(__termshade_models)'\n";
      continue;
    }
    for (const std::string& name : option.names) {
      out << (name.rfind("--", 0) == 0 ? " -l " + name.substr(2) : " -s " + name.substr(1));
    }
    switch (option.valueKind) {
      case ValueKind::kNone:
        break;
      case ValueKind::kChoice:
        out << " -x -a " << FishQuoted(Join(option.choices, " "));
        break;
      case ValueKind::kModelFile:
        out << " -x -a '(__termshade_models)'";
        break;
      case ValueKind::kFile:
        out << " -r -F";
        break;
      case ValueKind::kDirectory:
        out << " -x -a '(__fish_complete_directories)'";
        break;
      default:
        out << " -x";
    }
    out << " -d " << FishQuoted(FirstLine(option.description)) << "\n";
  }
}

}  // namespace

void WriteBashCompletion(const CommandModel& root, const std::vector<std::string>& modelExtensions,
                         std::ostream& out) {
  out << "# bash completion for termshade; made by `termshade --generate bash`.\n\n"
         "# Directories and model files starting with $1.\n"
         "_termshade_models() {\n"
         "  local file\n"
         "  local -a found\n"
         "  compopt -o filenames 2>/dev/null\n"
         "  mapfile -t found < <(compgen -f -- \"$1\")\n"
         "  for file in \"${found[@]}\"; do\n"
         "    if [[ -d $file ]]; then COMPREPLY+=(\"$file\"); continue; fi\n"
         "    case \"${file,,}\" in\n"
         "      *."
      << Join(modelExtensions, " | *.")
      << ") COMPREPLY+=(\"$file\") ;;\n"
         "    esac\n"
         "  done\n"
         "}\n\n"
         "# Files (-f) or directories (-d) starting with $2.\n"
         "_termshade_files() {\n"
         "  compopt -o filenames 2>/dev/null\n"
         "  mapfile -t COMPREPLY < <(compgen \"$1\" -- \"$2\")\n"
         "}\n\n"
         "_termshade() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}\n"
         "  # --option=value: readline splits at the =.\n"
         "  if [[ $cur == = ]]; then cur=''; elif [[ $prev == = ]]; then "
         "prev=${COMP_WORDS[COMP_CWORD - 2]}; fi\n"
         "  COMPREPLY=()\n"
         "  local command=termshade i\n"
         "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
         "    case \"$command/${COMP_WORDS[i]}\" in\n";
  ForEachSubcommandStep(
      root, [&out](const std::string& from, const std::string& word, const std::string& to) {
        out << "      " << SingleQuoted(from + "/" + word) << ") command=" << SingleQuoted(to)
            << " ;;\n";
      });
  out << "    esac\n"
         "  done\n"
         "  case \"$command/$prev\" in\n";
  ForEachCommand(root, [&out](const CommandModel& command) { WriteBashValueCases(command, out); });
  out << "  esac\n"
         "  local options subcommands models\n"
         "  case \"$command\" in\n";
  ForEachCommand(root, [&out](const CommandModel& command) { WriteBashCommandCase(command, out); });
  out << "  esac\n"
         "  if [[ $cur == -* ]]; then\n"
         "    mapfile -t COMPREPLY < <(compgen -W \"$options\" -- \"$cur\")\n"
         "    return\n"
         "  fi\n"
         "  mapfile -t COMPREPLY < <(compgen -W \"$subcommands\" -- \"$cur\")\n"
         "  if [[ $models == 1 ]]; then _termshade_models \"$cur\"; fi\n"
         "}\n\n"
         "complete -F _termshade termshade\n";
}

void WriteZshCompletion(const CommandModel& root, const std::vector<std::string>& modelExtensions,
                        std::ostream& out) {
  out << "#compdef termshade\n"
         "# zsh completion for termshade; made by `termshade --generate zsh`.\n\n"
         "_termshade_models() {\n"
         "  _files -g '*.(#i)("
      << Join(modelExtensions, "|") << ")(-.)'\n}\n\n";
  ForEachCommand(root,
                 [&out](const CommandModel& command) { WriteZshCommandFunction(command, out); });
  // Dispatch: find the subcommand, then complete its words alone.
  out << "_termshade() {\n"
         "  local command=termshade i start=1\n"
         "  for ((i = 2; i < CURRENT; i++)); do\n"
         "    case \"$command/$words[i]\" in\n";
  ForEachSubcommandStep(
      root, [&out](const std::string& from, const std::string& word, const std::string& to) {
        out << "      " << SingleQuoted(from + "/" + word) << ") command=" << SingleQuoted(to)
            << "; start=$i ;;\n";
      });
  out << "    esac\n"
         "  done\n"
         "  if ((start > 1)); then\n"
         "    words=(\"${(@)words[start,-1]}\")\n"
         "    ((CURRENT -= start - 1))\n"
         "  fi\n"
         "  case $command in\n";
  ForEachCommand(root, [&out](const CommandModel& command) {
    out << "    " << SingleQuoted(Join(command.path, " ")) << ") _termshade_command_"
        << Identifier(command) << " ;;\n";
  });
  out << "  esac\n"
         "}\n\n"
         "_termshade \"$@\"\n";
}

void WriteFishCompletion(const CommandModel& root, const std::vector<std::string>& modelExtensions,
                         std::ostream& out) {
  out << "# fish completion for termshade; made by `termshade --generate fish`.\n\n"
         "# The command the words so far name: \"termshade\", \"termshade bench terminal\".\n"
         "function __termshade_command\n"
         "    set -l command termshade\n"
         "    for word in (commandline -opc)[2..-1]\n"
         "        switch \"$command/$word\"\n";
  ForEachSubcommandStep(
      root, [&out](const std::string& from, const std::string& word, const std::string& to) {
        out << "            case " << FishQuoted(from + "/" + word)
            << "\n                set command " << FishQuoted(to) << "\n";
      });
  out << "        end\n"
         "    end\n"
         "    echo $command\n"
         "end\n\n"
         "function __termshade_is\n"
         "    test (__termshade_command) = \"$argv\"\n"
         "end\n\n"
         "# Directories and model files starting with the current word.\n"
         "function __termshade_models\n"
         "    set -l found (commandline -ct)*\n"
         "    for file in $found\n"
         "        if test -d $file\n"
         "            echo $file/\n"
         "            continue\n"
         "        end\n"
         "        switch (string lower -- $file)\n"
         "            case '*."
      << Join(modelExtensions, "' '*.")
      << "'\n"
         "                echo $file\n"
         "        end\n"
         "    end\n"
         "end\n\n"
         "complete -c termshade -f\n";
  ForEachCommand(root, [&out](const CommandModel& command) { WriteFishCommand(command, out); });
}

}  // namespace termshade
