// Issue 9: the ray hierarchy's bounds hold (every corner in its leaf's and
// every ancestor's box and slab, every triangle in one leaf, every normal in its
// ancestors' cones, the facing verdicts true for every face), and a frame
// drawn by casting a ray a sample through it is bit for bit the frame of the
// plain face-by-face loop (faces, glyphs, depth, faces seen) on the shipped
// scenes, hard cases and spheres, at several sizes, views, methods and
// thread counts, including views where the rays do not apply.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/FitCamera.h"
#include "geometry/RayBvh.h"
#include "geometry/ViewingTransform.h"
#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/RayCastStage.h"
#include "raster/Renderer.h"
#include "support/FrameCompare.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

std::shared_ptr<const RayBvh> Hierarchy(const Scene& scene) {
  return std::make_shared<const RayBvh>(BuildRayBvh(scene));
}

struct Slot {
  uint32_t node;
  int child;
};

// Calls leaf(ref, path) for every leaf, path the (node, child) slots from the root down.
template <typename Leaf>
void ForEachLeaf(const RayBvh& bvh, Leaf&& leaf) {
  std::vector<std::vector<Slot>> stack{{}};
  std::vector<uint32_t> refs{0};
  while (!refs.empty()) {
    const uint32_t ref = refs.back();
    std::vector<Slot> path = std::move(stack.back());
    refs.pop_back();
    stack.pop_back();
    if (RayBvh::IsLeaf(ref)) {
      leaf(ref, path);
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      if (bvh.nodes[ref].child[i] == RayBvh::kEmpty) continue;
      std::vector<Slot> childPath = path;
      childPath.push_back({ref, i});
      refs.push_back(bvh.nodes[ref].child[i]);
      stack.push_back(std::move(childPath));
    }
  }
}

// Inside the child's box and its slab along the node's axis.
bool InSlot(const RayBvhNode& node, int child, Vec3 p) {
  const double c[3] = {p.x, p.y, p.z};
  for (int k = 0; k < 3; ++k) {
    if (!(c[k] >= node.low[k][child] && c[k] <= node.high[k][child])) return false;
  }
  const float* const axis = node.cone.axis;
  const double along = Dot(Vec3{axis[0], axis[1], axis[2]}, p);
  return along >= node.slabLow[child] && along <= node.slabHigh[child];
}

void ExpectBoundsHold(const Scene& scene, const std::string& what) {
  const RayBvh bvh = BuildRayBvh(scene);
  ASSERT_FALSE(bvh.Empty()) << what;
  std::vector<int> seen(scene.triangles.size(), 0);
  ForEachLeaf(bvh, [&](uint32_t ref, const std::vector<Slot>& path) {
    ASSERT_GE(RayBvh::LeafCount(ref), 1U) << what;
    ASSERT_LE(RayBvh::LeafCount(ref), RayBvh::kLeafTriangles) << what;
    for (uint32_t i = 0; i < RayBvh::LeafCount(ref); ++i) {
      const RayBvhLeafTriangle& record = bvh.triangles[RayBvh::LeafFirst(ref) + i];
      const uint32_t t = record.triangle;
      ASSERT_LT(t, scene.triangles.size()) << what;
      ++seen[t];
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(record.vertices[k], scene.triangles[t].vertices[k]) << what << ": triangle " << t;
      }
      for (const uint32_t v : scene.triangles[t].vertices) {
        for (const Slot& slot : path) {
          ASSERT_TRUE(InSlot(bvh.nodes[slot.node], slot.child, scene.verticesWorld[v]))
              << what << ": triangle " << t << " outside node " << slot.node << " child "
              << slot.child;
        }
      }
      const FacePlane& plane = scene.facePlanesWorld[scene.TriangleFace(t)];
      if (Dot(plane.normal, plane.normal) == 0.0) continue;
      for (const Slot& slot : path) {
        const RayBvhCone& cone = bvh.nodes[slot.node].cone;
        EXPECT_NE(cone.coneCos, RayBvhCone::kAllAway) << what << ": node " << slot.node;
        if (!(cone.coneCos > 0.0F) || cone.coneCos == RayBvhCone::kAllAway) continue;
        const Vec3 axis{cone.axis[0], cone.axis[1], cone.axis[2]};
        const Vec3 center{cone.center[0], cone.center[1], cone.center[2]};
        EXPECT_GE(Dot(plane.normal, axis) / Length(axis), cone.coneCos) << what;
        EXPECT_LE(Dot(plane.normal, center) - plane.offset, cone.heightMax) << what;
        EXPECT_GE(Dot(plane.normal, center) - plane.offset, cone.heightMin) << what;
      }
    }
  });
  for (size_t t = 0; t < seen.size(); ++t) {
    ASSERT_EQ(seen[t], 1) << what << ": triangle " << t << " in " << seen[t] << " leaves";
  }
}

// A node's faces, all of them: those of every leaf below it.
std::vector<uint32_t> FacesBelow(const RayBvh& bvh, const Scene& scene, uint32_t node) {
  std::vector<uint32_t> faces;
  std::vector<uint32_t> refs{node};
  while (!refs.empty()) {
    const uint32_t ref = refs.back();
    refs.pop_back();
    if (RayBvh::IsLeaf(ref)) {
      for (uint32_t i = 0; i < RayBvh::LeafCount(ref); ++i) {
        faces.push_back(scene.TriangleFace(bvh.triangles[RayBvh::LeafFirst(ref) + i].triangle));
      }
      continue;
    }
    for (const uint32_t child : bvh.nodes[ref].child) {
      if (child != RayBvh::kEmpty) refs.push_back(child);
    }
  }
  return faces;
}

TEST(RayBvh, EveryCornerAndNormalLiesInsideItsNodes) {
  for (const std::string& name : GeneratedSceneNames()) {
    ExpectBoundsHold(PrepareScene(*GenerateScene(name)), name);
  }
  ExpectBoundsHold(PrepareScene(GenerateTriangleSphere(20000)), "sphere 20k");
  for (const double scale : {1e-9, 1e9}) {
    Mesh sphere = GenerateTriangleSphere(3000);
    for (Vec3& p : sphere.verticesFile) p = p * scale;
    ExpectBoundsHold(PrepareScene(sphere), "sphere x" + std::to_string(scale));
  }
  const std::array<Vec3, 4> quad{{{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}};
  ExpectBoundsHold(PrepareScene(test::QuadMesh({quad, quad, quad, quad, quad, quad})),
                   "coplanar duplicates");  // equal Morton codes: split by count
}

// Wherever ConeFacing says a node's faces all face away, none faces the
// point; where it says all face it, every one does.
// Member by member (not the padding), floats by their bits.
bool SameNode(const RayBvhNode& a, const RayBvhNode& b) {
  const RayBvhCone &ca = a.cone, &cb = b.cone;
  return std::memcmp(a.low, b.low, sizeof a.low) == 0 &&
         std::memcmp(a.high, b.high, sizeof a.high) == 0 &&
         std::memcmp(a.slabLow, b.slabLow, sizeof a.slabLow) == 0 &&
         std::memcmp(a.slabHigh, b.slabHigh, sizeof a.slabHigh) == 0 &&
         std::memcmp(a.child, b.child, sizeof a.child) == 0 &&
         std::memcmp(ca.center, cb.center, sizeof ca.center) == 0 &&
         std::memcmp(ca.axis, cb.axis, sizeof ca.axis) == 0 &&
         std::memcmp(&ca.coneCos, &cb.coneCos, sizeof ca.coneCos) == 0 &&
         std::memcmp(&ca.heightMin, &cb.heightMin, sizeof ca.heightMin) == 0 &&
         std::memcmp(&ca.heightMax, &cb.heightMax, sizeof ca.heightMax) == 0;
}

// Big scenes build the root's subtrees on two threads: the same hierarchy,
// node for node in the same order, as one thread builds.
TEST(RayBvh, TwoThreadsBuildTheOneThreadHierarchy) {
  for (const size_t triangles : {size_t{120000}, size_t{300000}}) {
    const Scene scene = PrepareScene(GenerateTriangleSphere(triangles));
    const RayBvh one = BuildRayBvh(scene, nullptr, 1);
    const RayBvh two = BuildRayBvh(scene, nullptr, 2);
    ASSERT_EQ(one.nodes.size(), two.nodes.size()) << triangles;
    EXPECT_EQ(one.triangles, two.triangles) << triangles;
    size_t differing = 0;
    for (size_t n = 0; n < one.nodes.size(); ++n) {
      differing += SameNode(one.nodes[n], two.nodes[n]) ? 0 : 1;
    }
    EXPECT_EQ(differing, 0U) << triangles << " triangles: nodes differ";
    ExpectBoundsHold(scene, std::to_string(triangles) + "-triangle sphere, two threads");
  }
}

TEST(RayBvh, FacingVerdictsHoldForEveryFace) {
  const std::vector<std::pair<std::string, Scene>> scenes = [] {
    std::vector<std::pair<std::string, Scene>> named;
    named.emplace_back("sphere_cone", PrepareScene(*GenerateScene("sphere_cone")));
    named.emplace_back("beams", PrepareScene(*GenerateScene("beams")));
    named.emplace_back("sphere 5k", PrepareScene(GenerateTriangleSphere(5000)));
    return named;
  }();
  int away = 0, toward = 0;
  for (const auto& [name, scene] : scenes) {
    const RayBvh bvh = BuildRayBvh(scene);
    std::mt19937 random(9);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
    for (int trial = 0; trial < 40; ++trial) {
      const Vec3 eye =
          Vec3{coordinate(random), coordinate(random), coordinate(random)} * scene.radiusModelUnits;
      const double eyeLength = Length(eye);
      for (uint32_t node = 0; node < bvh.nodes.size(); ++node) {
        const ClusterFacing facing = ConeFacing(bvh.nodes[node].cone, eye, eyeLength);
        if (facing == ClusterFacing::kMixed) continue;
        (facing == ClusterFacing::kAway ? away : toward) += 1;
        for (const uint32_t face : FacesBelow(bvh, scene, node)) {
          ASSERT_EQ(scene.facePlanesWorld[face].FacesPoint(eye), facing == ClusterFacing::kToward)
              << name << ": node " << node << " face " << face;
        }
      }
    }
  }
  EXPECT_GT(away, 0);  // the cones do decide something
  EXPECT_GT(toward, 0);
}

TEST(RayCastStage, WouldCastOnlyFramesItServes) {
  const Scene sphere = PrepareScene(GenerateTriangleSphere(20000));
  RenderOptions ramp;
  ramp.method = Method::kAuto;
  ramp.threads = 2;
  EXPECT_TRUE(RayCastStage::WouldCast(sphere, 32, 8, ramp));  // 78 a sample: timed against
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 32, 8, ramp,   // render builds from 150
                                       RayCastStage::kFasterFromTrianglesPerSample));
  EXPECT_TRUE(RayCastStage::WouldCast(sphere, 16, 8, ramp,  // 156 a sample
                                      RayCastStage::kFasterFromTrianglesPerSample));
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 60, 8, ramp));   // 42 a sample
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 80, 24, ramp));  // 10 a sample
  RenderOptions other = ramp;
  other.method = Method::kPainter;
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 32, 8, other));
  other = ramp;
  other.cullBackFaces = false;
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 32, 8, other));
  other = ramp;
  other.variant.hierarchy = HierarchyUse::kNever;
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 32, 8, other));
  other = ramp;
  other.glyphs = GlyphMode::kAscii;  // 2x4 samples a cell: 39 a sample at 16x4
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 16, 4, other));
  EXPECT_TRUE(RayCastStage::WouldCast(sphere, 8, 4, other));  // 78 a sample, on threads
  other.threads = 1;  // the sampled rasterizer draws it, casting no rays
  EXPECT_FALSE(RayCastStage::WouldCast(sphere, 8, 4, other));
}

// A hierarchy serves only the triangles it was built over; copies of a scene share it.
TEST(SceneHierarchy, ServesOnlyItsOwnScene) {
  const Scene sphere = PrepareScene(GenerateTriangleSphere(2000));
  const Scene other = PrepareScene(GenerateTriangleSphere(2000));
  EXPECT_EQ(sphere.hierarchy.Get(sphere), nullptr);
  const Scene copy = sphere;  // before the attach: shares the slot, not the triangles
  sphere.hierarchy.Attach(Hierarchy(sphere));
  ASSERT_NE(sphere.hierarchy.Get(sphere), nullptr);
  other.hierarchy.Attach(Hierarchy(sphere));  // built for another scene's triangles
  EXPECT_EQ(other.hierarchy.Get(other), nullptr);
  EXPECT_EQ(copy.hierarchy.Get(copy), nullptr);  // its own triangle array: not served
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(BuildRayBvh(sphere, &cancel).Empty());
}

const std::vector<test::OrbitView> kViews{{0.3, 1.3, 1.0},  {2.1, 0.4, 1.0},  {4.0, 2.6, 2.5},
                                          {1.0, 1.5, 0.35}, {5.5, 1.0, 0.12}, {3.0, 0.05, 0.6}};

// Returns how many frames the rays drew.
int ExpectRayFramesMatch(const std::string& name, const Scene& scene,
                         const std::vector<int>& sizes) {
  scene.hierarchy.Attach(Hierarchy(scene));
  int cast = 0;
  for (size_t s = 0; s + 1 < sizes.size(); s += 2) {
    const int width = sizes[s], height = sizes[s + 1];
    for (const Method method : {Method::kZBuffer, Method::kCull}) {
      for (const bool keepDepth : {true, false}) {
        for (const test::OrbitView& view : kViews) {
          RenderOptions reference;
          reference.method = method;
          reference.keepDepth = keepDepth;
          reference.variant.clusters = false;  // the plain face loop
          Renderer plain;
          const test::DrawnFrame expected =
              test::DrawOrbit(plain, scene, view, width, height, reference);
          for (const int threads : {1, 2, 3}) {
            RenderOptions options = reference;
            options.variant.clusters = true;
            options.threads = threads;
            options.threadsFromTriangles = 0;
            options.variant.hierarchy = HierarchyUse::kAlways;
            Renderer renderer;
            const std::string what =
                name + " " + std::to_string(width) + "x" + std::to_string(height) + " " +
                std::string(MethodName(method)) + " theta " + std::to_string(view.theta) +
                " rho x" + std::to_string(view.rhoScale) + " threads " + std::to_string(threads) +
                (keepDepth ? " depth" : "");
            for (int repeat = 0; repeat < 2; ++repeat) {  // the second reuses its buffers
              const test::DrawnFrame actual =
                  test::DrawOrbit(renderer, scene, view, width, height, options);
              test::ExpectSameFrame(expected, actual, what);
              cast += actual.stats.byHierarchy ? 1 : 0;
            }
          }
        }
      }
    }
  }
  return cast;
}

TEST(RayCastStage, SmallScenesMatchTheFaceLoop) {
  for (const std::string& name : GeneratedSceneNames()) {
    ExpectRayFramesMatch(name, PrepareScene(*GenerateScene(name)), {80, 24, 37, 11});
  }
  const std::array<Vec3, 4> quad{{{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}};
  ExpectRayFramesMatch("coplanar duplicates", PrepareScene(test::QuadMesh({quad, quad, quad})),
                       {80, 24});
  ExpectRayFramesMatch("crossing quads",
                       PrepareScene(test::QuadMesh({
                           {{{-1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, -1}}},
                           {{{-1, -1, 1}, {-1, 1, 1}, {1, 1, -1}, {1, -1, -1}}},
                       })),
                       {80, 24});
  for (const double scale : {1e-9, 1e9}) {  // tiny and huge coordinates
    Mesh sphere = GenerateTriangleSphere(5000);
    for (Vec3& p : sphere.verticesFile) p = p * scale;
    ExpectRayFramesMatch("sphere x" + std::to_string(scale), PrepareScene(sphere), {80, 24});
  }
  // A floor far larger than the view, reaching behind the eye (clipped: no rays), and a quad on it.
  ExpectRayFramesMatch(
      "floor through the eye plane",
      PrepareScene(test::QuadMesh({
          {{{-100, -100, -0.5}, {100, -100, -0.5}, {100, 100, -0.5}, {-100, 100, -0.5}}},
          {{{0, -0.5, -0.5}, {0, 0.5, -0.5}, {0, 0.5, 0.5}, {0, -0.5, 0.5}}},
      })),
      {80, 24});
  Mesh nan = test::QuadMesh({quad});
  nan.verticesFile.push_back({NAN, 0, 0});
  nan.AddFace(std::array<uint32_t, 3>{0, 1, 4});
  nan.AddFace(std::array<uint32_t, 3>{0, 0, 1});  // collinear
  ExpectRayFramesMatch("nan and collinear", PrepareScene(nan), {80, 24});
}

// A triangle 0.3 cells across whose edge lies `gap` cells beyond a sample
// (below it: a top edge; right of it: a left edge), both owned by the top-left
// rule: snapped to 1/512 cell the edge runs through the sample and covers it.
// World points from cell coordinates at eye depth 5, facing the eye.
void AddTriangleBeside(Mesh& mesh, const Camera& camera, int col, int row, bool below, double gap) {
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  const Vec3 eyeWorld = EyePositionWorld(camera.view);
  const Projection& p = camera.projection;
  auto world = [&](double u, double v) {
    const double depth = 5.0;
    const Vec3 eye{(u - p.cx) * depth / p.d, (p.cy - v) * p.cellAspect * depth / p.d, -depth};
    Vec3 out = eyeWorld;  // p_world = R^T p_eye + eye
    for (size_t r = 0; r < 3; ++r) {
      const double e = r == 0 ? eye.x : r == 1 ? eye.y : eye.z;
      out = out + Vec3{eyeFromWorld.At(r, 0), eyeFromWorld.At(r, 1), eyeFromWorld.At(r, 2)} * e;
    }
    return out;
  };
  const double u = col + 0.5, v = row + 0.5;
  std::array<Vec3, 3> corners =
      below ? std::array<Vec3, 3>{world(u - 0.3, v + gap), world(u + 0.3, v + gap),
                                  world(u, v + gap + 0.3)}
            : std::array<Vec3, 3>{world(u + gap, v - 0.3), world(u + gap, v + 0.3),
                                  world(u + gap + 0.3, v)};
  // Facing the eye: the normal towards it.
  if (Dot(Cross(corners[1] - corners[0], corners[2] - corners[0]), eyeWorld - corners[0]) < 0.0) {
    std::swap(corners[1], corners[2]);
  }
  const auto base = static_cast<uint32_t>(mesh.verticesFile.size());
  for (const Vec3& c : corners) mesh.verticesFile.push_back(c);
  mesh.AddFace(std::array<uint32_t, 3>{base, base + 1, base + 2});
}

// Rays start below what their tile's pyramid reaches (through the tile's
// corner samples). A triangle just outside that pyramid still covers the
// tile's edge sample once snapped: the pyramid is widened like every box.
// The view looks along -x, so the boxes of the triangles (in the plane x =
// 0) lie outside the pyramid where their triangles do.
TEST(RayCastStage, TrianglesSnappedOntoATilesEdgeSamplesAreFound) {
  const int width = 80, height = 24;
  const int tileCols = RayCastStage::kTileCols, tileRows = RayCastStage::kTileRows;
  const Camera camera{{5.0, 0.0, std::numbers::pi / 2}, {200.0, 40.0, 12.0, 2.0}};
  for (const bool below : {true, false}) {
    Mesh mesh;
    mesh.upAxisFile = UpAxis::kPlusZ;
    // Below every sample of each tile's bottom row, or right of every sample of its right column.
    for (int row = 0; row < height; ++row) {
      for (int col = 0; col < width; ++col) {
        if (below ? row % tileRows == tileRows - 1 : col % tileCols == tileCols - 1) {
          AddTriangleBeside(mesh, camera, col, row, below, 0.0008);
        }
      }
    }
    const int triangles = static_cast<int>(mesh.FaceCount());
    // Two specks at opposite corners: the box, and so the world, centered on the origin.
    const auto base = static_cast<uint32_t>(mesh.verticesFile.size());
    for (const double a : {-1.5, 1.5}) {
      mesh.verticesFile.push_back({a, a, a});
      mesh.verticesFile.push_back({a * 0.999, a, a});
      mesh.verticesFile.push_back({a, a * 0.999, a});
    }
    mesh.AddFace(std::array<uint32_t, 3>{base, base + 1, base + 2});
    mesh.AddFace(std::array<uint32_t, 3>{base + 3, base + 4, base + 5});
    const Scene scene = PrepareScene(std::move(mesh));
    scene.hierarchy.Attach(Hierarchy(scene));
    RenderOptions reference;
    reference.variant.clusters = false;
    test::DrawnFrame expected{{}, {}, {}};
    expected.cells.Resize(width, height);
    expected.depth.Resize(width, height);
    Renderer plain;
    expected.stats = plain.Render(scene, camera, reference, expected.depth, expected.cells);
    int covered = 0;
    for (const uint32_t face : expected.cells.FaceNumbers()) covered += face != 0 ? 1 : 0;
    EXPECT_EQ(covered, triangles) << "each triangle covers its edge sample, and only it";
    for (const int threads : {1, 2}) {
      RenderOptions options = reference;
      options.variant.clusters = true;
      options.variant.hierarchy = HierarchyUse::kAlways;
      options.threads = threads;
      options.threadsFromTriangles = 0;
      test::DrawnFrame actual{{}, {}, {}};
      actual.cells.Resize(width, height);
      actual.depth.Resize(width, height);
      Renderer renderer;
      actual.stats = renderer.Render(scene, camera, options, actual.depth, actual.cells);
      EXPECT_TRUE(actual.stats.byHierarchy);
      test::ExpectSameFrame(expected, actual,
                            std::string(below ? "below" : "right of") + " the tiles' edge samples");
    }
  }
}

// Two threads, whatever the triangle count, drawn by clusters only.
RenderOptions ClusterOptions(Method method, bool keepDepth) {
  RenderOptions options;
  options.method = method;
  options.keepDepth = keepDepth;
  options.threads = 2;
  options.threadsFromTriangles = 0;
  options.variant.hierarchy = HierarchyUse::kNever;
  return options;
}

// Where both passes may draw (kWhenFaster, enough triangles a sample) the
// renderer times them against each other: after a key's first frame (the
// prior's, uncounted) each pass draws two frames in turn, and every frame,
// whichever pass drew it, is the cluster pass's. Another frame size or
// another hierarchy (a new scene) starts the timing over.
TEST(RayCastStage, MeasuredChoiceDrawsBothPassesWithTheSameFrames) {
  const Scene sphere = PrepareScene(GenerateTriangleSphere(12000));  // 94 a sample at 16x8
  const RenderOptions clusters = ClusterOptions(Method::kAuto, true);
  RenderOptions measured = clusters;
  measured.variant.hierarchy = HierarchyUse::kWhenFaster;
  Renderer reference, chooser;
  int frame = 0;
  // The frames cast among the next five at width x height, each checked against the clusters'.
  auto castOfFive = [&](int width, int height) {
    int cast = 0;
    for (int k = 0; k < 5; ++k, ++frame) {
      const test::OrbitView view{0.2 * frame, 1.2, 1.0};
      const test::DrawnFrame expected =
          test::DrawOrbit(reference, sphere, view, width, height, clusters);
      const test::DrawnFrame actual =
          test::DrawOrbit(chooser, sphere, view, width, height, measured);
      test::ExpectSameFrame(expected, actual, "frame " + std::to_string(frame));
      cast += actual.stats.byHierarchy ? 1 : 0;
    }
    return cast;
  };
  sphere.hierarchy.Attach(Hierarchy(sphere));
  // Once timing has begun, five frames of one key cast 0 or 5 times, never 2.
  EXPECT_EQ(castOfFive(16, 8), 2)
      << "the prior (clusters) twice and uncounted once, the rays twice";
  EXPECT_EQ(castOfFive(15, 8), 2) << "another size starts over";
  sphere.hierarchy.Attach(Hierarchy(sphere));  // a new hierarchy, maybe at the old one's address
  EXPECT_EQ(castOfFive(15, 8), 2) << "another hierarchy starts over";
  for (int k = 0; k < 6; ++k) castOfFive(15, 8);  // the chosen pass and its probes
}

TEST(RayCastStage, Sphere200kMatchesTheFaceLoopAndIsCast) {
  const int cast = ExpectRayFramesMatch("sphere 200k", PrepareScene(GenerateTriangleSphere(200000)),
                                        {160, 48, 61, 7});
  EXPECT_GT(cast, 0);  // not only the views where the rays do not apply
}

// Real models: every model of tests/models and Assimp's test models that
// loads, drawn by rays and by clusters from views near and far, zbuffer and
// cull, depth kept: the same faces and depth in every cell.
TEST(RayCastStage, ModelFilesMatchTheClusterPass) {
  int scenes = 0, cast = 0;
  for (const std::string& root :
       {test::SourcePath("tests/models"), std::string("/usr/share/assimp/models")}) {
    std::error_code error;
    for (std::filesystem::recursive_directory_iterator it(root, error), end; !error && it != end;
         it.increment(error)) {
      if (!it->is_regular_file(error)) continue;
      Loaded<Mesh> mesh = LoadModelFile(it->path().string());
      if (!mesh.Ok()) continue;
      const Scene scene = PrepareScene(std::move(mesh.Value()));
      if (scene.triangles.empty()) continue;
      ++scenes;
      scene.hierarchy.Attach(Hierarchy(scene));
      for (const Method method : {Method::kZBuffer, Method::kCull}) {
        for (const test::OrbitView& view : {test::OrbitView{0.3, 1.1, 1.0}, {4.4, 2.0, 0.3}}) {
          const RenderOptions clusters = ClusterOptions(method, true);
          RenderOptions rays = clusters;
          rays.variant.hierarchy = HierarchyUse::kAlways;
          Renderer byClusters, byRays;
          const test::DrawnFrame expected =
              test::DrawOrbit(byClusters, scene, view, 97, 31, clusters);
          const test::DrawnFrame actual = test::DrawOrbit(byRays, scene, view, 97, 31, rays);
          test::ExpectSameFrame(expected, actual,
                                it->path().string() + " " + std::string(MethodName(method)) +
                                    " theta " + std::to_string(view.theta));
          cast += actual.stats.byHierarchy ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GT(scenes, 0);
  EXPECT_GT(cast, 0);
}

}  // namespace
}  // namespace termshade
