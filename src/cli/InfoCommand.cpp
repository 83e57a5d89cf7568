#include "cli/InfoCommand.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "geometry/MeshReport.h"
#include "geometry/Scene.h"
#include "io/load/ModelLoader.h"
#include "io/load/TextureReferences.h"
#include "io/read/LoadError.h"
#include "io/write/JsonText.h"

namespace termshade {
namespace {

// Everything one model's report says.
struct ModelInfo {
  std::string path;
  std::string reader;
  MeshReport mesh;
  size_t triangles = 0;
  double diagonal = 0.0;
  std::string fileUp;
  std::string drawnUp;
  bool upOverridden = false;
  size_t facesTurnedOutward = 0;
  std::vector<TextureReference> textures;
  /// Parallel to textures: "drawn, W x H texels", or why not.
  std::vector<std::string> textureStates;
  double loadMs = 0.0;
  double peakMiB = 0.0;        ///< this process, so far
  double helperPeakMiB = 0.0;  ///< the import helpers, so far
};

double PeakMiB(int who) {
  rusage usage{};
  getrusage(who, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

std::string Number(double value, const char* format = "%.6g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string Point(const Vec3& p) {
  return Number(p.x) + ", " + Number(p.y) + ", " + Number(p.z);
}

// Whether each texture is drawn: its size, or why it is not.
std::vector<std::string> TextureStates(const Mesh& mesh) {
  std::vector<std::string> states;
  for (size_t i = 0; i < mesh.textures.size(); ++i) {
    if (i >= mesh.textureImages.size()) {
      states.emplace_back("not drawn: no face has coordinates into it");
    } else if (const TextureImage& image = mesh.textureImages[i]; image.Decoded()) {
      states.push_back("drawn, " + std::to_string(image.widthTexels) + " x " +
                       std::to_string(image.heightTexels) + " texels");
    } else {
      states.push_back("not drawn: " + image.problem);
    }
  }
  return states;
}

// "none named", or each name, where it is and whether it is drawn:
// "1: duckCM.tga (found; drawn, 512 x 512 texels)".
std::string TexturesText(const ModelInfo& info) {
  if (info.textures.empty()) return "none named";
  std::string text = std::to_string(info.textures.size()) + ":";
  for (size_t i = 0; i < info.textures.size(); ++i) {
    text += (i == 0 ? " " : ", ") + SanitizeForTerminal(info.textures[i].name) + " (" +
            std::string(TextureWhereName(info.textures[i].where)) + "; " +
            SanitizeForTerminal(info.textureStates[i]) + ")";
  }
  return text;
}

void PrintText(const ModelInfo& info) {
  const MeshReport& m = info.mesh;
  std::cout << SanitizeForTerminal(info.path, 4096) << "\n"
            << "  reader       " << SanitizeForTerminal(info.reader) << "\n"
            << "  vertices     " << m.vertices << "\n"
            << "  faces        " << m.faces << " (" << info.triangles << " triangles once prepared)"
            << (m.segments > 0 ? ", " + std::to_string(m.segments) + " line segments" : "") << "\n"
            << "  parts        " << m.parts << " (faces joined through shared vertices)\n"
            << "  bounds       " << Point(m.boundsMin) << " .. " << Point(m.boundsMax)
            << " (file units), diagonal " << Number(info.diagonal) << "\n"
            << "  up axis      " << info.fileUp << " in the file (declared, or its format's), "
            << info.drawnUp << (info.upOverridden ? " as asked (--up)" : "") << " drawn up\n"
            << "  orientation  " << info.facesTurnedOutward
            << " faces of inside-out closed parts turned outward\n"
            << "  edges        " << m.openEdges << " open" << (m.openEdges == 0 ? " (closed)" : "")
            << ", " << m.nonManifoldEdges << " shared by three faces or more\n"
            << "  colours      "
            << (m.faceColours == 0 ? std::string("none given (drawn in the default grey)")
                                   : std::to_string(m.faceColours) + " distinct face colours")
            << "\n"
            << "  textures     " << TexturesText(info) << "\n"
            << "  load         " << Number(info.loadMs, "%.1f") << " ms, peak memory "
            << Number(info.peakMiB, "%.1f") << " MiB"
            << (info.reader.starts_with("Assimp (import helper)")
                    ? " (import helpers so far " + Number(info.helperPeakMiB, "%.1f") + " MiB)"
                    : "")
            << "\n";
}

void PrintJson(const ModelInfo& info) {
  const MeshReport& m = info.mesh;
  std::string out = "{\"format\": \"termshade-info/1\", \"file\": ";
  AppendJsonText(SanitizeForTerminal(info.path, 4096), out);
  out += ", \"reader\": ";
  AppendJsonText(info.reader, out);
  out += ", \"vertices\": " + std::to_string(m.vertices) +
         ", \"faces\": " + std::to_string(m.faces) +
         ", \"triangles\": " + std::to_string(info.triangles) +
         ", \"segments\": " + std::to_string(m.segments) +
         ", \"parts\": " + std::to_string(m.parts) + ", \"boundsMin\": [" + Point(m.boundsMin) +
         "], \"boundsMax\": [" + Point(m.boundsMax) + "], \"diagonal\": " + Number(info.diagonal) +
         ", \"upAxisFile\": \"" + info.fileUp + "\", \"upAxisDrawn\": \"" + info.drawnUp +
         "\", \"facesTurnedOutward\": " + std::to_string(info.facesTurnedOutward) +
         ", \"openEdges\": " + std::to_string(m.openEdges) +
         ", \"nonManifoldEdges\": " + std::to_string(m.nonManifoldEdges) +
         ", \"faceColours\": " + std::to_string(m.faceColours) + ", \"textures\": [";
  for (size_t i = 0; i < info.textures.size(); ++i) {
    out += i == 0 ? "{\"name\": " : ", {\"name\": ";
    AppendJsonText(SanitizeForTerminal(info.textures[i].name, 4096), out);
    out += ", \"where\": ";
    AppendJsonText(std::string(TextureWhereName(info.textures[i].where)), out);
    out += ", \"state\": ";
    AppendJsonText(SanitizeForTerminal(info.textureStates[i], 4096), out);
    out += "}";
  }
  out += std::string("]") + ", \"loadMs\": " + Number(info.loadMs, "%.3f") +
         ", \"peakMiB\": " + Number(info.peakMiB, "%.1f") +
         ", \"importHelperPeakMiB\": " + Number(info.helperPeakMiB, "%.1f") + "}\n";
  std::cout << out;
}

}  // namespace

int RunInfoCommand(const InfoCommandOptions& options) {
  if (options.format != "text" && options.format != "json") {
    std::cerr << "termshade info: --format must be text or json\n";
    return 2;
  }
  LoadOptions loadOptions(options.loadLimits);
  loadOptions.importerOnly = options.reader == "assimp";
  int exitCode = 0;
  for (const std::string& path : options.modelPaths) {
    // Step 1: load, timed, as the viewer and render do.
    const auto start = std::chrono::steady_clock::now();
    Loaded<Mesh> loaded = LoadModelFile(path, loadOptions);
    if (!loaded.Ok()) {
      std::cerr << loaded.Error().ToString() << "\n";
      exitCode = 1;
      continue;
    }
    // Step 2: the file's own counts, then the scene drawing would make.
    ModelInfo info;
    info.path = path;
    info.reader = loaded.Value().reader;
    info.mesh = ReportMesh(loaded.Value());
    info.fileUp = UpAxisName(loaded.Value().upAxisFile);
    info.textures = LocateTextures(loaded.Value().textures, path);
    info.textureStates = TextureStates(loaded.Value());
    // Where the loader found what the name alone does not say: in the file,
    // or in the folder under another name.
    for (size_t i = 0; i < info.textures.size() && i < loaded.Value().textureImages.size(); ++i) {
      const TextureImage& image = loaded.Value().textureImages[i];
      if (!image.Decoded()) continue;
      if (!image.readAs.empty()) {
        info.textures[i].where = TextureWhere::kInFolder;
        info.textureStates[i] = "read as " + image.readAs + ", " + info.textureStates[i];
      } else if (info.textures[i].where != TextureWhere::kInFolder) {
        info.textures[i].where = TextureWhere::kEmbedded;
      }
    }
    const Scene scene = PrepareScene(std::move(loaded.Value()), options.upAxis);
    info.loadMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    info.triangles = scene.triangles.size();
    info.diagonal = scene.diagonalModelUnits;
    info.drawnUp = UpAxisName(scene.upAxis);
    info.upOverridden = scene.upAxisOverridden;
    info.facesTurnedOutward = scene.facesTurnedOutward;
    info.peakMiB = PeakMiB(RUSAGE_SELF);
    info.helperPeakMiB = PeakMiB(RUSAGE_CHILDREN);
    // Step 3: the report.
    if (options.format == "json") {
      PrintJson(info);
    } else {
      PrintText(info);
    }
  }
  std::cout.flush();
  return std::cout ? exitCode : 1;
}

}  // namespace termshade
