// The dedicated STL, PLY and OBJ readers against the reference, Assimp: the
// same frame and the same face seen in every cell, on every such test model
// (tests/models, and the Assimp test models when installed).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/load/ModelLoader.h"
#include "io/read/OwnReaders.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> ModelsWithOwnReaders() {
  std::vector<std::string> paths;
  for (const std::string& root :
       {test::SourcePath("tests/models"), std::string("/usr/share/assimp/models")}) {
    std::error_code error;
    for (fs::recursive_directory_iterator it(root, error), end; !error && it != end;
         it.increment(error)) {
      if (!it->is_regular_file(error)) continue;
      std::string ext = it->path().extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext == ".stl" || ext == ".ply" || ext == ".obj") paths.push_back(it->path().string());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

std::string FacesAndGlyphs(Mesh mesh) {
  const Scene scene = PrepareScene(std::move(mesh));
  const test::Frame frame = test::RenderFrame(scene, 0.3, 1.3, 60, 20, RenderOptions{});
  std::string faces;
  for (const uint32_t face : frame.cells.FaceNumbers()) faces += std::to_string(face) + ' ';
  return frame.Text() + faces;
}

TEST(OwnReadersParity, SameFramesAsAssimpOnEveryTestModel) {
  int compared = 0;
  for (const std::string& path : ModelsWithOwnReaders()) {
    const std::string bytes = test::ReadFile(path);
    std::string format = fs::path(path).extension().string().substr(1);
    for (char& c : format) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!ReadWithOwnReader(bytes, format, path, size_t{1} << 30)) continue;  // the importer's file
    // Both paths through the loader, so both get its checks after reading.
    Loaded<Mesh> own = LoadModelFile(path);
    LoadOptions reference;
    reference.importerOnly = true;
    Loaded<Mesh> imported = LoadModelFile(path, reference);
    if (!imported.Ok() || !own.Ok()) {
      EXPECT_EQ(own.Ok(), imported.Ok())
          << path << ": " << (own.Ok() ? imported.Error() : own.Error()).ToString();
      continue;
    }
    ++compared;
    EXPECT_EQ(own.Value().FaceCount(), imported.Value().FaceCount()) << path;
    EXPECT_EQ(own.Value().upAxisFile, imported.Value().upAxisFile) << path;
    EXPECT_EQ(FacesAndGlyphs(own.Value()), FacesAndGlyphs(imported.Value())) << path;
  }
  EXPECT_GE(compared, 1);
  std::printf("compared %d models\n", compared);
}

// A bigger, generated model (the kind `bench load` measures) in all three
// formats: both paths give the same mesh sizes and the same frames.
TEST(OwnReadersParity, GeneratedSphereInEveryFormat) {
  const fs::path folder =
      fs::temp_directory_path() / ("termshade-parity-" + std::to_string(getpid()));
  fs::create_directories(folder);
  const Mesh sphere = GenerateTriangleSphere(20'000);
  for (const char* format : {"obj", "stl", "ply"}) {
    const std::string path = (folder / (std::string("sphere.") + format)).string();
    std::ofstream(path, std::ios::binary) << ExportMesh(sphere, *ExportFormatFromPath(path));
    LoadOptions own, reference;
    reference.importerOnly = true;
    Loaded<Mesh> ours = LoadModelFile(path, own);
    Loaded<Mesh> imported = LoadModelFile(path, reference);
    ASSERT_TRUE(ours.Ok() && imported.Ok()) << path;
    EXPECT_EQ(ours.Value().FaceCount(), sphere.FaceCount()) << path;
    EXPECT_EQ(ours.Value().FaceCount(), imported.Value().FaceCount()) << path;
    EXPECT_EQ(ours.Value().verticesFile.size(), imported.Value().verticesFile.size()) << path;
    EXPECT_EQ(FacesAndGlyphs(ours.Value()), FacesAndGlyphs(imported.Value())) << path;
  }
  fs::remove_all(folder);
}

}  // namespace
}  // namespace termshade
