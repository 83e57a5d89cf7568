// libFuzzer target: any bytes through the model loader's Assimp path (our
// confined IOSystem, header-count checks, budget, content sniffing) as OBJ,
// PLY, STL, OFF, glTF, GLB, COLLADA or unnamed content (the first byte picks),
// and whatever loads through the whole pipeline (FuzzPipeline.h).
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzPipeline.h"
#include "io/load/ModelLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace termshade;
  if (size == 0) return 0;
  static constexpr const char* kNames[] = {"fuzz.obj",  "fuzz.ply", "fuzz.stl", "fuzz.off",
                                           "fuzz.gltf", "fuzz.glb", "fuzz.dae", "fuzz"};
  const char* name = kNames[data[0] % (sizeof kNames / sizeof kNames[0])];
  LoadOptions options;
  options.memoryBudgetBytes = size_t{256} << 20;  // within libFuzzer's -rss_limit_mb
  options.importInProcess = true;  // the importer in this process, where coverage sees it
  Loaded<Mesh> mesh =
      LoadModelBytes(std::string(reinterpret_cast<const char*>(data) + 1, size - 1), name, options);
  return DrawEveryMethod(mesh);
}
