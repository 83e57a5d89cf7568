#include "cli/GenerateCommand.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>

#include "io/read/LoadError.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/DatWriter.h"
#include "io/write/MeshExport.h"

namespace termshade {
namespace {

bool WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) {
    std::cerr << SanitizeForTerminal(path) << ": cannot write: " << std::strerror(errno) << "\n";
  }
  return static_cast<bool>(out);
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
  std::optional<Mesh> mesh;
  if (options.name == "sphere") {
    mesh = GenerateTriangleSphere(options.triangles);
  } else {
    mesh = GenerateScene(options.name);
  }
  if (!mesh) {
    std::cerr << "termshade generate: unknown scene '" << SanitizeForTerminal(options.name)
              << "' (known: all, sphere";
    for (const std::string& scene : GeneratedSceneNames()) std::cerr << ", " << scene;
    std::cerr << ")\n";
    return 2;
  }
  if (options.outputPath.empty()) {
    std::cout << WriteDat(*mesh);
    return std::cout ? 0 : 1;
  }
  const auto format = ExportFormatFromPath(options.outputPath);
  if (!format) {
    std::cerr << "termshade generate: " << SanitizeForTerminal(options.outputPath)
              << ": the extension must be .dat, .obj, .stl or .ply\n";
    return 2;
  }
  return WriteFile(options.outputPath, ExportMesh(*mesh, *format)) ? 0 : 1;
}

}  // namespace termshade
