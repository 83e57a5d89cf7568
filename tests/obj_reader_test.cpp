#include "io/read/ObjReader.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>

#include "geometry/DropUnusedVertices.h"
#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

constexpr size_t kBudget = size_t{1} << 30;

Mesh ReadOk(const std::string& text) {
  auto read = ReadObj(text, "model.obj", kBudget);
  EXPECT_TRUE(read.has_value());
  if (!read) return {};
  EXPECT_TRUE(read->Ok()) << read->Error().ToString();
  return read->Ok() ? read->Value() : Mesh{};
}

std::string ErrorOf(const std::string& text) {
  auto read = ReadObj(text, "bad.obj", kBudget);
  if (!read) return "(left to the importer)";
  if (read->Ok()) return "(read)";
  return read->Error().ToString();
}

TEST(ObjReader, ReadsEveryCornerFormAndNegativeIndices) {
  const Mesh mesh = ReadOk(
      "# a square, a triangle and a line\r\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
      "g square\ns 1\nf 1/1/1 2/1/1 3//1 4\n"
      "v +2 0 -1.5e0\n"
      "f -1 -4 -3 # relative\n"
      "l 1 2 3\n");
  ASSERT_EQ(mesh.FaceCount(), 2U);
  EXPECT_EQ(mesh.faceCorners, (std::vector<uint32_t>{0, 1, 2, 3, 4, 1, 2}));
  EXPECT_EQ(mesh.verticesFile[4], (Vec3{2, 0, -1.5}));
  ASSERT_EQ(mesh.segments.size(), 2U);
  EXPECT_EQ(mesh.segments[1], (std::array<uint32_t, 2>{1, 2}));
}

TEST(ObjReader, LocatesBadNumbersAndUndefinedVertices) {
  EXPECT_EQ(ErrorOf("v 0 0 0\nv 1 x 0\n"), "bad.obj:2:5: expected a number");
  EXPECT_EQ(ErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"),
            "bad.obj:4:7: vertex 7 is not defined (3 so far)");
  EXPECT_EQ(ErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n"),
            "bad.obj:4:7: vertex 0 is not defined (3 so far)");
  EXPECT_EQ(ErrorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"),
            "bad.obj:4:9: vertex -4 is not defined (3 so far)");
  EXPECT_EQ(ErrorOf("v 0 0 0\nf 1 1 1 q\n"), "bad.obj:2:9: expected a vertex number");
  EXPECT_EQ(ErrorOf(""), "bad.obj: the file holds no polygons ('f' lines)");
}

TEST(ObjReader, LeavesMaterialsAndColoursToTheImporter) {
  EXPECT_EQ(ErrorOf("mtllib a.mtl\nv 0 0 0\n"), "(left to the importer)");
  EXPECT_EQ(ErrorOf("v 0 0 0\nusemtl red\n"), "(left to the importer)");
  EXPECT_EQ(ErrorOf("v 0 0 0 1 0 0\n"), "(left to the importer)");
  EXPECT_EQ(ErrorOf("v 0 0 \\\n0\n"), "(left to the importer)");
}

TEST(ObjReader, RefusesAModelOverTheMemoryBudget) {
  const std::string text = ExportMesh(GenerateTriangleSphere(2000), ExportFormat::kObj);
  auto read = ReadObj(text, "big.obj", 1000);
  ASSERT_TRUE(read && !read->Ok());
  EXPECT_NE(read->Error().message.find("more than the memory budget"), std::string::npos);
}

TEST(ObjReader, DropsVerticesNoFaceUses) {
  const Mesh mesh = ReadOk("v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n");
  ASSERT_EQ(mesh.verticesFile.size(), 3U);
  EXPECT_EQ(mesh.faceCorners, (std::vector<uint32_t>{0, 1, 2}));
}

// The reference: Assimp's reading of the same file draws the same frame.
TEST(ObjReader, DrawsWhatTheImporterDraws) {
  for (const char* scene : {"sphere_cone", "beams", "steps"}) {
    const std::string path = ::testing::TempDir() + "obj_reader_parity.obj";
    const std::string text = ExportMesh(GenerateScene(scene).value(), ExportFormat::kObj);
    std::ofstream(path, std::ios::binary) << text;
    LoadOptions reference;
    reference.importerOnly = true;
    Loaded<Mesh> imported = LoadModelFile(path, reference);
    ASSERT_TRUE(imported.Ok()) << imported.Error().ToString();
    EXPECT_EQ(test::FrameText(ReadOk(text)), test::FrameText(imported.Value())) << scene;
    std::remove(path.c_str());
  }
}

// Every chunk count gives the same mesh, or the same first error in file order.
TEST(ObjReader, ChunksGiveTheSameMeshAndErrorAsOneChunk) {
  const std::string good =
      "# cube-ish\r\nv 0 0 0\nv 1 0 0\r\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
      "f 1 2 3 4 # quad\nf -1 -2 -3\nl 1 2 3\nf 1 2\nf 1\nv 0 0 1\n\n"
      "v 1 0 1\nf 5/1 6/1/1 1//1\nf -2 -1 2\nl 5 6\nv 7 7 7\nf 1 3 6";
  const std::string bad[] = {
      good + "\nf 1 2 99\nv 1 x 0\n",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\nv 1 2 3\nf 1 2 3\nf 1 2 -9\n",
      "v 0 0 0\nv 1 0 0\nv 0 1 q\n" + good,
  };
  for (const std::string& text : {good, bad[0], bad[1], bad[2]}) {
    const std::string one = test::ReadResultText(ReadObjInChunks(text, "m.obj", kBudget, 1));
    for (size_t chunks = 2; chunks <= 24; ++chunks) {
      EXPECT_EQ(test::ReadResultText(ReadObjInChunks(text, "m.obj", kBudget, chunks)), one)
          << chunks << " chunks";
    }
  }
  EXPECT_EQ(test::ReadResultText(ReadObjInChunks(bad[1], "m.obj", kBudget, 5)),
            "m.obj:8:7: vertex -9 is not defined (4 so far)");
}

// Given its own string, the reader frees it once the geometry is parsed: the
// same mesh, or the same error, as from a view, for any chunk count.
TEST(ObjReader, OwnedTextGivesTheSameResultAndIsFreedWhenRead) {
  const std::string sphere = ExportMesh(GenerateTriangleSphere(20000), ExportFormat::kObj);
  const std::string bad = sphere + "f 1 2 x\n";
  for (const std::string* text : {&sphere, &bad}) {
    const std::string one = test::ReadResultText(ReadObjInChunks(*text, "m.obj", kBudget, 1));
    for (const size_t chunks : {1UL, 2UL, 7UL}) {
      FileBytes owned(*text);
      EXPECT_EQ(
          test::ReadResultText(ReadObjInChunks(owned.View(), "m.obj", kBudget, chunks, &owned)),
          one);
      EXPECT_EQ(owned.Size() == 0, text == &sphere) << chunks << " chunks";
    }
  }
}

TEST(DropUnusedVertices, KeepsWhatSegmentsUseAndTheOrder) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {5, 5, 5}, {1, 0, 0}, {0, 1, 0}, {6, 6, 6}, {2, 2, 2}};
  mesh.AddFace(std::array<uint32_t, 3>{0, 2, 3});
  mesh.segments.push_back({5, 0});
  DropUnusedVertices(mesh);
  EXPECT_EQ(mesh.verticesFile.size(), 4U);
  EXPECT_EQ(mesh.faceCorners, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(mesh.segments[0], (std::array<uint32_t, 2>{3, 0}));
}

}  // namespace
}  // namespace termshade
