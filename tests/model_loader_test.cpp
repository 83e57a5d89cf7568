// The model loader's hostile-input rules and what it takes from files:
// messages for each class of bad file, references kept inside the model's
// folder, content sniffing, budget, cancel and progress, colours and up axis.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>

#include "io/load/ModelLoader.h"
#include "io/read/LoadBudget.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

using test::SourcePath;

std::string ErrorOf(const std::string& relative, const LoadOptions& options = {}) {
  Loaded<Mesh> mesh = LoadModelFile(SourcePath(relative), options);
  EXPECT_FALSE(mesh.Ok()) << relative << " loaded";
  return mesh.Ok() ? "" : mesh.Error().ToString();
}

Mesh Good(const std::string& relative) {
  Loaded<Mesh> mesh = LoadModelFile(SourcePath(relative));
  EXPECT_TRUE(mesh.Ok()) << (mesh.Ok() ? "" : mesh.Error().ToString());
  return mesh.Ok() ? std::move(mesh.Value()) : Mesh{};
}

struct BadModel {
  const char* name;
  const char* message;  // what the message must contain, after the file name
};

void PrintTo(const BadModel& bad, std::ostream* out) {
  *out << bad.name;
}

class HostileModels : public testing::TestWithParam<BadModel> {};

// Assimp, the reference path, refuses bad PLY indices too (its data
// structure validation) instead of crashing in a later step.
TEST(HostileModels, AssimpRefusesBadPlyIndices) {
  LoadOptions reference;
  reference.importerOnly = true;
  for (const char* name : {"ply_face_index_out_of_range.ply", "ply_face_index_negative.ply"}) {
    const std::string error = ErrorOf(std::string("tests/models/bad/") + name, reference);
    EXPECT_NE(error.find("is out of range"), std::string::npos) << error;
  }
}

// Assimp's PLY importer takes content starting "ply" under any name and loops
// forever on a header without end_header (a libFuzzer timeout): such content
// gets our header's error on every path, the reference path included.
TEST(HostileModels, PlyHeaderThatNeverEndsIsRefusedUnderAnyName) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n";
  for (const bool importerOnly : {false, true}) {
    LoadOptions options;
    options.importerOnly = importerOnly;
    for (const char* name : {"m.ply", "m.glb", "m.gltf", "m.dae", "m.3ds", "m.off", "m"}) {
      const Loaded<Mesh> mesh = LoadModelBytes(header, name, options);
      ASSERT_FALSE(mesh.Ok()) << name;
      EXPECT_EQ(mesh.Error().line, 4) << name;
      EXPECT_NE(mesh.Error().message.find("expected 'end_header'"), std::string::npos)
          << name << ": " << mesh.Error().ToString();
    }
  }
  // Counts are checked from the line that ends the header, not from the
  // first "end_header" in it, and from where Assimp starts reading.
  const std::string counts =
      "ply\nformat ascii end_header1.0\nelement vertex 2000000000\nproperty float x\n"
      "end_header\n0\n";
  for (const std::string& bytes : {counts, "\n" + counts}) {
    const Loaded<Mesh> mesh = LoadModelBytes(bytes, "m.glb");
    ASSERT_FALSE(mesh.Ok());
    EXPECT_NE(mesh.Error().message.find("the header promises 2000000000 vertex"), std::string::npos)
        << mesh.Error().ToString();
  }
  // A NUL in the header would split a line for Assimp alone.
  const Loaded<Mesh> nul = LoadModelBytes(
      std::string("ply\nformat ascii 1.0\ncomment x\0element vertex 9\nend_header\n", 59), "m");
  ASSERT_FALSE(nul.Ok());
  EXPECT_EQ(nul.Error().line, 3) << nul.Error().ToString();
  EXPECT_NE(nul.Error().message.find("holds a NUL"), std::string::npos) << nul.Error().ToString();
  // Assimp's own magic check is case-blind and skips a leading line end.
  EXPECT_FALSE(LoadModelBytes("PlY\nformat ascii 1.0\n", "m.glb").Ok());
  const Loaded<Mesh> afterLineEnd = LoadModelBytes("\r\nply\nformat ascii 1.0\n", "m.glb");
  ASSERT_FALSE(afterLineEnd.Ok());
  EXPECT_EQ(afterLineEnd.Error().line, 3) << afterLineEnd.Error().ToString();
}

// Assimp's OpenDDL parser reads past its buffer on an unclosed structure (a
// libFuzzer heap-buffer-overflow): content its OpenGEX importer would sniff
// must be closed; closed content, and a glTF that mentions a token, pass.
TEST(HostileModels, OpenGexContentMustBeClosed) {
  for (const char* bytes : {"a{indexarray", "indexarray ", "nmetric ", "Metric {} x",
                            "Metric {float {1}", "Metric (a = \"}\") {", "Metric {} /* x"}) {
    for (const char* name : {"m", "m.ogex", "m.glb", "m.gltf"}) {
      const Loaded<Mesh> mesh = LoadModelBytes(bytes, name);
      ASSERT_FALSE(mesh.Ok()) << bytes << " as " << name;
      EXPECT_NE(mesh.Error().message.find("read as OpenGEX"), std::string::npos)
          << bytes << " as " << name << ": " << mesh.Error().ToString();
    }
  }
  const std::string closed = "Metric (key = \"up\") {string {\"z}\"}} // end {\n";
  const Loaded<Mesh> mesh = LoadModelBytes(closed, "m.ogex");
  EXPECT_TRUE(mesh.Ok() || mesh.Error().message.find("read as OpenGEX") == std::string::npos)
      << mesh.Error().ToString();
  const Loaded<Mesh> gltf = LoadModelBytes("{\"asset\": {\"generator\": \"metric {\"}", "m.gltf");
  EXPECT_TRUE(gltf.Ok() || gltf.Error().message.find("read as OpenGEX") == std::string::npos)
      << gltf.Error().ToString();
}

TEST_P(HostileModels, AreRefusedWithAMessageNamingTheFile) {
  const std::string path = SourcePath(std::string("tests/models/bad/") + GetParam().name);
  const std::string error = ErrorOf(std::string("tests/models/bad/") + GetParam().name);
  EXPECT_EQ(error.rfind(path + ":", 0), 0U) << error;  // then a line number or a blank
  EXPECT_NE(error.find(GetParam().message), std::string::npos) << error;
  for (const char c : error) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << error;
}

INSTANTIATE_TEST_SUITE_P(
    BadFiles, HostileModels,
    testing::Values(
        BadModel{"raw_null_child_node.raw", "A node of the scene-graph is nullptr"},
        BadModel{"raw_null_child_node_with_texture.raw", "nullptr"},
        BadModel{"ply_face_index_out_of_range.ply", ":13: face 0 names vertex 7 (the file has 3"},
        BadModel{"ply_face_index_negative.ply", ":13: face 0 names vertex -1"},
        BadModel{"off_counts_with_trailing_junk.off",
                 "the header promises 900000000 vertices and 90000000 faces"},
        BadModel{"ply_header_claims_2e9_vertices.ply",
                 "the header promises 2000000000 vertex, 1 face, more than the 27 bytes"},
        BadModel{"ply_header_claims_2to64_minus_1_vertices.ply",
                 "the header promises 18446744073709551615 vertex, more than"},
        BadModel{"stl_binary_cut_short.stl",
                 "binary STL header counts 1000 triangles, so 84 + 50 x 1000 = 50084 bytes, but "
                 "the file has 259 (cut short?)"},
        BadModel{"ply_header_never_ends_named_glb.glb",
                 ":6:1: content read as PLY: expected 'end_header' to close the PLY header"},
        BadModel{"ply_end_header_word_inside_a_line_named_glb.glb",
                 "content read as PLY: the header promises 2000000000 vertex"},
        BadModel{"opengex_structure_never_closed",
                 "read as OpenGEX: a structure is never closed (unbalanced brackets)"},
        BadModel{"opengex_geometry_node_never_closed.ogex",
                 "read as OpenGEX: a structure is never closed"},
        BadModel{"q3d_vertex_count_beyond_file_size.q3o",
                 "read as Quick3D: a count of 201326592 vertices is more than the bytes after it "
                 "can hold"},
        BadModel{"q3d_material_count_2to30_unnamed",
                 "read as Quick3D: a count of 1073741824 materials"},
        BadModel{"ply_vertex_list_length_negative.ply",
                 ":8: vertex 0 has an impossible list length"},
        BadModel{"ply_header_never_ends_after_a_property.ply",
                 ":4:1: expected 'end_header' to close the PLY header"},
        BadModel{"obj_every_face_has_no_area.obj",
                 ": all 3 of its faces have no area (corners on a line or at a point)"},
        BadModel{"off_counts_beyond_file_size.off", "the header promises 353535235358 vertices"},
        BadModel{"off_header_counts_huge.off", "the header promises 900000000 vertices"},
        BadModel{"off_header_counts_huge_named_glb.glb",
                 "content read as OFF: the header promises 900000000 vertices and 900000000 "
                 "faces"},
        BadModel{"obj_mtllib_absolute_path.obj", "refused to read '/etc/passwd': an absolute path"},
        BadModel{"obj_mtllib_leaves_folder.obj",
                 "refused to read '../../../../../../etc/passwd': a path that leaves the model's"},
        BadModel{"gltf_buffer_uri_absolute_path.gltf", "refused to read '/etc/passwd'"},
        BadModel{"gltf_buffer_uri_leaves_folder.gltf",
                 "refused to read '../../../../../../../etc/passwd'"},
        BadModel{"gltf_buffer_uri_file_scheme.gltf", "refused to read 'file:///etc/passwd': a URI"},
        BadModel{"gltf_escape_bytes_in_uri.gltf", "\\x1B]0;pwned\\x07"},
        BadModel{"empty_file.obj", "the file is empty"},
        BadModel{"png_image_without_extension", "not a model file (looks like PNG image)"},
        BadModel{"cube_edge_3.5e38_beyond_float.dat", "is outside what can be drawn"},
        BadModel{"cube_edge_1e-100_below_float.dat", "is outside what can be drawn"}),
    [](const testing::TestParamInfo<BadModel>& info) {
      std::string name = info.param.name;
      for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

TEST(ModelLoader, AFolderIsNotAModel) {
  EXPECT_EQ(ErrorOf("tests/models"),
            SourcePath("tests/models") + ": not a regular file but a folder");
}

TEST(ModelLoader, AFifoIsRefusedWithoutBlocking) {
  const std::string fifo = testing::TempDir() + "/termshade_fifo.obj";
  unlink(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  Loaded<Mesh> mesh = LoadModelFile(fifo);
  unlink(fifo.c_str());
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().message, "not a regular file but a FIFO (named pipe)");
}

TEST(ModelLoader, ADeviceIsRefused) {
  Loaded<Mesh> mesh = LoadModelFile("/dev/zero");
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().message, "not a regular file but a character device");
}

TEST(ModelLoader, GltfWithExternalBufferLoadsFromAnyWorkingDirectory) {
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path("/");
  const Mesh mesh = Good("tests/models/good/triangle_external_buffer.gltf");
  std::filesystem::current_path(before);
  EXPECT_EQ(mesh.FaceCount(), 1U);
}

TEST(ModelLoader, FaceColoursComeFromTheMaterials) {
  const Mesh mesh = Good("tests/models/good/two_colours_from_mtl.obj");
  ASSERT_EQ(mesh.faceColors.size(), 2U);
  EXPECT_EQ(mesh.faceColors[0], (Rgb{1, 0, 0}));
  EXPECT_EQ(mesh.faceColors[1], (Rgb{0, 0, 1}));
}

TEST(ModelLoader, FaceColoursComeFromGltfBaseColor) {
  const Mesh mesh = Good("tests/models/good/triangle_external_buffer.gltf");
  ASSERT_EQ(mesh.faceColors.size(), 1U);
  EXPECT_EQ(mesh.faceColors[0], (Rgb{0.2f, 0.4f, 0.6f}));
}

TEST(ModelLoader, VertexColoursAreAveragedOverTheFace) {
  const Mesh mesh = Good("tests/models/good/vertex_colours.obj");
  ASSERT_EQ(mesh.faceColors.size(), 1U);
  EXPECT_FLOAT_EQ(mesh.faceColors[0].r, 1.0f / 3);
  EXPECT_FLOAT_EQ(mesh.faceColors[0].g, 1.0f / 3);
  EXPECT_FLOAT_EQ(mesh.faceColors[0].b, 1.0f / 3);
}

TEST(ModelLoader, NoColourInTheFileLeavesFaceColoursEmpty) {
  EXPECT_TRUE(Good("tests/models/good/quad_and_triangle.obj").faceColors.empty());
  EXPECT_TRUE(Good("data/cube.dat").faceColors.empty());
  for (const char* name : {"plain.ply", "plain.off"}) {
    const std::string text =
        std::string(name) == "plain.ply"
            ? "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
              "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
            : "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    Loaded<Mesh> mesh = LoadModelBytes(text, name);
    ASSERT_TRUE(mesh.Ok()) << mesh.Error().ToString();
    EXPECT_TRUE(mesh.Value().faceColors.empty()) << name;
  }
}

TEST(ModelLoader, UpAxisFollowsTheFormat) {
  EXPECT_EQ(Good("data/cube.dat").upAxisFile, UpAxis::kPlusZ);
  EXPECT_EQ(Good("tests/models/good/quad_and_triangle.obj").upAxisFile, UpAxis::kPlusY);
  EXPECT_EQ(Good("tests/models/good/triangle_external_buffer.gltf").upAxisFile, UpAxis::kPlusY);
  Loaded<Mesh> stl = LoadModelBytes(
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid t\n",
      "t.stl");
  ASSERT_TRUE(stl.Ok()) << stl.Error().ToString();
  EXPECT_EQ(stl.Value().upAxisFile, UpAxis::kPlusZ);
}

TEST(ModelLoader, ContentWithoutExtensionIsSniffed) {
  EXPECT_TRUE(LoadModelBytes("1 0 0 0\n2 1 0 0\n3 0 1 0\nFaces:\n1 2 3 .\n", "model").Ok());
  EXPECT_TRUE(LoadModelBytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "model").Ok());
  const Loaded<Mesh> png = LoadModelBytes("\x89PNG\r\n\x1a\nrest", "picture");
  ASSERT_FALSE(png.Ok());
  EXPECT_EQ(png.Error().message, "not a model file (looks like PNG image)");
}

TEST(ModelLoader, ReferencesFromStandardInputAreRefused) {
  Loaded<Mesh> mesh = LoadModelBytes("mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "-");
  ASSERT_FALSE(mesh.Ok());
  EXPECT_NE(mesh.Error().message.find("refused to read 'x.mtl'"), std::string::npos);
}

TEST(ModelLoader, AModelOverTheBudgetSaysHowMuchItNeeds) {
  LoadOptions options;
  options.memoryBudgetBytes = 1 << 20;
  const std::string error = ErrorOf("data/sphere_cone.dat", options);
  EXPECT_NE(error.find("loading it needs about"), std::string::npos) << error;
  EXPECT_NE(error.find("more than the memory budget of 1.0 MiB"), std::string::npos) << error;
}

TEST(ModelLoader, CancelStopsTheLoad) {
  std::atomic<bool> cancel{true};
  LoadOptions options;
  options.cancel = &cancel;
  EXPECT_NE(ErrorOf("data/sphere_cone.dat", options).find("loading cancelled"), std::string::npos);
  EXPECT_NE(ErrorOf("tests/models/good/quad_and_triangle.obj", options).find("loading cancelled"),
            std::string::npos);
}

TEST(ModelLoader, ProgressIsReportedForOurReaderAndAssimp) {
  for (const char* model : {"data/sphere_cone.dat", "tests/models/good/two_colours_from_mtl.obj"}) {
    double last = -1.0;
    int calls = 0;
    LoadOptions options;
    options.progress = [&](double share) {
      EXPECT_GE(share, 0.0);
      EXPECT_LE(share, 1.0);
      last = share;
      ++calls;
    };
    EXPECT_TRUE(LoadModelFile(SourcePath(model), options).Ok());
    EXPECT_GT(calls, 0) << model;
    EXPECT_GE(last, 0.0) << model;
  }
}

TEST(LoadBudget, ParsesByteCounts) {
  EXPECT_EQ(ParseByteCount("4G"), size_t{4} << 30);
  EXPECT_EQ(ParseByteCount("512M"), size_t{512} << 20);
  EXPECT_EQ(ParseByteCount("1.5GiB"), size_t{3} << 29);
  EXPECT_EQ(ParseByteCount("1000"), size_t{1000});
  EXPECT_FALSE(ParseByteCount("lots"));
  EXPECT_FALSE(ParseByteCount("-1G"));
  EXPECT_FALSE(ParseByteCount("4Q"));
}

}  // namespace
}  // namespace termshade
