// The .dat reader (SPEC 6): what it accepts, and every error with its exact message.
#include <gtest/gtest.h>

#include "io/load/ModelLoader.h"
#include "io/read/DatReader.h"
#include "io/write/DatWriter.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

using test::SourcePath;

Mesh LoadGood(const std::string& name) {
  Loaded<Mesh> mesh = LoadModelFile(SourcePath("tests/models/good/" + name));
  EXPECT_TRUE(mesh.Ok()) << (mesh.Ok() ? "" : mesh.Error().ToString());
  return mesh.Ok() ? std::move(mesh.Value()) : Mesh{};
}

TEST(DatReader, ReadsTheSpecWedge) {
  const Mesh mesh = LoadGood("../../../data/wedge.dat");
  ASSERT_EQ(mesh.verticesFile.size(), 6U);
  ASSERT_EQ(mesh.FaceCount(), 5U);
  EXPECT_EQ(mesh.Face(2).size(), 4U);
  EXPECT_EQ(mesh.verticesFile[4], (Vec3{1, 0, 5}));
}

TEST(DatReader, SparseVertexNumbersMapToTheirVertices) {
  const Mesh mesh = LoadGood("sparse_vertex_numbers.dat");
  ASSERT_EQ(mesh.FaceCount(), 1U);
  const auto face = mesh.Face(0);
  EXPECT_EQ(mesh.verticesFile[face[0]], (Vec3{0, 0, 0}));  // 10
  EXPECT_EQ(mesh.verticesFile[face[2]], (Vec3{1, 1, 0}));  // 35
  EXPECT_EQ(mesh.verticesFile[face[3]], (Vec3{0, 1, 0}));  // 7
}

TEST(DatReader, MinusMarksHiddenEdgesAndHashEndsAFace) {
  const Mesh mesh = LoadGood("hidden_edges_and_hash_end.dat");
  ASSERT_EQ(mesh.FaceCount(), 1U);
  EXPECT_EQ(mesh.Face(0)[0], 0U);
  EXPECT_EQ(mesh.edgeHidden, (std::vector<uint8_t>{1, 0, 1, 0}));
}

TEST(DatReader, AcceptsEveryNumberForm) {
  const Mesh mesh = LoadGood("number_forms.dat");
  ASSERT_EQ(mesh.verticesFile.size(), 3U);
  EXPECT_EQ(mesh.verticesFile[0], (Vec3{150.0, -0.2, 3.0}));
  EXPECT_EQ(mesh.verticesFile[1], (Vec3{0.5, 5.0, 0.0}));
  EXPECT_EQ(mesh.verticesFile[2], (Vec3{0.0, 7.0, 100.0}));
}

TEST(DatReader, TwoVerticesAreASegmentAndOneIsNothing) {
  const Mesh mesh = LoadGood("segments_and_points.dat");
  EXPECT_EQ(mesh.FaceCount(), 1U);
  ASSERT_EQ(mesh.segments.size(), 1U);
  EXPECT_EQ(mesh.segments[0], (std::array<uint32_t, 2>{0, 1}));
}

TEST(DatReader, SkipsAUtf8ByteOrderMark) {
  EXPECT_EQ(LoadGood("utf8_byte_order_mark.dat").FaceCount(), 1U);
  // Columns on line 1 count from after the mark.
  Loaded<Mesh> bad = ParseDat(
      "\xEF\xBB\xBF"
      "1 0 x 0\n",
      "bom.dat");
  ASSERT_FALSE(bad.Ok());
  EXPECT_EQ(bad.Error().ToString().substr(0, 12), "bom.dat:1:5:");
}

TEST(DatReader, CrlfBlankLinesAndTabs) {
  EXPECT_EQ(LoadGood("crlf_line_endings.dat").FaceCount(), 1U);
  EXPECT_EQ(LoadGood("blank_lines_and_tabs.dat").FaceCount(), 1U);
}

TEST(DatReader, WriterOutputReadsBackTheSame) {
  const Mesh mesh = LoadGood("hidden_edges_and_hash_end.dat");
  Loaded<Mesh> again = ParseDat(WriteDat(mesh), "again.dat");
  ASSERT_TRUE(again.Ok());
  EXPECT_EQ(again.Value().faceCorners, mesh.faceCorners);
  EXPECT_EQ(again.Value().edgeHidden, mesh.edgeHidden);
  EXPECT_EQ(again.Value().verticesFile, mesh.verticesFile);
}

struct BadFile {
  const char* name;
  const char* message;  // after "<path>:"
};

void PrintTo(const BadFile& badFile, std::ostream* out) {
  *out << badFile.name;
}

class DatReaderErrors : public testing::TestWithParam<BadFile> {};

TEST_P(DatReaderErrors, NamesLineColumnAndWhatWasExpected) {
  const std::string path = SourcePath(std::string("tests/models/bad/") + GetParam().name);
  Loaded<Mesh> mesh = LoadModelFile(path);
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().ToString(), path + ":" + GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    BadFiles, DatReaderErrors,
    testing::Values(
        BadFile{"undefined_vertex.dat", "14:7: vertex 12 is not defined (highest is 9)"},
        BadFile{"vertex_zero_in_face.dat",
                "5:3: vertex number 0 is not valid (vertex numbers start at 1)"},
        BadFile{"missing_face_terminator.dat",
                "5:6: expected a vertex number, or '.' or '#' to end the face"},
        BadFile{"bad_coordinate.dat",
                "3:5: expected the y coordinate of vertex 3 (a number), found 'x'"},
        BadFile{"missing_coordinate.dat",
                "2:6: expected the z coordinate of vertex 2 (a number), found end of line"},
        BadFile{"duplicate_vertex.dat", "3:1: vertex 2 is already defined on line 2"},
        BadFile{"no_faces_section.dat",
                "4:1: expected a 'Faces:' line after the vertices (found end of file)"},
        BadFile{"vertex_number_zero.dat",
                "1:1: vertex number 0 is not valid (vertex numbers start at 1)"},
        BadFile{"negative_vertex_number.dat",
                "1:1: expected a vertex number (a whole number >= 1) or 'Faces:', found '-'"},
        BadFile{"text_after_face_end.dat",
                "5:8: expected end of line after the end of the face, found 'e'"},
        BadFile{"coordinate_out_of_range.dat",
                "1:3: the x coordinate of vertex 1 is out of range for a double"},
        BadFile{"escape_sequence_in_vertex.dat",
                "2:1: expected a vertex number or 'Faces:', found '\\x1B'"},
        BadFile{"extra_number_after_z.dat",
                "1:9: expected end of line after the z coordinate of vertex 1, found '0'"},
        BadFile{"vertex_number_too_large.dat",
                "1:1: vertex number is too large (at most 2147483647)"},
        BadFile{"nul_byte_in_coordinate.dat",
                "1:4: expected a blank after the x coordinate of vertex 1, found '\\x00'"},
        BadFile{"letter_in_face.dat",
                "5:5: expected a vertex number, or '.' or '#' to end the face, found 'x'"},
        BadFile{"letter_after_vertex_number.dat",
                "1:2: expected a blank after vertex number 1, found 'a'"},
        BadFile{"float_vertex_number_in_face.dat",
                "5:5: expected end of line after the end of the face, found '5'"},
        BadFile{"text_after_faces_header.dat",
                "2:8: expected end of line after 'Faces:', found 'p'"},
        BadFile{"empty_file.dat",
                "1:1: expected a 'Faces:' line after the vertices (found end of file)"},
        BadFile{"face_before_any_vertex.dat",
                "2:1: vertex 1 is not defined (no vertices are defined)"}),
    [](const testing::TestParamInfo<BadFile>& info) {
      std::string name = info.param.name;
      return name.substr(0, name.find('.'));
    });

TEST(ModelLoader, MissingFileSaysSo) {
  Loaded<Mesh> mesh = LoadModelFile("/nonexistent/model.dat");
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().ToString(),
            "/nonexistent/model.dat: cannot open: No such file or directory");
}

TEST(ModelLoader, ImportsObjThroughAssimp) {
  const Mesh mesh = LoadGood("quad_and_triangle.obj");
  EXPECT_EQ(mesh.FaceCount(), 2U);
  EXPECT_EQ(mesh.Face(0).size(), 4U);  // polygons stay polygons
  EXPECT_EQ(mesh.verticesFile.size(), 5U);
}

}  // namespace
}  // namespace termshade
