#include "support/TestSupport.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/FitCamera.h"
#include "io/load/ModelLoader.h"
#include "io/write/FrameFormats.h"
#include "raster/Renderer.h"

namespace termshade::test {

std::string SourcePath(const std::string& relative) {
  return std::string(TERMSHADE_SOURCE_DIR) + "/" + relative;
}

ScratchFolder::ScratchFolder(const std::string& name)
    : path_((std::filesystem::temp_directory_path() / (name + "-" + std::to_string(getpid())))
                .string()) {
  std::filesystem::create_directories(path_);
}

ScratchFolder::~ScratchFolder() {
  std::error_code error;
  std::filesystem::remove_all(path_, error);
}

std::string ScratchFolder::Write(const std::string& name, const std::string& bytes) const {
  const std::string file = (std::filesystem::path(path_) / name).string();
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Mesh LoadMesh(const std::string& relative) {
  Loaded<Mesh> mesh = LoadModelFile(SourcePath(relative));
  if (!mesh.Ok()) {
    ADD_FAILURE() << mesh.Error().ToString();
    return Mesh{};
  }
  return std::move(mesh.Value());
}

Scene LoadScene(const std::string& relative) {
  return PrepareScene(LoadMesh(relative));
}

std::string Frame::Text() const {
  std::string text;
  AppendTextFrame(cells, text);
  return text;
}

Frame RenderFrame(const Scene& scene, double theta, double phi, int widthCells, int heightCells,
                  const RenderOptions& options, double rho, double cellAspect) {
  ViewParams view = DefaultView(scene.diagonalModelUnits);
  view.theta = theta;
  view.phi = phi;
  if (rho > 0.0) view.rho = rho;
  Frame frame;
  frame.camera = FitCamera(scene, view, widthCells, heightCells, cellAspect);
  frame.cells.Resize(widthCells, heightCells);
  frame.depth.Resize(widthCells, heightCells);
  Renderer renderer;
  renderer.Render(scene, frame.camera, options, frame.depth, frame.cells);
  return frame;
}

Mesh QuadMesh(const std::vector<std::array<Vec3, 4>>& quads) {
  Mesh mesh;
  for (const auto& quad : quads) {
    const auto base = static_cast<uint32_t>(mesh.verticesFile.size());
    for (const Vec3& p : quad) mesh.verticesFile.push_back(p);
    mesh.AddFace(std::array<uint32_t, 4>{base, base + 1, base + 2, base + 3});
  }
  return mesh;
}

Scene ShiftedScene(Scene scene, Vec3 shiftWorld) {
  scene.radiusModelUnits = scene.horizontalRadiusModelUnits = 0.0;
  for (Vec3& p : scene.verticesWorld) {
    p = p + shiftWorld;
    if (!IsFinite(p)) continue;
    scene.radiusModelUnits = std::max(scene.radiusModelUnits, Length(p));
    scene.horizontalRadiusModelUnits =
        std::max(scene.horizontalRadiusModelUnits, std::hypot(p.x, p.y));
  }
  // n . p = h for every p of the plane: moved by s, h grows by n . s.
  for (FacePlane& plane : scene.facePlanesWorld) plane.offset += Dot(plane.normal, shiftWorld);
  scene.clusters = BuildClusters(scene);
  scene.worldFromFile = Mat4::Translation(shiftWorld) * scene.worldFromFile;
  scene.source.shiftZUp = scene.source.shiftZUp - shiftWorld;
  return scene;
}

std::string FrameText(Mesh mesh) {
  mesh.upAxisFile = UpAxis::kPlusZ;
  const Scene scene = PrepareScene(std::move(mesh));
  return RenderFrame(scene, 0.3, 1.3, 80, 24, RenderOptions{}).Text();
}

std::string ReadResultText(std::optional<Loaded<Mesh>> read) {
  if (!read) return "(importer)";
  if (!read->Ok()) return read->Error().ToString();
  const Mesh& mesh = read->Value();
  std::string text;
  for (const Vec3& p : mesh.verticesFile) {
    text += std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.z) + " ";
  }
  for (const uint32_t c : mesh.faceCorners) text += std::to_string(c) + ",";
  for (const uint32_t f : mesh.faceStarts) text += std::to_string(f) + ";";
  for (const auto& g : mesh.segments)
    text += std::to_string(g[0]) + "-" + std::to_string(g[1]) + " ";
  for (const uint8_t h : mesh.edgeHidden) text += static_cast<char>('0' + h);
  return text;
}

TermColour IndexedColour(int index) {
  TermColour colour;
  colour.kind = TermColour::Kind::kIndexed;
  colour.index = static_cast<uint8_t>(index);
  return colour;
}

}  // namespace termshade::test
