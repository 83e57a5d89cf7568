// Real models as users have them (tests/models/real, licences in LICENCES.md):
// each drawn upright at the default view, as a golden text frame, and in the
// file's own colours, as a golden ansi (24-bit) frame.
// Set TERMSHADE_UPDATE=1 (or TERMSHADE_UPDATE_GOLDEN=1) to rewrite the frames after a deliberate
// change.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>

#include "io/write/FrameFormats.h"
#include "support/GoldenFile.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

struct RealModel {
  const char* file;
  UpAxis conventionAxis;          ///< SPEC 10: the format's convention
  std::optional<UpAxis> upright;  ///< --up a user gives when the file breaks its convention
  bool coloured;                  ///< the file gives its faces colours
};

const RealModel kRealModels[] = {
    {"spider_y_up.obj", UpAxis::kPlusY, std::nullopt, true},  // MTL Kd
    {"spider_z_up_binary.stl", UpAxis::kPlusZ, std::nullopt, false},
    {"vase_vertex_colours.ply", UpAxis::kPlusY, std::nullopt, true},
    {"vase_y_up.gltf", UpAxis::kPlusY, std::nullopt, true},  // baseColorFactor
    // Wuson is modelled z-up though OFF's convention is +y: upright with --up z,
    // and inside out (turned outward when prepared).
    {"wuson_inside_out.off", UpAxis::kPlusY, UpAxis::kPlusZ, false},
};

std::string Stem(const std::string& file) {
  return file.substr(0, file.find('.'));
}

void ExpectGolden(const std::string& name, const std::string& actual) {
  test::ExpectTextGolden(test::SourcePath("tests/golden/" + name), actual);
}

class RealModelFrames : public testing::TestWithParam<RealModel> {};

TEST_P(RealModelFrames, UprightAtTheDefaultView) {
  const RealModel& model = GetParam();
  Mesh mesh = test::LoadMesh(std::string("tests/models/real/") + model.file);
  EXPECT_EQ(mesh.upAxisFile, model.conventionAxis);  // SPEC 10, from the loader
  const Scene scene = PrepareScene(std::move(mesh), model.upright);
  EXPECT_EQ(scene.upAxis, model.upright.value_or(model.conventionAxis));
  const std::string actual = test::RenderFrame(scene, 0.3, 1.3, 80, 24, RenderOptions{}).Text();
  ExpectGolden("real_" + Stem(model.file) + ".zbuffer.default.txt", actual);
}

TEST_P(RealModelFrames, InTheFilesOwnColours) {
  const RealModel& model = GetParam();
  Mesh mesh = test::LoadMesh(std::string("tests/models/real/") + model.file);
  EXPECT_EQ(!mesh.faceColors.empty(), model.coloured);
  const Scene scene = PrepareScene(std::move(mesh), model.upright);
  RenderOptions options;
  options.twoColour = true;  // as the ansi dump draws
  const test::Frame frame = test::RenderFrame(scene, 0.3, 1.3, 80, 24, options);
  std::string actual;
  AppendAnsiFrame(frame.cells, scene.source.faceColors, options.ramp.LevelCount(),
                  ColourMode::kTrueColour, actual);
  ExpectGolden("real_" + Stem(model.file) + ".zbuffer.default.ansi", actual);
}

INSTANTIATE_TEST_SUITE_P(Files, RealModelFrames, testing::ValuesIn(kRealModels),
                         [](const testing::TestParamInfo<RealModel>& info) {
                           return Stem(info.param.file);
                         });

}  // namespace
}  // namespace termshade
