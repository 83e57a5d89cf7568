// The frame loop allocates nothing once its buffers have grown, and the
// optional structures stay within their memory estimates: every operator new
// in this test binary is counted, with its bytes (its own executable, so the
// replacement touches no other test).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "geometry/FitCamera.h"
#include "geometry/LevelOfDetail.h"
#include "geometry/RayBvh.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/Renderer.h"

namespace {
// The counters a replaced operator new needs.
std::atomic<long> gAllocations{0};  // NOLINT
std::atomic<long> gLiveBytes{0};    // NOLINT
std::atomic<long> gPeakBytes{0};    // NOLINT

// Each block carries its size in front (16 bytes keep malloc's alignment).
constexpr std::size_t kHeaderBytes = 16;

void CountLive(long bytes) {
  const long live = gLiveBytes.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  long peak = gPeakBytes.load(std::memory_order_relaxed);
  while (live > peak && !gPeakBytes.compare_exchange_weak(peak, live)) {
  }
}
}  // namespace

void* operator new(std::size_t size) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (auto* block = static_cast<std::size_t*>(std::malloc(size + kHeaderBytes))) {
    *block = size;
    CountLive(static_cast<long>(size));
    return reinterpret_cast<char*>(block) + kHeaderBytes;
  }
  throw std::bad_alloc();
}
// The replacement new above takes memory from malloc, so free is its match;
// GCC cannot see that through the replacement and warns.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  auto* block = reinterpret_cast<std::size_t*>(static_cast<char*>(p) - kHeaderBytes);
  CountLive(-static_cast<long>(*block));
  std::free(block);
}
void operator delete(void* p, std::size_t) noexcept {
  operator delete(p);
}
#pragma GCC diagnostic pop

namespace termshade {
namespace {

TEST(FrameLoop, TheCounterSeesAllocations) {
  const long before = gAllocations.load();
  std::vector<int> grown(100);
  EXPECT_GT(gAllocations.load(), before);
}

TEST(FrameLoop, AllocatesNothingAfterTheFirstFrames) {
  const Scene scene = PrepareScene(*GenerateScene("sphere_cone"));
  for (Method method :
       {Method::kZBuffer, Method::kPainter, Method::kCull, Method::kWire, Method::kAuto}) {
    for (GlyphMode glyphs : {GlyphMode::kRamp, GlyphMode::kAscii, GlyphMode::kQuadrants,
                             GlyphMode::kSextants, GlyphMode::kBraille}) {
      RenderOptions options;
      options.method = method;
      options.glyphs = glyphs;
      options.twoColour = glyphs == GlyphMode::kQuadrants;
      Renderer renderer;
      CellBuffer cells(160, 48);
      DepthBuffer depth;
      depth.Resize(160, 48);
      ViewParams view = DefaultView(scene.diagonalModelUnits);
      auto frame = [&] {
        view.theta += 0.37;
        const Camera camera = FitCamera(scene, view, 160, 48, 2.0);
        renderer.Render(scene, camera, options, depth, cells);
      };
      for (int i = 0; i < 20; ++i) frame();  // buffers grow to what any view needs
      const long before = gAllocations.load();
      for (int i = 0; i < 50; ++i) frame();
      EXPECT_EQ(gAllocations.load() - before, 0)
          << MethodName(method) << " with glyphs " << GlyphModeName(glyphs);
    }
  }
}

// The most bytes alive at once while `build` runs, above those alive before it.
template <typename Build>
long PeakBytesOf(Build&& build) {
  const long before = gLiveBytes.load();
  gPeakBytes.store(before);
  build();
  return gPeakBytes.load() - before;
}

// The budget checks (io/load/ExtrasBudget.h) trust these estimates: each
// must cover what its build allocates, and not by more than three times over
// (they also cover resident memory, which huge pages and two build threads
// raise above the allocations: docs/load-and-memory.md).
TEST(ExtrasMemory, LevelsOfDetailStayWithinTheirEstimate) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(400000));
  DetailLevels levels;
  const long peak = PeakBytesOf([&] { levels = BuildDetailLevels(scene); });
  ASSERT_FALSE(levels.levels.empty());
  const auto estimate = static_cast<long>(EstimateDetailBuildBytes(scene));
  EXPECT_LE(peak, estimate);
  EXPECT_GE(3 * peak, estimate);
}

TEST(ExtrasMemory, RayHierarchyStaysWithinItsEstimate) {
  const Scene scene = PrepareScene(GenerateTriangleSphere(400000));
  RayBvh bvh;
  const long peak = PeakBytesOf([&] { bvh = BuildRayBvh(scene, nullptr, 1); });
  ASSERT_FALSE(bvh.nodes.empty());
  const auto estimate = static_cast<long>(EstimateRayBvhBytes(scene));
  EXPECT_LE(peak, estimate);
  EXPECT_GE(3 * peak, estimate);
}

}  // namespace
}  // namespace termshade
