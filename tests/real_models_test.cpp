// Real models as users have them (tests/models/real, licences in LICENCES.md):
// each drawn upright at the default view, as a golden text frame.
// Set TERMSHADE_UPDATE_GOLDEN=1 to rewrite the frames after a deliberate change.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>

#include "support/TestSupport.h"

namespace termshade {
namespace {

struct RealModel {
  const char* file;
  UpAxis conventionAxis;          ///< SPEC 10: the format's convention
  std::optional<UpAxis> upright;  ///< --up a user gives when the file breaks its convention
};

const RealModel kRealModels[] = {
    {"spider_y_up.obj", UpAxis::kPlusY, std::nullopt},
    {"spider_z_up_binary.stl", UpAxis::kPlusZ, std::nullopt},
    {"vase_vertex_colours.ply", UpAxis::kPlusY, std::nullopt},
    {"vase_y_up.gltf", UpAxis::kPlusY, std::nullopt},
    // Wuson is modelled z-up though OFF's convention is +y: upright with --up z,
    // and inside out (turned outward when prepared).
    {"wuson_inside_out.off", UpAxis::kPlusY, UpAxis::kPlusZ},
};

std::string Stem(const std::string& file) {
  return file.substr(0, file.find('.'));
}

class RealModelFrames : public testing::TestWithParam<RealModel> {};

TEST_P(RealModelFrames, UprightAtTheDefaultView) {
  const RealModel& model = GetParam();
  Mesh mesh = test::LoadMesh(std::string("tests/models/real/") + model.file);
  EXPECT_EQ(mesh.upAxisFile, model.conventionAxis);  // SPEC 10, from the loader
  const Scene scene = PrepareScene(std::move(mesh), model.upright);
  EXPECT_EQ(scene.upAxis, model.upright.value_or(model.conventionAxis));
  const std::string actual = test::RenderFrame(scene, 0.3, 1.3, 80, 24, RenderOptions{}).Text();
  const std::string path =
      test::SourcePath("tests/golden/real_" + Stem(model.file) + ".zbuffer.default.txt");
  if (std::getenv("TERMSHADE_UPDATE_GOLDEN") != nullptr) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  EXPECT_EQ(test::ReadFile(path), actual)
      << "golden frame " << path << " differs; the actual frame:\n"
      << actual << "(run with TERMSHADE_UPDATE_GOLDEN=1 to accept)";
}

INSTANTIATE_TEST_SUITE_P(Files, RealModelFrames, testing::ValuesIn(kRealModels),
                         [](const testing::TestParamInfo<RealModel>& info) {
                           return Stem(info.param.file);
                         });

}  // namespace
}  // namespace termshade
