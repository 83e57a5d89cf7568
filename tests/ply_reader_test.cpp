#include "io/read/PlyReader.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

constexpr size_t kBudget = size_t{1} << 30;

std::array<float, 3> AsFloats(Vec3 p) {
  return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
}

Mesh ReadOk(const std::string& bytes) {
  auto read = ReadPly(bytes, "model.ply", kBudget);
  EXPECT_TRUE(read.has_value());
  if (!read) return {};
  EXPECT_TRUE(read->Ok()) << read->Error().ToString();
  return read->Ok() ? read->Value() : Mesh{};
}

std::string ErrorOf(const std::string& bytes) {
  auto read = ReadPly(bytes, "bad.ply", kBudget);
  if (!read) return "(left to the importer)";
  if (read->Ok()) return "(read)";
  return read->Error().ToString();
}

constexpr const char* kAsciiSquare =
    "ply\nformat ascii 1.0\ncomment a unit square and a line\nelement vertex 4\n"
    "property float x\nproperty float y\nproperty float z\nproperty float confidence\n"
    "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n4 0 1 2 3\n2 3 0\n";

TEST(PlyReader, KeepsABinarySpheresOwnIndexing) {
  const Mesh sphere = GenerateTriangleSphere(2000);
  const Mesh mesh = ReadOk(ExportMesh(sphere, ExportFormat::kPly));
  ASSERT_EQ(mesh.verticesFile.size(), sphere.verticesFile.size());
  EXPECT_EQ(mesh.faceCorners, sphere.faceCorners);
  EXPECT_EQ(mesh.faceStarts, sphere.faceStarts);
  for (size_t v = 0; v < mesh.verticesFile.size(); ++v) {
    ASSERT_EQ(AsFloats(mesh.verticesFile[v]), AsFloats(sphere.verticesFile[v])) << v;
  }
}

TEST(PlyReader, ReadsAsciiPolygonsSegmentsAndSkipsOtherProperties) {
  const Mesh mesh = ReadOk(kAsciiSquare);
  ASSERT_EQ(mesh.FaceCount(), 1U);
  EXPECT_EQ(mesh.Face(0).size(), 4U);
  ASSERT_EQ(mesh.segments.size(), 1U);
  EXPECT_EQ(mesh.segments[0], (std::array<uint32_t, 2>{3, 0}));
  EXPECT_EQ(mesh.verticesFile[2], (Vec3{1, 1, 0}));
}

TEST(PlyReader, ReadsBigEndian) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\n"
      "property list uchar uint vertex_indices\nend_header\n";
  auto appendBigEndian = [&bytes](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    for (size_t i = sizeof value; i-- > 0;) bytes += raw[i];
  };
  for (const double coordinate : {0.0, 0.0, 0.5, 2.0, 0.0, 0.5, 0.0, 3.0, 0.5}) {
    appendBigEndian(coordinate);
  }
  bytes += '\x03';
  for (const uint32_t index : {0U, 1U, 2U}) appendBigEndian(index);
  const Mesh mesh = ReadOk(bytes);
  ASSERT_EQ(mesh.FaceCount(), 1U);
  EXPECT_EQ(mesh.verticesFile[1], (Vec3{2, 0, 0.5}));
  EXPECT_EQ(mesh.verticesFile[2], (Vec3{0, 3, 0.5}));
}

// A binary PLY of both byte orders from the same values: vertices with an
// extra property, then faces (triangles, a quad, a 2-corner segment, and
// what the test adds), cut short by cut bytes.
std::string BinaryPly(bool little, const std::vector<std::vector<int32_t>>& faces, size_t cut) {
  std::string bytes = std::string("ply\nformat binary_") + (little ? "little" : "big") +
                      "_endian 1.0\nelement vertex 5\nproperty float x\nproperty double y\n"
                      "property uchar tag\nproperty float z\nelement face " +
                      std::to_string(faces.size()) +
                      "\nproperty list uchar int vertex_indices\nend_header\n";
  const auto append = [&bytes, little](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    for (size_t i = 0; i < sizeof value; ++i) bytes += raw[little ? i : sizeof value - 1 - i];
  };
  for (int v = 0; v < 5; ++v) {
    append(static_cast<float>(v) * 0.5F);
    append(static_cast<double>(v * v));
    append(static_cast<uint8_t>(v));
    append(-static_cast<float>(v));
  }
  for (const auto& face : faces) {
    append(static_cast<uint8_t>(face.size()));
    for (const int32_t index : face) append(index);
  }
  return bytes.substr(0, bytes.size() - cut);
}

std::string Describe(const std::string& bytes) {
  return test::ReadResultText(ReadPly(bytes, "m.ply", kBudget));
}

// Little-endian files take a fast path; big-endian ones the general one: the
// same mesh, or the same error, either way.
TEST(PlyReader, BothByteOrdersGiveTheSameMeshOrError) {
  const std::vector<std::vector<int32_t>> good = {{0, 1, 2}, {1, 2, 3, 4}, {0, 4}, {4, 3, 2}};
  auto withFace = [&good](std::vector<int32_t> face) {
    auto faces = good;
    faces.insert(faces.begin() + 2, std::move(face));
    return faces;
  };
  const std::vector<std::vector<std::vector<int32_t>>> cases = {
      good, withFace({0, 1, 5}), withFace({0, -1, 2}), withFace({2, 1}), withFace({3})};
  for (size_t c = 0; c < cases.size(); ++c) {
    for (const size_t cut : {0UL, 3UL, 14UL, 60UL}) {
      const std::string little = Describe(BinaryPly(true, cases[c], cut));
      EXPECT_EQ(little, Describe(BinaryPly(false, cases[c], cut)))
          << "case " << c << " cut " << cut;
      if (c == 0 && cut == 0) {
        EXPECT_EQ(little.find("m.ply"), std::string::npos) << little;
      }
    }
  }
  EXPECT_EQ(Describe(BinaryPly(true, withFace({0, 1, 5}), 0)),
            "m.ply: face 2 names vertex 5 (the file has 5 vertices) (at byte 128)");
}

TEST(PlyReader, LocatesHeaderProblems) {
  EXPECT_EQ(ErrorOf("plx\n"), "bad.ply:1:1: expected 'ply' on the first line");
  EXPECT_EQ(ErrorOf("ply\nformat ascii 1.0\nelement vertex 3\nproperty wide x\n"),
            "bad.ply:4:1: unknown property type");
  EXPECT_NE(ErrorOf("ply\nformat ascii 1.0\nelement vertex 3\n").find("end_header"),
            std::string::npos);
}

TEST(PlyReader, ChecksCountsAgainstTheFileBeforeAllocating) {
  const std::string claim =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(ErrorOf(claim + std::string(100, '\0')).find("more than the file can hold"),
            std::string::npos);
}

TEST(PlyReader, RefusesAModelOverTheMemoryBudget) {
  const std::string bytes = ExportMesh(GenerateTriangleSphere(2000), ExportFormat::kPly);
  auto read = ReadPly(bytes, "big.ply", 1000);
  ASSERT_TRUE(read && !read->Ok());
  EXPECT_NE(read->Error().message.find("more than the memory budget"), std::string::npos);
}

TEST(PlyReader, RefusesIndicesOutOfRangeOrNegative) {
  std::string outOfRange = kAsciiSquare;
  outOfRange.replace(outOfRange.find("4 0 1 2 3"), 9, "4 0 1 2 9");
  EXPECT_NE(ErrorOf(outOfRange).find("names vertex 9 (the file has 4 vertices)"),
            std::string::npos);
  std::string negative = kAsciiSquare;
  negative.replace(negative.find("4 0 1 2 3"), 9, "4 0 1 -2 3");
  EXPECT_NE(ErrorOf(negative).find("names vertex -2"), std::string::npos);
  EXPECT_EQ(ErrorOf(outOfRange).rfind("bad.ply:16:", 0), 0U) << ErrorOf(outOfRange);
}

TEST(PlyReader, ATruncatedFileIsAnError) {
  const std::string bytes = ExportMesh(GenerateTriangleSphere(200), ExportFormat::kPly);
  EXPECT_NE(ErrorOf(bytes.substr(0, bytes.size() - 7)).find("bad.ply"), std::string::npos);
  EXPECT_NE(ErrorOf(bytes.substr(0, bytes.size() - 7)), "(read)");
}

TEST(PlyReader, LeavesColouredFilesToTheImporter) {
  std::string coloured = kAsciiSquare;
  coloured.replace(coloured.find("property float confidence"), 25, "property uchar red");
  EXPECT_EQ(ErrorOf(coloured), "(left to the importer)");
}

// The reference: Assimp's reading of the same file draws the same frame.
TEST(PlyReader, DrawsWhatTheImporterDraws) {
  const std::string path = ::testing::TempDir() + "ply_reader_parity.ply";
  const std::string bytes = ExportMesh(GenerateScene("sphere_cone").value(), ExportFormat::kPly);
  std::ofstream(path, std::ios::binary) << bytes;
  LoadOptions reference;
  reference.importerOnly = true;
  Loaded<Mesh> imported = LoadModelFile(path, reference);
  ASSERT_TRUE(imported.Ok()) << imported.Error().ToString();
  EXPECT_EQ(test::FrameText(ReadOk(bytes)), test::FrameText(imported.Value()));
  std::remove(path.c_str());
}

}  // namespace
}  // namespace termshade
