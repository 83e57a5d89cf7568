// libFuzzer target: any bytes through the .dat reader, and whatever it
// accepts through the whole pipeline (hostile geometry: NaN-free but huge,
// tiny, degenerate, self-intersecting) at a few views and sizes.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "FuzzPipeline.h"
#include "io/read/DatReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace termshade;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Loaded<Mesh> mesh = ParseDat(text, "fuzz.dat");
  return DrawEveryMethod(mesh);
}
