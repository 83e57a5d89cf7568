// Issue 9: the threaded, cluster-culled frame is bit for bit the frame of the
// plain face-by-face loop on one thread (faces, glyphs, depth, triangles
// drawn), on the shipped scenes, hard cases and a 200k sphere, at several
// sizes, views and thread counts; cluster culling on equals off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/Clusters.h"
#include "geometry/FitCamera.h"
#include "geometry/ViewingTransform.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/Renderer.h"
#include "support/FrameCompare.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

const std::vector<test::OrbitView> kViews{
    {0.3, 1.3, 1.0}, {2.1, 0.4, 1.0}, {4.0, 2.6, 1.0}, {1.0, 1.5, 0.35}, {5.5, 1.0, 0.12}};

struct NamedScene {
  std::string name;
  Scene scene;
};

std::vector<NamedScene> SmallScenes() {
  std::vector<NamedScene> scenes;
  for (const std::string& name : GeneratedSceneNames()) {
    scenes.push_back({name, PrepareScene(*GenerateScene(name))});
  }
  const std::array<Vec3, 4> quad{{{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}};
  scenes.push_back({"coplanar duplicates", PrepareScene(test::QuadMesh({quad, quad, quad}))});
  scenes.push_back({"crossing quads", PrepareScene(test::QuadMesh({
                                          {{{-1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, -1}}},
                                          {{{-1, -1, 1}, {-1, 1, 1}, {1, 1, -1}, {1, -1, -1}}},
                                      }))});
  scenes.push_back(
      {"plates gap 1e-4", PrepareScene(test::QuadMesh({
                              {{{0, -2, -2}, {0, 2, -2}, {0, 2, 2}, {0, -2, 2}}},
                              {{{1e-4, -1, -1}, {1e-4, 1, -1}, {1e-4, 1, 1}, {1e-4, -1, 1}}},
                          }))});
  Mesh nan = test::QuadMesh({quad});
  nan.verticesFile.push_back({NAN, 0, 0});
  nan.AddFace(std::array<uint32_t, 3>{0, 1, 4});
  nan.AddFace(std::array<uint32_t, 3>{0, 0, 1});  // collinear
  scenes.push_back({"nan and collinear", PrepareScene(nan)});
  scenes.push_back({"sphere 20k", PrepareScene(GenerateSphere(100, 100))});
  return scenes;
}

RenderOptions Options(Method method, int threads, bool clusters, bool culling) {
  RenderOptions options;
  options.method = method;
  options.threads = threads;
  options.threadsFromTriangles = 0;  // small scenes too: every band and run path
  options.variant.clusters = clusters;
  options.variant.clusterCulling = culling;
  return options;
}

void ExpectEveryThreadCountMatches(const NamedScene& named, const std::vector<int>& sizes) {
  for (size_t s = 0; s + 1 < sizes.size(); s += 2) {
    const int width = sizes[s], height = sizes[s + 1];
    for (const Method method : {Method::kZBuffer, Method::kCull}) {
      for (const test::OrbitView& view : kViews) {
        Renderer reference;
        const test::DrawnFrame expected = test::DrawOrbit(reference, named.scene, view, width,
                                                          height, Options(method, 1, false, false));
        for (const int threads : {1, 2, 3, 7}) {
          for (const bool culling : {true, false}) {
            Renderer renderer;
            const std::string what =
                named.name + " " + std::to_string(width) + "x" + std::to_string(height) + " " +
                std::string(MethodName(method)) + " theta " + std::to_string(view.theta) +
                " threads " + std::to_string(threads) + (culling ? " culled" : " all");
            // Twice with the same renderer: the second frame reuses its bins and threads.
            for (int repeat = 0; repeat < 2; ++repeat) {
              test::ExpectSameFrame(expected,
                                    test::DrawOrbit(renderer, named.scene, view, width, height,
                                                    Options(method, threads, true, culling)),
                                    what);
            }
          }
        }
      }
    }
  }
}

TEST(ThreadedFrame, SmallScenesMatchTheSingleThreadFaceLoop) {
  for (const NamedScene& named : SmallScenes()) {
    ExpectEveryThreadCountMatches(named, {80, 24, 37, 11, 160, 48});
  }
}

TEST(ThreadedFrame, Sphere200kMatchesTheSingleThreadFaceLoop) {
  const NamedScene sphere{"sphere 200k", PrepareScene(GenerateTriangleSphere(200000))};
  ExpectEveryThreadCountMatches(sphere, {160, 48, 61, 7});
}

TEST(ThreadedFrame, DefaultThresholdStillMatches) {
  // The product's options: every core, one thread below the threshold.
  const Scene sphere = PrepareScene(GenerateTriangleSphere(50000));
  for (const test::OrbitView& view : kViews) {
    Renderer reference, renderer;
    RenderOptions plain;
    plain.variant.clusters = false;
    test::ExpectSameFrame(test::DrawOrbit(reference, sphere, view, 120, 40, plain),
                          test::DrawOrbit(renderer, sphere, view, 120, 40, RenderOptions{}),
                          "default options");
  }
}

TEST(ThreadedFrame, SupersampledAndVariantsMatch) {
  const Scene scene = PrepareScene(*GenerateScene("sphere_cone"));
  for (const auto change :
       {+[](RenderOptions& o) {
          o.variant.samples = {2, 2};
        },
        +[](RenderOptions& o) { o.variant.depthFormat = DepthFormat::kLinearZ; },
        +[](RenderOptions& o) { o.variant.scanline = true; },
        +[](RenderOptions& o) { o.variant.floatGeometry = true; },
        +[](RenderOptions& o) { o.keepDepth = false; }}) {
    RenderOptions plain = Options(Method::kZBuffer, 1, false, false);
    RenderOptions threaded = Options(Method::kZBuffer, 3, true, true);
    change(plain);
    change(threaded);
    for (const test::OrbitView& view : kViews) {
      Renderer reference, renderer;
      const test::DrawnFrame expected = test::DrawOrbit(reference, scene, view, 80, 24, plain);
      const test::DrawnFrame actual = test::DrawOrbit(renderer, scene, view, 80, 24, threaded);
      ASSERT_EQ(expected.cells.FaceNumbers(), actual.cells.FaceNumbers());
      ASSERT_EQ(expected.cells.Glyphs(), actual.cells.Glyphs());
    }
  }
}

// The cluster tests themselves: culling must skip most of a sphere's back
// half (or the equality above would hold vacuously) and never a front face.
TEST(Clusters, ConeTestIsConservativeAndSkipsTheBackHalf) {
  const Scene sphere = PrepareScene(GenerateTriangleSphere(200000));
  ASSERT_FALSE(sphere.clusters.clusters.empty());
  for (const test::OrbitView& view : kViews) {
    ViewParams params = DefaultView(sphere.diagonalModelUnits);
    params.theta = view.theta;
    params.phi = view.phi;
    params.rho *= view.rhoScale;
    const Vec3 eye = EyePositionWorld(params);
    size_t away = 0;
    for (const SceneCluster& cluster : sphere.clusters.clusters) {
      const ClusterFacing facing = FacingOf(cluster, eye);
      for (uint32_t t = cluster.firstTriangle; t < cluster.triangleEnd; ++t) {
        const bool front = sphere.facePlanesWorld[sphere.TriangleFace(t)].FacesPoint(eye);
        if (facing == ClusterFacing::kAway) {
          ASSERT_FALSE(front) << "triangle " << t;
        }
        if (facing == ClusterFacing::kToward) {
          ASSERT_TRUE(front) << "triangle " << t;
        }
      }
      away += facing == ClusterFacing::kAway ? 1 : 0;
    }
    EXPECT_GT(away, sphere.clusters.clusters.size() / 4) << "theta " << view.theta;
  }
}

// sphere_cone's clusters are fitted on one thread, the 300k sphere's split
// over the load threads (where there are cores): each range of clusters must
// still cover its triangles once, in order, and bound them.
TEST(Clusters, CoverEveryTriangleOnceInOrder) {
  for (const Scene& scene : {PrepareScene(*GenerateScene("sphere_cone")),
                             PrepareScene(GenerateTriangleSphere(300000))}) {
    uint32_t next = 0;
    for (const SceneCluster& cluster : scene.clusters.clusters) {
      ASSERT_EQ(cluster.firstTriangle, next);
      ASSERT_GT(cluster.triangleEnd, cluster.firstTriangle);
      ASSERT_LE(cluster.triangleEnd - cluster.firstTriangle, SceneClusters::kMaxTriangles);
      for (uint32_t t = cluster.firstTriangle; t < cluster.triangleEnd; ++t) {
        for (const uint32_t v : scene.triangles[t].vertices) {
          ASSERT_LE(Length(scene.verticesWorld[v] - cluster.centerWorld), cluster.radius);
        }
      }
      next = cluster.triangleEnd;
    }
    EXPECT_EQ(next, scene.triangles.size());
  }
}

}  // namespace
}  // namespace termshade
