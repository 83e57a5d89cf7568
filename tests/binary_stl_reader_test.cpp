#include "io/read/BinaryStlReader.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"

namespace termshade {
namespace {

// Compared as floats: GCC 12 at -O3 folds a vectorised double -> float -> double round trip.
std::array<float, 3> AsFloats(Vec3 p) {
  return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
}

TEST(BinaryStlReader, WeldsASphereBackToItsSharedVertices) {
  const Mesh sphere = GenerateTriangleSphere(2000);
  const std::string bytes = ExportMesh(sphere, ExportFormat::kStl);
  ASSERT_TRUE(IsBinaryStlLayout(bytes));
  Loaded<Mesh> read = ReadBinaryStl(bytes, "sphere.stl");
  ASSERT_TRUE(read.Ok()) << read.Error().ToString();
  const Mesh& mesh = read.Value();
  EXPECT_EQ(mesh.verticesFile.size(), sphere.verticesFile.size());
  ASSERT_EQ(mesh.FaceCount(), sphere.FaceCount());
  for (size_t f = 0; f < mesh.FaceCount(); ++f) {
    ASSERT_EQ(mesh.Face(f).size(), 3U);
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(AsFloats(mesh.verticesFile[mesh.Face(f)[i]]),
                AsFloats(sphere.verticesFile[sphere.Face(f)[i]]))
          << "face " << f << " corner " << i;
    }
  }
}

TEST(BinaryStlReader, NumbersVerticesInFirstOccurrenceOrder) {
  const Mesh sphere = GenerateTriangleSphere(200);
  Loaded<Mesh> read = ReadBinaryStl(ExportMesh(sphere, ExportFormat::kStl), "sphere.stl");
  ASSERT_TRUE(read.Ok());
  uint32_t nextNew = 0;
  for (const uint32_t corner : read.Value().faceCorners) {
    ASSERT_LE(corner, nextNew);
    if (corner == nextNew) ++nextNew;
  }
}

// Welded in any number of runs (threads), the same mesh as in one, bit for
// bit, and the same as meshoptimizer's first-occurrence remap; a run may
// hold a single triangle, or positions only other runs have.
TEST(BinaryStlReader, AnyPartCountGivesTheSameMesh) {
  const Mesh sphere = GenerateTriangleSphere(3000);
  const std::string bytes = ExportMesh(sphere, ExportFormat::kStl);
  Loaded<Mesh> one = ReadBinaryStlInParts(bytes, "sphere.stl", 1);
  ASSERT_TRUE(one.Ok());
  // meshopt_generateVertexRemap's numbering: each position numbered at its first corner.
  std::vector<Vec3> firstSeen;
  for (const uint32_t corner : one.Value().faceCorners) {
    if (corner == firstSeen.size()) firstSeen.push_back(one.Value().verticesFile[corner]);
    ASSERT_LT(corner, firstSeen.size());
  }
  EXPECT_EQ(firstSeen.size(), one.Value().verticesFile.size());
  for (const size_t parts : {2UL, 3UL, 7UL, 5000UL}) {
    Loaded<Mesh> split = ReadBinaryStlInParts(bytes, "sphere.stl", parts);
    ASSERT_TRUE(split.Ok());
    EXPECT_EQ(split.Value().faceCorners, one.Value().faceCorners) << parts;
    ASSERT_EQ(split.Value().verticesFile.size(), one.Value().verticesFile.size()) << parts;
    EXPECT_EQ(std::memcmp(split.Value().verticesFile.data(), one.Value().verticesFile.data(),
                          one.Value().verticesFile.size() * sizeof(Vec3)),
              0)
        << parts;
  }
}

// Given the file's own string, the reader hands its pages back as it reads
// (files past 4 MiB) and frees it: the same mesh as from a view, bit for bit.
TEST(BinaryStlReader, OwnedFileGivesTheSameMeshAndIsFreed) {
  const Mesh sphere = GenerateTriangleSphere(300000);
  const std::string copy = ExportMesh(sphere, ExportFormat::kStl);
  ASSERT_GT(copy.size(), size_t{8} << 20);
  FileBytes owned(copy);
  Loaded<Mesh> fromView = ReadBinaryStl(copy, "sphere.stl");
  Loaded<Mesh> fromOwned = ReadBinaryStl(owned.View(), "sphere.stl", &owned);
  ASSERT_TRUE(fromView.Ok() && fromOwned.Ok());
  EXPECT_EQ(owned.Size(), 0U);
  const Mesh &a = fromView.Value(), &b = fromOwned.Value();
  EXPECT_EQ(a.faceCorners, b.faceCorners);
  EXPECT_EQ(a.faceStarts, b.faceStarts);
  ASSERT_EQ(a.verticesFile.size(), b.verticesFile.size());
  EXPECT_EQ(std::memcmp(a.verticesFile.data(), b.verticesFile.data(),
                        a.verticesFile.size() * sizeof(Vec3)),
            0);
}

TEST(BinaryStlReader, RefusesAnythingButTheExactLayout) {
  std::string bytes = ExportMesh(GenerateTriangleSphere(200), ExportFormat::kStl);
  EXPECT_FALSE(IsBinaryStlLayout(bytes.substr(0, bytes.size() - 1)));
  EXPECT_FALSE(IsBinaryStlLayout(bytes + "x"));
  EXPECT_FALSE(IsBinaryStlLayout("solid x\nendsolid x\n"));
  const uint32_t huge = 0xFFFFFFFFU;  // a count the file cannot hold
  std::memcpy(bytes.data() + 80, &huge, sizeof huge);
  EXPECT_FALSE(IsBinaryStlLayout(bytes));
  Loaded<Mesh> read = ReadBinaryStl(bytes, "lying.stl");
  ASSERT_FALSE(read.Ok());
  EXPECT_NE(read.Error().ToString().find("lying.stl"), std::string::npos);
}

// A binary STL cut short or padded is no STL the importer knows either: the
// message says what the size should be. ASCII STLs and exact layouts pass.
TEST(BinaryStlReader, SaysHowAMisSizedFileMissesItsLayout) {
  const std::string bytes = ExportMesh(GenerateTriangleSphere(200), ExportFormat::kStl);
  uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof count);
  const std::string expected = std::to_string(84 + 50 * uint64_t{count});
  const auto cut = MisSizedBinaryStl(bytes.substr(0, bytes.size() - 75), "cut.stl");
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->file, "cut.stl");
  EXPECT_EQ(cut->message, "binary STL header counts " + std::to_string(count) +
                              " triangles, so 84 + 50 x " + std::to_string(count) + " = " +
                              expected + " bytes, but the file has " +
                              std::to_string(bytes.size() - 75) + " (cut short?)");
  const auto padded = MisSizedBinaryStl(bytes + "xy", "padded.stl");
  ASSERT_TRUE(padded.has_value());
  EXPECT_NE(padded->message.find("(bytes after the last triangle)"), std::string::npos);
  const auto tiny = MisSizedBinaryStl(std::string(10, 'x'), "tiny.stl");
  ASSERT_TRUE(tiny.has_value());
  EXPECT_NE(tiny->message.find("too short for a binary one: 10 bytes"), std::string::npos);
  EXPECT_FALSE(MisSizedBinaryStl(bytes, "exact.stl").has_value());
  EXPECT_FALSE(MisSizedBinaryStl("  solid x\nendsolid x\n", "ascii.stl").has_value());
}

TEST(BinaryStlReader, AnEmptyFileIsAnError) {
  const std::string bytes(84, '\0');
  ASSERT_TRUE(IsBinaryStlLayout(bytes));
  EXPECT_FALSE(ReadBinaryStl(bytes, "empty.stl").Ok());
}

TEST(BinaryStlReader, SeesMaterialiseColourHeaders) {
  std::string bytes = ExportMesh(GenerateTriangleSphere(200), ExportFormat::kStl);
  EXPECT_FALSE(BinaryStlHasColours(bytes));
  bytes.replace(0, 10, "COLOR=\xff\x00\x00\xff");
  EXPECT_TRUE(BinaryStlHasColours(bytes));
}

}  // namespace
}  // namespace termshade
