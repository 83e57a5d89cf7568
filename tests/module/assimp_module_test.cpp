// The Assimp import module (termshade-assimp.so) is mapped into the process
// only when a file needs Assimp: not for .dat and our own OBJ, STL and PLY
// readers; and once mapped, it gives the same frame as our reader does for
// the same model. Its own executable, and CTest runs each test in its own
// process (gtest_discover_tests), so /proc/self/maps shows what each test loaded.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/load/ModelExtensions.h"
#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

namespace fs = std::filesystem;

// Lines of /proc/self/maps naming a file that contains `part`.
std::string MappedFilesContaining(const std::string& part) {
  std::ifstream maps("/proc/self/maps");
  std::string found;
  for (std::string line; std::getline(maps, line);) {
    if (line.find(part) != std::string::npos) found += line + "\n";
  }
  return found;
}

// The mesh as an OFF file, a format only Assimp reads here.
std::string OffText(const Mesh& mesh) {
  char number[96];
  std::snprintf(number, sizeof number, "OFF\n%zu %zu 0\n", mesh.verticesFile.size(),
                mesh.FaceCount());
  std::string text = number;
  for (const Vec3& p : mesh.verticesFile) {
    std::snprintf(number, sizeof number, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    text += number;
  }
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    text += std::to_string(mesh.Face(f).size());
    for (const uint32_t corner : mesh.Face(f)) {
      text += ' ';
      text += std::to_string(corner);
    }
    text += "\n";
  }
  return text;
}

Mesh LoadOrFail(const std::string& path) {
  Loaded<Mesh> mesh = LoadModelFile(path);
  EXPECT_TRUE(mesh.Ok()) << (mesh.Ok() ? "" : mesh.Error().ToString());
  return mesh.Ok() ? std::move(mesh.Value()) : Mesh{};
}

TEST(AssimpModule, IsNotLoadedForDatObjStlOrPly) {
  ASSERT_EQ(MappedFilesContaining("assimp"), "") << "mapped before any load";
  const test::ScratchFolder folder("termshade-module");
  const Mesh sphere = GenerateTriangleSphere(500);
  for (const auto& [name, format] :
       {std::pair{"m.obj", ExportFormat::kObj}, std::pair{"m.stl", ExportFormat::kStl},
        std::pair{"m.ply", ExportFormat::kPly}, std::pair{"m.dat", ExportFormat::kDat}}) {
    const Mesh mesh = LoadOrFail(folder.Write(name, ExportMesh(sphere, format)));
    EXPECT_EQ(mesh.FaceCount(), sphere.FaceCount()) << name;
    EXPECT_FALSE(test::FrameText(mesh).empty());
  }
  EXPECT_TRUE(UsesImporter("x.obj"));
  EXPECT_EQ(MappedFilesContaining("assimp"), "");
}

TEST(AssimpModule, IsLoadedForOffAndGivesTheSameFrame) {
  const test::ScratchFolder folder("termshade-module");
  const Mesh sphere = GenerateTriangleSphere(500);
  const Mesh own = LoadOrFail(folder.Write("m.obj", ExportMesh(sphere, ExportFormat::kObj)));
  EXPECT_EQ(MappedFilesContaining("assimp"), "");
  const Mesh imported = LoadOrFail(folder.Write("m.off", OffText(sphere)));
  EXPECT_NE(MappedFilesContaining("termshade-assimp.so"), "");
  EXPECT_NE(MappedFilesContaining("libassimp"), "");
  ASSERT_EQ(imported.FaceCount(), own.FaceCount());
  EXPECT_EQ(test::FrameText(imported), test::FrameText(own));
}

// The shortcut that keeps the module closed for obj, stl and ply agrees with Assimp's list.
TEST(AssimpModule, ExtensionsWithoutTheModuleAreAssimpsOwn) {
  const std::vector<std::string> extensions = ModelFileExtensions();
  for (const char* format : {"obj", "stl", "ply", "off", "dat"}) {
    EXPECT_NE(std::find(extensions.begin(), extensions.end(), format), extensions.end()) << format;
  }
  EXPECT_NE(MappedFilesContaining("termshade-assimp.so"), "");
}

}  // namespace
}  // namespace termshade
