// libFuzzer target: bytes as the import helper's answer (io/import/ImportWire.h),
// read the way termshade reads them from a helper that may be compromised:
// a progress frame or a result frame, within a byte limit. A mesh the reader
// accepts must keep the invariants MeshWireProblem names, and is drawn
// through the whole pipeline (FuzzPipeline.h) when its size is one the
// loader lets through (1e-30 to 1e30 model units).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "FuzzPipeline.h"
#include "io/import/ImportWire.h"

namespace {

bool DrawableSize(const termshade::Mesh& mesh) {
  double largest = 0.0;
  for (const termshade::Vec3& p : mesh.verticesFile) {
    for (const double c : {p.x, p.y, p.z}) {
      if (std::isfinite(c)) largest = std::max(largest, std::fabs(c));
    }
  }
  return largest <= 1e29 && (largest == 0.0 || largest >= 1e-29);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace termshade;
  size_t at = 0;
  WireReader reader(
      [&](void* to, size_t count) {
        if (count > size - at) return false;
        std::memcpy(to, data + at, count);
        at += count;
        return true;
      },
      uint64_t{1} << 20);
  // Frames as the parent reads them: progress, progress, ..., then a result.
  Loaded<Mesh> result = LoadError{"fuzz", 0, 0, "no result"};
  for (uint8_t kind = 0; reader.U8(kind);) {
    double share = 0.0;
    if (kind == static_cast<uint8_t>(ImportFrame::kProgress)) {
      if (!reader.F64(share)) return 0;
      continue;
    }
    if (kind != static_cast<uint8_t>(ImportFrame::kResult)) return 0;
    ModuleStatus status{};
    std::string text;
    if (!ReadResultFrame(reader, status, text, result)) return 0;
    break;
  }
  if (!result.Ok()) return DrawEveryMethod(result);
  const Mesh& mesh = result.Value();
  if (!MeshWireProblem(mesh).empty()) std::abort();  // the reader let a broken mesh through
  if (!DrawableSize(mesh)) return 0;
  return DrawEveryMethod(result);
}
