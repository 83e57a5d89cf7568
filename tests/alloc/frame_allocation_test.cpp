// The frame loop allocates nothing once its buffers have grown: every
// operator new in this test binary is counted (its own executable, so the
// replacement touches no other test).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "geometry/FitCamera.h"
#include "io/scenes/SceneGenerators.h"
#include "raster/Renderer.h"

namespace {
std::atomic<long> gAllocations{0};  // NOLINT: the counter a replaced operator new needs
}

void* operator new(std::size_t size) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// The replacement new above takes memory from malloc, so free is its match;
// GCC cannot see that through the replacement and warns.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
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

}  // namespace
}  // namespace termshade
