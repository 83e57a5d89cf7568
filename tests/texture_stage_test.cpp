// Textures (issue 33, item 2): each cell's colours from the texels its
// samples see, with exact perspective-correct coordinates; texture levels.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/FaceUv.h"
#include "geometry/LevelOfDetail.h"
#include "geometry/Projection.h"
#include "geometry/Scene.h"
#include "geometry/SrgbCoding.h"
#include "geometry/TextureLevels.h"
#include "geometry/ViewingTransform.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/FrameFidelity.h"
#include "raster/Renderer.h"
#include "shade/CellColour.h"
#include "shade/GlyphMode.h"

namespace termshade {
namespace {

constexpr Srgb8 kRed{255, 0, 0};
constexpr Srgb8 kBlue{0, 0, 255};

// A texture red left of `splitTexels` (default: half) and blue right of it.
TextureImage HalvesTexture(uint32_t side, uint32_t splitTexels = 0) {
  if (splitTexels == 0) splitTexels = side / 2;
  TextureImage image{side, side, {}, {}, {}};
  for (uint32_t y = 0; y < side; ++y) {
    for (uint32_t x = 0; x < side; ++x) {
      const Srgb8 c = x < splitTexels ? kRed : kBlue;
      image.srgbTexels.insert(image.srgbTexels.end(), {c.r, c.g, c.b});
    }
  }
  return image;
}

// A 2 x 2 square in the y-z plane facing +x, u along +y and v along +z.
Mesh TexturedSquare(const TextureImage& image) {
  Mesh mesh;
  mesh.upAxisFile = UpAxis::kPlusZ;
  mesh.verticesFile = {{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}};
  mesh.AddFace(std::array<uint32_t, 4>{0, 1, 2, 3});
  mesh.textures = {"halves.png"};
  mesh.textureImages = {image};
  mesh.faceTextures = {0};
  mesh.cornerUvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return mesh;
}

struct Drawn {
  CellBuffer cells;
  DepthBuffer depth;
};

Drawn Draw(const Scene& scene, const Camera& camera, GlyphMode glyphs, bool textures = true) {
  Drawn drawn;
  drawn.cells.Resize(80, 24);
  drawn.depth.Resize(80, 24);
  RenderOptions options;
  options.glyphs = glyphs;
  options.twoColour = true;
  options.textures = textures;
  Renderer renderer;
  renderer.Render(scene, camera, options, drawn.depth, drawn.cells);
  return drawn;
}

Srgb8 Unpacked(uint32_t albedo) {
  return EncodeSrgb8(UnpackAlbedo(albedo));
}

TEST(TextureStage, CellsTakeTheTexelsTheirSamplesSeeInEveryGlyphMode) {
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(16)));
  ASSERT_TRUE(scene.textures.Any());
  const Camera camera{{6.0, 0.0, std::numbers::pi / 2}, FitProjection(1.5, 6.0, 80, 24, 2.0)};
  for (const GlyphMode mode : {GlyphMode::kRamp, GlyphMode::kSextants, GlyphMode::kQuadrants}) {
    const Drawn drawn = Draw(scene, camera, mode);
    int red = 0, blue = 0;
    for (int row = 0; row < 24; ++row) {
      for (int col = 0; col < 80; ++col) {
        if (drawn.cells.FaceNumber(col, row) == 0) continue;
        // (Edge cells blend with the far side: the texture repeats.)
        const bool edge = col == 0 || col == 79 || drawn.cells.FaceNumber(col - 1, row) == 0 ||
                          drawn.cells.FaceNumber(col + 1, row) == 0;
        const uint32_t albedo = drawn.cells.ForeAlbedo(col, row);
        ASSERT_NE(albedo, 0U) << "cell " << col << "," << row;
        const Srgb8 c = Unpacked(albedo);
        // Left of the square's middle (screen right is +y, u) red, right blue.
        const double u = col + 0.5 - camera.projection.cx;
        if (edge || std::fabs(u) < 1.0) continue;
        EXPECT_EQ(c, u < 0 ? kRed : kBlue) << col << "," << row;
        ++(u < 0 ? red : blue);
      }
    }
    EXPECT_GT(red, 100);
    EXPECT_GT(blue, 100);
  }
}

TEST(TextureStage, TheBoundaryLiesWherePerspectivePutsItNotMidwayOnScreen) {
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(256)));
  // Close and oblique: the near half of the square looks much wider.
  const ViewParams view{1.8, 0.7, std::numbers::pi / 2};
  const Camera camera{view, FitProjection(0.6, 1.8, 80, 24, 2.0)};  // zoomed in
  const Drawn drawn = Draw(scene, camera, GlyphMode::kRamp);
  const Mat4 eyeFromWorld = EyeFromWorld(view);
  const auto columnOf = [&](Vec3 pWorld) {
    return ProjectToCell(camera.projection, TransformPoint(eyeFromWorld, pWorld)).u;
  };
  // On the middle row: the texture's boundary is the projection of u = 0.5 (y = 0).
  const int row = static_cast<int>(camera.projection.cy);
  const double z = 0.0;
  const double exact = columnOf({0, 0, z});
  const double affine = 0.5 * (columnOf({0, -1, z}) + columnOf({0, 1, z}));
  ASSERT_GT(std::fabs(exact - affine), 3.0) << "the view must tell the two apart";
  for (int col = 0; col < 80; ++col) {
    if (drawn.cells.FaceNumber(col, row) == 0) continue;
    const double center = col + 0.5;
    if (std::fabs(center - exact) < 1.0) continue;  // the boundary's cell
    if (col == 0 || col == 79 || drawn.cells.FaceNumber(col - 1, row) == 0 ||
        drawn.cells.FaceNumber(col + 1, row) == 0)
      continue;  // edge cells blend with the far side (the texture repeats)
    const bool leftOfBoundary = (center < exact) == (columnOf({0, -1, z}) < exact);
    EXPECT_EQ(Unpacked(drawn.cells.ForeAlbedo(col, row)), leftOfBoundary ? kRed : kBlue)
        << "column " << col << ", exact boundary " << exact << ", affine " << affine;
  }
}

TEST(TextureStage, ABlockCellAcrossTheTexturesBoundaryShowsBothSides) {
  // (Split at 3/8: the boundary crosses cells, not a cell edge.)
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(256, 96)));
  const Camera camera{{6.0, 0.0, std::numbers::pi / 2}, FitProjection(1.5, 6.0, 80, 24, 2.0)};
  // (Blocks split a cell top from bottom: a vertical boundary is not theirs to show.)
  for (const GlyphMode mode : {GlyphMode::kSextants, GlyphMode::kQuadrants}) {
    const Drawn drawn = Draw(scene, camera, mode);
    int split = 0;
    for (int row = 0; row < 24; ++row) {
      for (int col = 0; col < 80; ++col) {
        const uint32_t fore = drawn.cells.ForeAlbedo(col, row);
        const uint32_t back = drawn.cells.BackAlbedo(col, row);
        if (fore == 0 || back == 0 || fore == back) continue;
        // One face, two colours: the pattern splits the cell's samples.
        EXPECT_EQ(drawn.cells.FaceNumber(col, row), drawn.cells.BackFaceNumber(col, row));
        EXPECT_NE(drawn.cells.Glyph(col, row), U' ');
        EXPECT_NE(drawn.cells.Glyph(col, row), U'\u2588');
        ++split;
      }
    }
    // Each row the square covers has its boundary in one column, split there.
    EXPECT_GE(split, 5) << GlyphModeName(mode);
  }
}

TEST(TextureStage, OffOrWithoutColourTheCellsKeepTheirFaceColours) {
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(16)));
  const Camera camera{{6.0, 0.0, std::numbers::pi / 2}, FitProjection(1.5, 6.0, 80, 24, 2.0)};
  EXPECT_FALSE(Draw(scene, camera, GlyphMode::kSextants, false).cells.HasAlbedos());
  Drawn drawn;
  drawn.cells.Resize(80, 24);
  drawn.depth.Resize(80, 24);
  Renderer renderer;
  RenderOptions options;  // no colours shown: nothing to texture
  renderer.Render(scene, camera, options, drawn.depth, drawn.cells);
  EXPECT_FALSE(drawn.cells.HasAlbedos());
}

TEST(TextureStage, AnUndecodedTextureLeavesTheSceneUntextured) {
  TextureImage broken;
  broken.problem = "cannot decode";
  const Scene scene = PrepareScene(TexturedSquare(broken));
  EXPECT_FALSE(scene.textures.Any());
}

TEST(TextureStage, TheSourceMeshGivesTheTexturesBack) {
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(4)));
  const Mesh back = scene.SourceMesh();
  ASSERT_EQ(back.textureImages.size(), 1U);
  EXPECT_EQ(back.textureImages[0].srgbTexels, HalvesTexture(4).srgbTexels);
  ASSERT_EQ(back.cornerUvs.size(), 4U);
  // Each corner keeps its coordinates, in whatever order the face comes back.
  for (size_t i = 0; i < 4; ++i) {
    const Vec3 p = back.verticesFile[back.faceCorners[i]];
    EXPECT_EQ(back.cornerUvs[i][0], p.y > 0 ? 1.0F : 0.0F);
    EXPECT_EQ(back.cornerUvs[i][1], p.z > 0 ? 1.0F : 0.0F);
  }
}

TEST(TextureFidelity, TheExactImageIsShadeTimesTheTexelsLuminance) {
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(16)));
  const Camera camera{{6.0, 0.0, std::numbers::pi / 2}, FitProjection(1.5, 6.0, 80, 24, 2.0)};
  RenderOptions options;
  const InkImage textured = ExactImage(scene, camera, options, 80, 24, 1.0);
  options.textures = false;
  const InkImage plain = ExactImage(scene, camera, options, 80, 24, 1.0);
  // The middle row of pixels, 10 cells either side of the square's middle:
  // red's luminance (0.2126) on the left, blue's (0.0722) on the right.
  const int yPx = static_cast<int>(camera.projection.cy * kFidelityPxPerCellDown);
  for (const auto& [cellsAcross, luminance] : {std::pair{-10, 0.2126}, std::pair{10, 0.0722}}) {
    const int xPx =
        static_cast<int>((camera.projection.cx + cellsAcross) * kFidelityPxPerCellAcross);
    const size_t at = static_cast<size_t>(yPx) * textured.widthPx + xPx;
    ASSERT_GT(plain.pixels[at], 0.1F) << "the square is lit there";
    EXPECT_NEAR(textured.pixels[at] / plain.pixels[at], luminance, 1e-4) << cellsAcross;
  }
}

TEST(TextureFidelity, TexturedFramesMatchTheTexturedModelBetterThanPlainOnes) {
  const Scene scene = PrepareScene(TexturedSquare(HalvesTexture(16)));
  const Camera camera{{6.0, 0.3, std::numbers::pi / 2}, FitProjection(1.5, 6.0, 80, 24, 2.0)};
  RenderOptions options;
  options.twoColour = true;
  const InkImage exact = ExactImage(scene, camera, options, 80, 24, 1.0);
  const auto ssimOf = [&](bool textures) {
    const Drawn drawn = Draw(scene, camera, GlyphMode::kSextants, textures);
    return CompareImages(exact, GlyphImage(drawn.cells, DefaultInkTable(), true), 1.0).ssim;
  };
  const double textured = ssimOf(true), plain = ssimOf(false);
  EXPECT_GT(textured, 0.95);
  EXPECT_GT(textured, plain + 0.1) << "plain " << plain;
}

TEST(TextureFidelity, FlickerCountsTextureColoursThatMoveVisibly) {
  CellBuffer before(4, 1);
  before.FaceNumbers()[1] = 7;
  before.Glyphs()[1] = U'#';
  before.UseAlbedos();
  before.ForeAlbedos()[1] = PackAlbedo({100, 100, 100});
  CellBuffer after = before;
  after.ForeAlbedos()[1] = PackAlbedo({100, 112, 100});  // 12 steps: unseen
  EXPECT_EQ(ChangedShare(before, after, true), 0.0);
  after.ForeAlbedos()[1] = PackAlbedo({100, 113, 100});
  EXPECT_EQ(ChangedShare(before, after, true), 1.0);
  EXPECT_EQ(ChangedShare(before, after, false), 0.0) << "mono frames show no texture";
}

TEST(TextureLevels, EachLevelHalvesAndKeepsTheMeanInLinearLight) {
  const TextureLevels levels(HalvesTexture(16));
  ASSERT_EQ(levels.LevelCount(), 5);  // 16, 8, 4, 2, 1
  // The last level is the mean of red and blue in linear light, encoded once.
  const Rgb mean = levels.Sample(0.5, 0.5, 4);
  EXPECT_NEAR(mean.r, 0.5, 1e-2);
  EXPECT_NEAR(mean.b, 0.5, 1e-2);
  EXPECT_EQ(mean.g, 0.0F);
  EXPECT_EQ(Srgb8OfLinear(mean.r), 188);  // not 128: averaged as light, not as bytes
}

TEST(TextureLevels, LookupsRepeatAndSurviveAnyCoordinate) {
  const TextureLevels levels(HalvesTexture(16));
  const Rgb a = levels.Sample(0.1, 0.3, 0);
  const Rgb b = levels.Sample(3.1, -6.7, 0);
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.b, b.b);
  for (const double bad : {std::nan(""), 1e300, -1e300, double{INFINITY}}) {
    const Rgb c = levels.Sample(bad, bad, 0);
    EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
  }
  EXPECT_EQ(levels.LevelFor(0.5), 0);
  EXPECT_EQ(levels.LevelFor(4.0), 2);
  EXPECT_EQ(levels.LevelFor(1e12), 4);
}

}  // namespace
}  // namespace termshade

namespace termshade {
namespace {

// A textured sphere of 200k triangles: u around, red west and blue east.
TEST(TextureLevelOfDetail, LevelsTakeTheirColoursFromTheTexture) {
  Mesh mesh = GenerateSphere(250, 400);
  mesh.textures = {"halves.png"};
  mesh.textureImages = {HalvesTexture(64)};
  mesh.faceTextures.assign(mesh.FaceCount(), 0);
  mesh.faceColors.assign(mesh.FaceCount(), Rgb{1, 1, 1});
  for (const uint32_t corner : mesh.faceCorners) {
    const Vec3 p = mesh.verticesFile[corner];
    const double u = std::atan2(p.y, p.x) / (2 * std::numbers::pi) + 0.5;
    mesh.cornerUvs.push_back({static_cast<float>(u), 0.5F});
  }
  const Scene exact = PrepareScene(std::move(mesh));
  const DetailLevels levels = BuildDetailLevels(exact);
  ASSERT_FALSE(levels.levels.empty());
  for (const DetailLevel& level : levels.levels) {
    int red = 0, blue = 0;
    for (size_t f = 0; f < level.scene.FaceCount(); ++f) {
      // The face colour stays the material's (textures off); the flat colour is the texture's.
      EXPECT_EQ(level.scene.source.faceColors[f], (Rgb{1, 1, 1}));
      ASSERT_EQ(level.scene.textures.flatColours.size(), level.scene.FaceCount());
      const Rgb c = level.scene.textures.flatColours[f];
      // Away from the seams (u near 0, 0.5, 1) and the poles, each face is one colour.
      const auto& v = level.scene.triangles[f].vertices;
      const Vec3 p = (level.scene.verticesWorld[v[0]] + level.scene.verticesWorld[v[1]] +
                      level.scene.verticesWorld[v[2]]) *
                     (1.0 / 3.0);
      if (std::fabs(p.z) > 0.5 * Length(p)) continue;
      const double u = std::atan2(p.y, p.x) / (2 * std::numbers::pi) + 0.5;
      if (std::fabs(u - 0.25) < 0.1) {
        EXPECT_TRUE(c.r > 0.9F && c.b < 0.1F) << u << ": " << c.r << " " << c.b;
        ++red;
      }
      if (std::fabs(u - 0.75) < 0.1) {
        EXPECT_TRUE(c.b > 0.9F && c.r < 0.1F) << u << ": " << c.r << " " << c.b;
        ++blue;
      }
    }
    EXPECT_GT(red, 10);
    EXPECT_GT(blue, 10);
  }
}

}  // namespace
}  // namespace termshade

namespace termshade {
namespace {

// A 400-gon (more triangles than are searched) mapped by a plane projection:
// its fitted map gives that projection back anywhere on the face.
TEST(FaceUv, ABigPolygonsCoordinatesComeFromItsFittedPlaneMap) {
  Mesh mesh;
  mesh.upAxisFile = UpAxis::kPlusZ;
  std::vector<uint32_t> corners;
  for (uint32_t i = 0; i < 400; ++i) {
    const double angle = 2 * std::numbers::pi * i / 400;
    mesh.verticesFile.push_back({std::cos(angle), std::sin(angle), 0.0});
    mesh.cornerUvs.push_back({static_cast<float>(0.25 + 0.5 * std::cos(angle)),
                              static_cast<float>(0.5 - 0.25 * std::sin(angle))});
    corners.push_back(i);
  }
  mesh.AddFace(corners);
  mesh.textures = {"halves.png"};
  mesh.textureImages = {HalvesTexture(4)};
  mesh.faceTextures = {0};
  const Scene scene = PrepareScene(std::move(mesh));
  ASSERT_EQ(scene.textures.bigFaceUvs.size(), 1U);
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{0.5, -0.3}, std::pair{-0.7, 0.1}}) {
    // World space is file space centered on the bounding box (centered here).
    const auto uv = FaceUvAt(scene, 0, Vec3{x, y, 0.0});
    EXPECT_NEAR(uv[0], 0.25 + 0.5 * x, 1e-6);
    EXPECT_NEAR(uv[1], 0.5 - 0.25 * y, 1e-6);
  }
}

}  // namespace
}  // namespace termshade
