#include "cli/GenerateCommand.h"

#include <fstream>
#include <iostream>

#include "io/DatWriter.h"
#include "io/LoadError.h"
#include "io/SceneGenerators.h"

namespace termshade {
namespace {

bool WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) std::cerr << SanitizeForTerminal(path) << ": cannot write\n";
  return static_cast<bool>(out);
}

}  // namespace

int RunGenerateCommand(const std::string& name, const std::string& outputPath) {
  if (name == "all") {
    if (outputPath.empty()) {
      std::cerr << "termshade generate: 'all' needs -o DIRECTORY\n";
      return 2;
    }
    for (const std::string& scene : GeneratedSceneNames()) {
      std::string path = outputPath;
      path += '/';
      path += scene;
      path += ".dat";
      if (!WriteFile(path, WriteDat(*GenerateScene(scene)))) return 1;
    }
    return 0;
  }
  const auto mesh = GenerateScene(name);
  if (!mesh) {
    std::cerr << "termshade generate: unknown scene '" << SanitizeForTerminal(name)
              << "' (known: all";
    for (const std::string& scene : GeneratedSceneNames()) std::cerr << ", " << scene;
    std::cerr << ")\n";
    return 2;
  }
  if (outputPath.empty()) {
    std::cout << WriteDat(*mesh);
    return std::cout ? 0 : 1;
  }
  return WriteFile(outputPath, WriteDat(*mesh)) ? 0 : 1;
}

}  // namespace termshade
