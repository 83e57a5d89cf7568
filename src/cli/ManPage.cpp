#include "cli/ManPage.h"

#include <array>
#include <sstream>

#include "tui/ViewerKeys.h"

namespace termshade {

namespace {

struct Entry {
  const char* name;
  const char* text;
};

constexpr std::array kEnvironment{
    Entry{"NO_COLOR", "When set (to anything), the viewer draws without colour, as with --mono."},
    Entry{"COLORTERM",
          "truecolor or 24bit: the terminal shows 24-bit colour (read by --color auto where "
          "the program has it)."},
    Entry{"TERM",
          "The terminal type; its terminfo entry gives the viewer's control sequences. Unset or "
          "dumb: the viewer refuses and points to termshade render, which needs no terminal."},
    Entry{"LANG, LC_ALL, LC_CTYPE",
          "The locale; the viewer needs a UTF-8 one to show shade characters beyond ASCII "
          "(--ramp). Dumps are always UTF-8."},
    Entry{"HOME", "Where ~ points in the viewer's open prompt."},
    Entry{"TERMSHADE_MEMORY_BUDGET",
          "The memory budget when --memory-budget is not given (4G, 512M, bytes; default 2G)."},
    Entry{"TERMSHADE_IMPORT_SECONDS",
          "Processor seconds an import through Assimp may take in its helper process when "
          "--import-seconds is not given (1 to 86400); default 30 s and 1 s a MiB of the file."},
};

constexpr std::array kExitStatus{
    Entry{"0", "Success."},
    Entry{"1",
          "Bad input: a model or other file could not be read; the message names the file "
          "(and line:column for .dat) and what was expected."},
    Entry{"2", "Bad usage: an unknown option or a value out of range."},
    Entry{"3", "Internal error."},
    Entry{"128+N", "The viewer was ended by signal N, after restoring the terminal."},
};

/// Text for roff: backslashes and minus signs escaped.
std::string Escape(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '\\') {
      escaped += "\\e";
    } else if (c == '-') {
      escaped += "\\-";
    } else {
      escaped += c;
    }
  }
  return escaped;
}

/// Escaped text lines, none starting with a control character.
std::string Roff(const std::string& text) {
  std::string result;
  std::istringstream lines(Escape(text));
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && (line[0] == '.' || line[0] == '\'')) result += "\\&";
    result += line + "\n";
  }
  return result;
}

std::string Bold(const std::string& text) {
  return "\\fB" + Escape(text) + "\\fR";
}
std::string Italic(const std::string& text) {
  return "\\fI" + Escape(text) + "\\fR";
}

std::string JoinedText(const std::string& text) {
  std::string joined = text;
  for (char& c : joined) {
    if (c == '\n') c = ' ';
  }
  return joined;
}

std::string Usage(const CommandModel& command) {
  std::string usage = Bold(command.path.front());
  for (size_t i = 1; i < command.path.size(); ++i) usage += " " + Bold(command.path[i]);
  std::string positionals;
  bool hasOptions = false;
  for (const OptionModel& option : command.options) {
    if (!option.names.empty()) {
      hasOptions = true;
      continue;
    }
    const std::string name = Italic(option.valueName) + (option.repeatable ? "..." : "");
    positionals += " " + (option.required ? name : "[" + name + "]");
  }
  return usage + (hasOptions ? " [" + Italic("OPTIONS") + "]" : "") + positionals;
}

/// -h, --help and --help-all, said once for the program, not per command.
bool IsHelpOption(const OptionModel& option) {
  for (const std::string& name : option.names) {
    if (name == "--help" || name == "--help-all") return true;
  }
  return false;
}

void WriteOptions(const CommandModel& command, std::ostream& out) {
  for (const OptionModel& option : command.options) {
    if (command.path.size() > 1 && IsHelpOption(option)) continue;
    out << ".TP\n";
    if (option.names.empty()) {
      out << Italic(option.valueName.empty() ? option.positionalName : option.valueName)
          << (option.repeatable ? "..." : "") << "\n";
    } else {
      std::string names;
      for (const std::string& name : option.names)
        names += (names.empty() ? "" : ", ") + Bold(name);
      out << names;
      if (!option.valueName.empty()) out << " " << Italic(option.valueName);
      out << "\n";
    }
    out << Roff(JoinedText(option.description));
  }
}

void WriteLeafUsages(const CommandModel& command, std::ostream& out, bool& first) {
  if (!command.subcommandRequired) {
    if (!first) out << ".br\n";
    out << Usage(command) << "\n";
    first = false;
  }
  for (const CommandModel& sub : command.subcommands) WriteLeafUsages(sub, out, first);
}

void WriteCommands(const CommandModel& command, std::ostream& out) {
  for (const CommandModel& sub : command.subcommands) {
    out << ".SS \"" << Usage(sub) << "\"\n" << Roff(JoinedText(sub.description));
    WriteOptions(sub, out);
    WriteCommands(sub, out);
  }
}

void WriteExamples(const CommandModel& command, std::ostream& out) {
  // A command that only groups others shows its members' examples.
  for (const Example& example :
       command.subcommandRequired ? std::vector<Example>{} : command.examples) {
    out << ".TP\n" << Bold(example.command) << "\n" << Roff(example.what);
  }
  for (const CommandModel& sub : command.subcommands) WriteExamples(sub, out);
}

template <size_t N>
void WriteEntries(const std::array<Entry, N>& entries, std::ostream& out) {
  for (const Entry& entry : entries) {
    out << ".TP\n" << Bold(entry.name) << "\n" << Roff(entry.text);
  }
}

}  // namespace

void WriteManPage(const CommandModel& root, const std::string& version,
                  const std::vector<std::string>& modelExtensions, std::ostream& out) {
  out << ".\\\" termshade(1); made by `termshade --generate man`.\n"
      << ".TH TERMSHADE 1 \"\" \"termshade " << version << "\" \"User Commands\"\n"
      << ".SH NAME\ntermshade \\- shaded 3D polygon models in a terminal\n"
      << ".SH SYNOPSIS\n";
  bool first = true;
  WriteLeafUsages(root, out, first);
  out << ".SH DESCRIPTION\n"
      << "termshade draws 3D polygon models as shaded characters in a terminal. With no "
         "command it opens the interactive viewer on the MODEL files given (the embedded demo "
         "scene if none): orbit with the arrow keys, locally or over SSH. "
      << Bold("termshade render") << " writes the same frames as text, ANSI or JSON, "
      << "with no terminal needed, for tests and tools to compare.\n"
      << ".SH OPTIONS\nThe viewer's options:\n";
  WriteOptions(root, out);
  out << ".SH COMMANDS\n";
  WriteCommands(root, out);
  out << ".SH KEYS\nIn the viewer (also shown by " << Bold("?") << "):\n";
  for (const ViewerKey& key : ViewerKeyTable()) {
    out << ".TP\n" << Bold(std::string(key.keys)) << "\n" << Roff(std::string(key.does));
  }
  out << ".SH FILES\n.TP\n"
      << Italic("MODEL") << ".dat\n"
      << "termshade's own polygon format (a vertex count, vertices, faces as 1-based vertex "
         "lists), read by its own parser; errors name file:line:column.\n"
      << ".TP\n"
      << Italic("MODEL") << ".obj, .stl, .ply, .off, .gltf, ...\n"
      << "Read through the Open Asset Import Library (Assimp) with polygons kept (binary STL, "
         "PLY and plain OBJ by termshade's own readers). Assimp sits in the module "
         "termshade-assimp.so, in the termshade folder of the library directory beside the "
         "program's, loaded only for a file that needs it; each import runs in a child "
         "process, termshade-import, beside it, under memory and processor-time limits, so "
         "a file that crashes or hangs the importer is refused (exit 1). Every extension read: ";
  std::string list;
  for (const std::string& extension : modelExtensions) {
    list += (list.empty() ? "" : ", ") + std::string(".") + extension;
  }
  out << Roff(list + ".");
  out << ".SH ENVIRONMENT\n";
  WriteEntries(kEnvironment, out);
  out << ".SH EXIT STATUS\n";
  WriteEntries(kExitStatus, out);
  out << ".SH EXAMPLES\n";
  WriteExamples(root, out);
  out << ".SH SEE ALSO\n"
      << "The README, installed as " << Italic("share/doc/termshade/README.md")
      << " under the install prefix, describes how frames are made and measured.\n";
}

}  // namespace termshade
