#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/Mesh.h"
#include "io/import/AssimpModuleInterface.h"
#include "io/read/LoadError.h"

namespace termshade {

// The import helper's wire format (termshade-import, io/import/IsolatedImport.h): a
// request on the helper's standard input, frames from it on fd 3. Native
// byte order: both ends come from one build (the request carries its stamp).

/// The first bytes of a request (the last is the format's version).
inline constexpr std::string_view kImportRequestMagic{"TSIMPRQ3", 8};

/// One import for the helper.
struct ImportRequest {
  std::string stamp;  ///< the sender's build stamp (ModuleBuildStamp)
  ImportSource source;
  uint64_t memoryBudgetBytes = 0;
  std::string bytes;  ///< the model file's content
};

/// A frame's first byte.
enum class ImportFrame : uint8_t {
  kProgress = 'P',  ///< a double in [0, 1]
  kResult = 'R',    ///< the status, its exception text, then an error or a mesh
};

/// Writes the wire to a sink that takes `size` bytes from `from`, or returns false.
using WireSink = std::function<bool(const void* from, size_t size)>;

/// Writes a request, all but its bytes (which follow it as they are).
bool WriteRequestHead(const ImportRequest& request, const WireSink& sink);

/// Writes a progress frame.
bool WriteProgressFrame(double share, const WireSink& sink);

/// Writes a result frame (a mesh's arrays straight from the mesh).
bool WriteResultFrame(ModuleStatus status, const std::string& exceptionText,
                      const Loaded<Mesh>& result, const WireSink& sink);

/// Reads the wire from a source that fills exactly `size` bytes at `to`, or
/// returns false (at the end of its input, or when it gave up). Every count
/// is checked against `byteLimit` (the bytes the reader may still take)
/// before anything is allocated for it.
class WireReader {
 public:
  using Source = std::function<bool(void* to, size_t size)>;
  WireReader(Source source, uint64_t byteLimit)
      : source_(std::move(source)), bytesLeft_(byteLimit) {}

  bool Bytes(void* to, size_t size);
  bool U8(uint8_t& value) { return Bytes(&value, 1); }
  bool U32(uint32_t& value) { return Bytes(&value, sizeof value); }
  bool U64(uint64_t& value) { return Bytes(&value, sizeof value); }
  bool F64(double& value) { return Bytes(&value, sizeof value); }
  /// A string of at most maxBytes.
  bool String(std::string& value, uint64_t maxBytes);
  /// A count, then that many trivially copyable elements; the array grows
  /// as its bytes arrive (a count alone commits no memory).
  template <typename T>
  bool Array(std::vector<T>& values) {
    uint64_t count = 0;
    if (!U64(count) || count > bytesLeft_ / sizeof(T))
      return Refuse("an array longer than allowed");
    constexpr size_t kChunkElements = (size_t{16} << 20) / sizeof(T);
    values.clear();
    while (values.size() < count) {
      const size_t have = values.size();
      values.resize(have + std::min<size_t>(kChunkElements, static_cast<size_t>(count) - have));
      if (!Bytes(values.data() + have, (values.size() - have) * sizeof(T))) return false;
    }
    return true;
  }

  /// Why the last read failed, when the wire itself was wrong (empty when the source stopped).
  const std::string& Problem() const { return problem_; }
  bool Refuse(std::string why) {
    problem_ = std::move(why);
    return false;
  }

 private:
  Source source_;
  uint64_t bytesLeft_;
  std::string problem_;
};

/// Reads a request (the magic first). The request's bytes take the rest.
bool ReadRequest(WireReader& reader, ImportRequest& request);

/// Reads a result frame after its first byte: the status, the exception
/// text and the mesh or error, the mesh checked whole (MeshWireProblem).
bool ReadResultFrame(WireReader& reader, ModuleStatus& status, std::string& exceptionText,
                     Loaded<Mesh>& result);

/// Why a mesh from the wire could not be one the importer made (no face, a
/// face of fewer than 3 corners, indices past the vertices, face starts out
/// of order, arrays of the wrong length); empty when sound.
std::string MeshWireProblem(const Mesh& mesh);

}  // namespace termshade
