// Issue 9: the triangle hierarchy's bounds hold (every corner in its leaf's
// and every ancestor's box, every normal in their cones, the facing verdicts
// true for every face), and a frame drawn by walking it is bit for bit the
// frame of the plain face-by-face loop (faces, glyphs, depth, counts) on the
// shipped scenes, hard cases and spheres, at several sizes, views, methods
// and thread counts, including views where the walk does not apply.
#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "geometry/FitCamera.h"
#include "geometry/TriangleBvh.h"
#include "io/SceneGenerators.h"
#include "raster/HierarchyStage.h"
#include "raster/Renderer.h"
#include "support/FrameCompare.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

std::shared_ptr<const TriangleBvh> Hierarchy(const Scene& scene) {
  return std::make_shared<const TriangleBvh>(BuildTriangleBvh(scene));
}

// The point's coordinates in the node's axes, as far out as the node lets them be (<= 1 inside).
double Reach(const BvhNode& node, Vec3 p) {
  const Vec3 a = node.Axis(0), b = node.Axis(1), c = node.Axis(2);
  const Vec3 bc = Cross(b, c), ca = Cross(c, a), ab = Cross(a, b);
  const double det = Dot(a, bc);
  const Vec3 d = p - node.Center();
  const double s[3] = {Dot(bc, d) / det, Dot(ca, d) / det, Dot(ab, d) / det};
  double reach = 0.0;
  for (int k = 0; k < 3; ++k) {
    reach = std::max(reach, node.half[k] > 0.0F ? std::fabs(s[k]) / node.half[k]
                                                : (std::fabs(s[k]) > 0.0 ? INFINITY : 0.0));
  }
  return reach;
}

struct Visit {
  uint32_t node;
  std::vector<uint32_t> ancestors;
};

// Calls leaf(node, ancestors) for every leaf, depth-first.
template <typename Leaf>
void ForEachLeaf(const TriangleBvh& bvh, Leaf&& leaf) {
  std::vector<Visit> stack{{0, {}}};
  while (!stack.empty()) {
    Visit visit = std::move(stack.back());
    stack.pop_back();
    const BvhNode& node = bvh.nodes[visit.node];
    if (node.count > 0) {
      leaf(node, visit.ancestors);
      continue;
    }
    visit.ancestors.push_back(visit.node);
    stack.push_back({node.first, visit.ancestors});
    stack.push_back({visit.node + 1, visit.ancestors});
  }
}

void ExpectBoundsHold(const Scene& scene, const std::string& what) {
  const TriangleBvh bvh = BuildTriangleBvh(scene);
  std::vector<int> seen(scene.triangles.size(), 0);
  ForEachLeaf(bvh, [&](const BvhNode& leaf, const std::vector<uint32_t>& ancestors) {
    for (uint32_t t = leaf.first; t < leaf.first + leaf.count; ++t) {
      ++seen[t];
      for (const uint32_t v : scene.triangles[t].vertices) {
        const Vec3 p = scene.verticesWorld[v];
        ASSERT_LE(Reach(leaf, p), 1.0) << what << ": triangle " << t << " outside its leaf";
        for (const uint32_t a : ancestors) {
          ASSERT_LE(Reach(bvh.nodes[a], p), 1.0)
              << what << ": triangle " << t << " outside node " << a;
        }
      }
      const FacePlane& plane = scene.facePlanesWorld[scene.TriangleFace(t)];
      if (Dot(plane.normal, plane.normal) == 0.0) continue;
      for (const uint32_t a : ancestors) {
        const BvhNode& node = bvh.nodes[a];
        if (!(node.coneCos > 0.0F) || node.coneCos == BvhNode::kAllDegenerate) continue;
        const Vec3 axis = node.Axis(2) * (1.0 / Length(node.Axis(2)));
        EXPECT_GE(Dot(plane.normal, axis), node.coneCos) << what << ": node " << a;
        const double height = Dot(plane.normal, node.Center()) - plane.offset;
        EXPECT_LE(height, node.heightMax) << what << ": node " << a;
        EXPECT_GE(height, node.heightMin) << what << ": node " << a;
      }
    }
  });
  for (size_t t = 0; t < seen.size(); ++t) {
    ASSERT_EQ(seen[t], 1) << what << ": triangle " << t << " in " << seen[t] << " leaves";
  }
}

TEST(TriangleBvh, EveryCornerAndNormalLiesInsideItsNodes) {
  for (const std::string& name : GeneratedSceneNames()) {
    ExpectBoundsHold(PrepareScene(*GenerateScene(name)), name);
  }
  ExpectBoundsHold(PrepareScene(GenerateTriangleSphere(20000)), "sphere 20k");
  Mesh huge =
      test::QuadMesh({{{{0, -1e12, -1e12}, {0, 1e12, -1e12}, {0, 1e12, 1e12}, {0, -1e12, 1e12}}}});
  ExpectBoundsHold(PrepareScene(huge), "huge quad");
}

// Walks the tree from `eye`, a verdict holding for its whole subtree, and
// checks kAway and kToward against every face; counts the verdicts.
void ExpectVerdictsHold(const Scene& scene, const TriangleBvh& bvh, Vec3 eye, int& away,
                        int& toward) {
  std::vector<std::pair<uint32_t, ClusterFacing>> stack{{0, ClusterFacing::kMixed}};
  while (!stack.empty()) {
    auto [index, above] = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh.nodes[index];
    const ClusterFacing facing = above != ClusterFacing::kMixed ? above : NodeFacing(node, eye);
    away += facing == ClusterFacing::kAway;
    toward += facing == ClusterFacing::kToward;
    if (node.count == 0) {
      stack.push_back({node.first, facing});
      stack.push_back({index + 1, facing});
      continue;
    }
    for (uint32_t t = node.first; t < node.first + node.count; ++t) {
      const bool front = scene.facePlanesWorld[scene.TriangleFace(t)].FacesPoint(eye);
      if (facing == ClusterFacing::kAway) {
        ASSERT_FALSE(front) << "triangle " << t << " node " << index;
      }
      if (facing == ClusterFacing::kToward) {
        ASSERT_TRUE(front) << "triangle " << t << " node " << index;
      }
    }
  }
}

// kAway and kToward hold for every face below the node, from eyes all around
// and close to the model, and from eyes on and just off nodes' cone axes
// (where |v|^2 - along^2 would cancel).
TEST(TriangleBvh, FacingVerdictsHoldForEveryFace) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(5000));
  const TriangleBvh bvh = BuildTriangleBvh(scene);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  int away = 0, toward = 0;
  for (int trial = 0; trial < 40; ++trial) {
    ExpectVerdictsHold(scene, bvh, {coordinate(random), coordinate(random), coordinate(random)},
                       away, toward);
  }
  int onAxis = 0;
  for (size_t index = 0; index < bvh.nodes.size() && onAxis < 60; index += 37) {
    const BvhNode& node = bvh.nodes[index];
    if (!(node.coneCos > 0.0F) || node.coneCos == BvhNode::kAllDegenerate) continue;
    ++onAxis;
    const Vec3 axis = node.Axis(2) * (1.0 / Length(node.Axis(2)));
    const Vec3 side =
        Normalized(Cross(axis, std::fabs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    for (const double distance : {0.01, 0.5, 3.0, 40.0}) {
      for (const double off : {0.0, 1e-8, 3e-4, 1e-2}) {
        const Vec3 eye = node.Center() + (axis + side * off) * distance;
        int nodeAway = 0, nodeToward = 0;
        ExpectVerdictsHold(scene, bvh, eye, nodeAway, nodeToward);
        toward += nodeToward;
      }
    }
  }
  EXPECT_GT(away, 0);  // the verdicts are not all "mixed"
  EXPECT_GT(toward, 0);
  EXPECT_GT(onAxis, 10);
}

// A hand-made node whose stored float axis is furthest from unit length, the
// eye about sqrt(2 |axis| - 2) from the axis, a face at the cone's edge on
// the far side just back-facing: no kToward (a review's case; with
// sqrt(|v|^2 - along^2) and the float axis as unit it was kToward).
TEST(TriangleBvh, FacingNearTheAxisOfAFloatConeIsNotTowardABackFace) {
  std::mt19937 random(1);
  std::normal_distribution<double> gauss;
  Vec3 stored{}, unit{};
  double delta = -1.0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 v = Normalized(Vec3{gauss(random), gauss(random), gauss(random)});
    const Vec3 f{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
    if (Length(f) - 1.0 > delta) {
      delta = Length(f) - 1.0;
      stored = f;
    }
  }
  unit = stored * (1.0 / Length(stored));
  const Vec3 u = Normalized(Cross(unit, std::fabs(unit.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  BvhNode node{};
  for (int k = 0; k < 3; ++k) node.half[k] = 0.001F;
  node.axes[2][0] = static_cast<float>(stored.x);
  node.axes[2][1] = static_cast<float>(stored.y);
  node.axes[2][2] = static_cast<float>(stored.z);
  node.coneCos = 0.5F;
  const double cone = std::acos(0.5);
  const double phi = std::sqrt(2.0 * delta);
  const Vec3 eye = (unit * std::cos(phi) + u * std::sin(phi)) * 10.0;
  const Vec3 normal = unit * std::cos(cone - 1e-7) - u * std::sin(cone - 1e-7);
  const FacePlane face{normal, Dot(normal, eye) + 0.002};  // eye 0.002 behind it
  node.heightMin = static_cast<float>(-face.offset);
  node.heightMax = node.heightMin;
  ASSERT_FALSE(face.FacesPoint(eye));
  EXPECT_NE(NodeFacing(node, eye), ClusterFacing::kToward) << "axis off unit by " << delta;
}

// Front ends build a hierarchy only for frames that would walk it: enough
// triangles a sample of the frame's grid, and a frame the walk serves.
TEST(HierarchyStage, WouldWalkOnlyFramesItServes) {
  const Scene sphere = PrepareScene(GenerateTriangleSphere(20000));
  RenderOptions ramp;
  ramp.method = Method::kAuto;
  ramp.threads = 2;
  EXPECT_TRUE(HierarchyStage::WouldWalk(sphere, 8, 4, ramp));  // 625 a sample: timed against
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 8, 4, ramp,   // render builds from 700
                                         HierarchyStage::kFasterFromTrianglesPerSample));
  EXPECT_TRUE(HierarchyStage::WouldWalk(sphere, 6, 4, ramp,  // 833 a sample
                                        HierarchyStage::kFasterFromTrianglesPerSample));
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 16, 8, ramp));   // 156 a sample
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 80, 24, ramp));  // 10 a sample
  RenderOptions other = ramp;
  other.method = Method::kPainter;
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 8, 4, other));
  other = ramp;
  other.cullBackFaces = false;
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 8, 4, other));
  other = ramp;
  other.variant.hierarchy = HierarchyUse::kNever;
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 8, 4, other));
  other = ramp;
  other.glyphs = GlyphMode::kAscii;  // 2x4 samples a cell: 78 a sample at 8x4
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 8, 4, other));
  EXPECT_TRUE(HierarchyStage::WouldWalk(sphere, 3, 1, other));  // 833 a sample, on threads
  other.threads = 1;  // the sampled rasterizer draws it, not the walk
  EXPECT_FALSE(HierarchyStage::WouldWalk(sphere, 3, 1, other));
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
  EXPECT_TRUE(BuildTriangleBvh(sphere, &cancel).Empty());
}

const std::vector<test::OrbitView> kViews{{0.3, 1.3, 1.0},  {2.1, 0.4, 1.0},  {4.0, 2.6, 2.5},
                                          {1.0, 1.5, 0.35}, {5.5, 1.0, 0.12}, {3.0, 0.05, 0.6}};

// Returns how many frames the walk drew.
int ExpectHierarchyFramesMatch(const std::string& name, const Scene& scene,
                               const std::vector<int>& sizes) {
  scene.hierarchy.Attach(Hierarchy(scene));
  int walked = 0;
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
              walked += actual.stats.byHierarchy ? 1 : 0;
            }
          }
        }
      }
    }
  }
  return walked;
}

TEST(HierarchyStage, SmallScenesMatchTheFaceLoop) {
  for (const std::string& name : GeneratedSceneNames()) {
    ExpectHierarchyFramesMatch(name, PrepareScene(*GenerateScene(name)), {80, 24, 37, 11});
  }
  const std::array<Vec3, 4> quad{{{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}};
  ExpectHierarchyFramesMatch("coplanar duplicates",
                             PrepareScene(test::QuadMesh({quad, quad, quad})), {80, 24});
  ExpectHierarchyFramesMatch("crossing quads",
                             PrepareScene(test::QuadMesh({
                                 {{{-1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, -1}}},
                                 {{{-1, -1, 1}, {-1, 1, 1}, {1, 1, -1}, {1, -1, -1}}},
                             })),
                             {80, 24});
  for (const double scale : {1e-9, 1e9}) {  // tiny and huge coordinates
    Mesh sphere = GenerateTriangleSphere(5000);
    for (Vec3& p : sphere.verticesFile) p = p * scale;
    ExpectHierarchyFramesMatch("sphere x" + std::to_string(scale), PrepareScene(sphere), {80, 24});
  }
  // A floor far larger than the view, reaching behind the eye (clipped: no walk), and a quad on it.
  ExpectHierarchyFramesMatch(
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
  ExpectHierarchyFramesMatch("nan and collinear", PrepareScene(nan), {80, 24});
}

// Where both passes may draw (kWhenFaster, enough triangles a sample) the
// renderer times them against each other: after a key's first frame (the
// prior's, uncounted) each pass draws two frames in turn, and every frame,
// whichever pass drew it, is the cluster pass's. Another frame size or
// another hierarchy (a new scene) starts the timing over.
TEST(HierarchyStage, MeasuredChoiceDrawsBothPassesWithTheSameFrames) {
  const Scene sphere = PrepareScene(GenerateTriangleSphere(60000));  // 468 a sample at 16x8
  RenderOptions clusters;
  clusters.method = Method::kAuto;
  clusters.threads = 2;
  clusters.threadsFromTriangles = 0;
  clusters.variant.hierarchy = HierarchyUse::kNever;
  RenderOptions measured = clusters;
  measured.variant.hierarchy = HierarchyUse::kWhenFaster;
  Renderer reference, chooser;
  int frame = 0;
  // The walked frames among the next five at width x height, each checked against the clusters'.
  auto walkedOfFive = [&](int width, int height) {
    int walked = 0;
    for (int k = 0; k < 5; ++k, ++frame) {
      const test::OrbitView view{0.2 * frame, 1.2, 1.0};
      const test::DrawnFrame expected =
          test::DrawOrbit(reference, sphere, view, width, height, clusters);
      const test::DrawnFrame actual =
          test::DrawOrbit(chooser, sphere, view, width, height, measured);
      test::ExpectSameFrame(expected, actual, "frame " + std::to_string(frame));
      walked += actual.stats.byHierarchy ? 1 : 0;
    }
    return walked;
  };
  sphere.hierarchy.Attach(Hierarchy(sphere));
  // Once timing has begun, five frames of one key walk 0 or 5 times, never 2.
  EXPECT_EQ(walkedOfFive(16, 8), 2)
      << "the prior (clusters) twice and uncounted once, the walk twice";
  EXPECT_EQ(walkedOfFive(15, 8), 2) << "another size starts over";
  sphere.hierarchy.Attach(Hierarchy(sphere));  // a new hierarchy, maybe at the old one's address
  EXPECT_EQ(walkedOfFive(15, 8), 2) << "another hierarchy starts over";
  for (int k = 0; k < 6; ++k) walkedOfFive(15, 8);  // the chosen pass and its probes
}

TEST(HierarchyStage, Sphere200kMatchesTheFaceLoopAndIsWalked) {
  const int walked = ExpectHierarchyFramesMatch(
      "sphere 200k", PrepareScene(GenerateTriangleSphere(200000)), {160, 48, 61, 7});
  EXPECT_GT(walked, 0);  // not only the views where the walk does not apply
}

}  // namespace
}  // namespace termshade
