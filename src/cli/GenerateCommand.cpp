#include "cli/GenerateCommand.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <vector>

#include "io/read/LoadError.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/DatWriter.h"
#include "io/write/MeshExport.h"
#include "io/write/OutputFile.h"

namespace termshade {
namespace {

// The file replaced whole, through its links (OutputFile.h).
bool WriteFile(const std::string& path, const std::string& text) {
  OutputFile file(path);
  auto problem = file.Open();
  if (!problem) problem = file.Write(text);
  if (!problem) problem = file.Commit();
  if (problem)
    std::cerr << SanitizeForTerminal(path) << ": " << SanitizeForTerminal(*problem) << "\n";
  return !problem;
}

int WriteAll(const std::string& directory) {
  if (directory.empty()) {
    std::cerr << "termshade generate: 'all' needs -o DIRECTORY\n";
    return 2;
  }
  for (const std::string& scene : GeneratedSceneNames()) {
    std::string path = directory;
    path += '/';
    path += scene;
    path += ".dat";
    if (!WriteFile(path, WriteDat(*GenerateScene(scene)))) return 1;
  }
  return 0;
}

}  // namespace

int RunGenerateCommand(const GenerateCommandOptions& options) {
  if (options.name == "all") return WriteAll(options.outputPath);
  // Step 1: the arguments, before any work (a 50M-triangle sphere takes 20 s).
  const std::vector<std::string>& scenes = GeneratedSceneNames();
  if (options.name != "sphere" &&
      std::find(scenes.begin(), scenes.end(), options.name) == scenes.end()) {
    std::cerr << "termshade generate: unknown scene '" << SanitizeForTerminal(options.name)
              << "' (known: all, sphere";
    for (const std::string& scene : scenes) std::cerr << ", " << scene;
    std::cerr << ")\n";
    return 2;
  }
  std::optional<ExportFormat> format = ExportFormat::kDat;
  if (!options.outputPath.empty()) format = ExportFormatFromPath(options.outputPath);
  if (!format) {
    std::cerr << "termshade generate: " << SanitizeForTerminal(options.outputPath)
              << ": the extension must be .dat, .obj, .stl or .ply\n";
    return 2;
  }
  // Step 2: the scene, to standard output or a file replaced whole.
  const std::optional<Mesh> mesh = options.name == "sphere"
                                       ? GenerateTriangleSphere(options.triangles)
                                       : GenerateScene(options.name);
  if (!mesh) return 2;
  if (options.outputPath.empty()) {
    if (const auto problem = WriteWhole(STDOUT_FILENO, WriteDat(*mesh))) {
      std::cerr << "termshade generate: standard output: " << SanitizeForTerminal(*problem) << "\n";
      return 1;
    }
    return 0;
  }
  return WriteFile(options.outputPath, ExportMesh(*mesh, *format)) ? 0 : 1;
}

}  // namespace termshade
