#include "io/read/BinaryStlReader.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <vector>

#include "geometry/FirstOccurrence.h"
#include "process/HugePages.h"
#include "process/LoadThreads.h"

namespace termshade {
namespace {

constexpr size_t kHeaderBytes = 80;
constexpr size_t kRecordBytes = 50;  // normal, 3 corners (12 floats), 2 attribute bytes
constexpr size_t kFirstRecord = kHeaderBytes + 4;
constexpr size_t kKeyBytes = 12;  // a corner's 3 floats

uint32_t TriangleCount(std::string_view bytes) {
  uint32_t count = 0;
  std::memcpy(&count, bytes.data() + kHeaderBytes, sizeof count);
  return count;
}

// A key's 12 bytes in a part's compact key array, by vertex number.
struct CompactKeyAt {
  const char* keys = nullptr;
  const char* operator()(size_t vertex) const { return keys + vertex * kKeyBytes; }
};

using KeyTable = FirstOccurrenceTable<kKeyBytes, CompactKeyAt>;

// One run of triangles welded on its own: its distinct positions (12-byte
// keys, first occurrence first) and a table of them; its corners' entries
// in faceCorners become numbers among them.
struct WeldPart {
  size_t firstTriangle = 0;
  size_t endTriangle = 0;
  std::unique_ptr<char[]> keys;  ///< room for every key it may get, `distinct` written
  uint32_t distinct = 0;
  std::optional<KeyTable> table;
  static constexpr size_t kChunkTriangles = 1024;
  std::unique_ptr<char[]> chunk_;  ///< the records being welded, copied out of the file

  // Room for up to `most` keys (address space: untouched until written).
  void Allocate(size_t most) {
    keys.reset(new char[most * kKeyBytes]);
    AdviseHugePages(keys.get(), most * kKeyBytes);
    // A closed surface has about one vertex for 6 corners: the table starts
    // there and grows if the file has more.
    table.emplace(most / 5, CompactKeyAt{keys.get()});
    chunk_.reset(new char[kChunkTriangles * kRecordBytes]);
  }
  const char* KeyAt(uint32_t vertex) const { return keys.get() + size_t{vertex} * kKeyBytes; }

  // The number of the key at `key` (12 bytes), a new one when it is new.
  uint32_t Insert(const char* key) { return InsertHashed(key, table->Hash(key)); }
  uint32_t InsertHashed(const char* key, uint64_t hash) {
    std::memcpy(keys.get() + size_t{distinct} * kKeyBytes, key, kKeyBytes);
    const uint32_t number = table->FindOrInsert(distinct, hash);
    if (number == distinct) ++distinct;
    return number;
  }

  // numbers[i] = Insert(keyAt(i)) for i < count, a batch at a time: hashes
  // first and the table slots they start at prefetched, then the keys those
  // slots hold, then the probes.
  template <typename KeyAtIndex>
  void InsertAll(size_t count, const KeyAtIndex& keyAt, uint32_t* numbers) {
    constexpr size_t kBatch = 32;
    uint64_t hashes[kBatch];
    for (size_t batch = 0; batch < count; batch += kBatch) {
      const size_t batchEnd = std::min(count, batch + kBatch);
      for (size_t i = batch; i < batchEnd; ++i) {
        hashes[i - batch] = table->Hash(keyAt(i));
        table->PrefetchSlot(hashes[i - batch]);
      }
      for (size_t i = batch; i < batchEnd; ++i) {
        const uint32_t held = table->HeldAt(hashes[i - batch]);
        if (held != KeyTable::kEmpty) __builtin_prefetch(KeyAt(held));
      }
      for (size_t i = batch; i < batchEnd; ++i) {
        numbers[i] = InsertHashed(keyAt(i), hashes[i - batch]);
      }
    }
  }

  // Numbers the part's corners (in place in corners), reading its records
  // in order a chunk at a time (copied out of the file once: FileBytes::
  // CopyOut for a mapped one), each chunk a batch at a time: hashes first
  // and the table slots they start at prefetched, then the keys those
  // slots hold, then the probes.
  void Weld(std::string_view bytes, uint32_t* corners, FileBytes* owned) {
    constexpr size_t kReleaseBytes = size_t{4} << 20;
    char* const chunk = chunk_.get();
    // Held bytes (not a mapping) are handed back as they are read.
    const bool releaseBehind = owned != nullptr && !owned->Mapped();
    size_t released = kFirstRecord + firstTriangle * kRecordBytes;
    for (size_t chunkFirst = firstTriangle; chunkFirst < endTriangle;
         chunkFirst += kChunkTriangles) {
      const size_t chunkTriangles = std::min(kChunkTriangles, endTriangle - chunkFirst);
      const size_t offset = kFirstRecord + chunkFirst * kRecordBytes;
      if (owned != nullptr) {
        owned->CopyOut(offset, chunkTriangles * kRecordBytes, chunk);
      } else {
        std::memcpy(chunk, bytes.data() + offset, chunkTriangles * kRecordBytes);
      }
      const auto keyAt = [chunk](size_t corner) {
        return chunk + (corner / 3) * kRecordBytes + 12 + (corner % 3) * 12;
      };
      InsertAll(3 * chunkTriangles, keyAt, corners + 3 * chunkFirst);
      const size_t readTo = offset + chunkTriangles * kRecordBytes;
      if (releaseBehind && readTo >= released + kReleaseBytes) {
        owned->Release(released, readTo);
        released = readTo;
      }
    }
  }

  // Frees the keys and the table, their pages handed back (HugePages.h).
  void Clear() {
    if (table) table->ReleasePages();
    table.reset();
    ReleasePages(keys.get(), size_t{distinct} * kKeyBytes);
    keys.reset();
    chunk_.reset();
  }
};

// The triangle count, read once, when the bytes have the layout it gives.
std::optional<uint32_t> LaidOutTriangleCount(std::string_view bytes) {
  if (bytes.size() < kFirstRecord) return std::nullopt;
  const uint32_t count = TriangleCount(bytes);
  if (kFirstRecord + uint64_t{count} * kRecordBytes != bytes.size()) return std::nullopt;
  return count;
}

LoadError NotBinaryStlError(const std::string& path) {
  return LoadError{path, 0, 0, "not a binary STL (size is not 84 + 50 x triangle count)"};
}

// ReadBinaryStlInParts with the triangle count its layout was checked with.
Loaded<Mesh> ReadLaidOut(std::string_view bytes, const std::string& path, size_t triangles,
                         size_t partCount, FileBytes* owned) {
  if (triangles == 0) return LoadError{path, 0, 0, "the file holds no triangles"};
  if (triangles >= UINT32_MAX / 3)
    return LoadError{path, 0, 0, "more triangles than 32-bit indices hold"};

  // Step 1: the corners in parts, one a load thread, each welded on its own
  // (its distinct positions in first-occurrence order); the parts' records
  // are handed back as they are read.
  const size_t cornerCount = triangles * 3;
  Mesh mesh;
  mesh.name = path;
  ResizeFaultedIn(mesh.faceCorners, cornerCount);
  partCount = std::clamp<size_t>(partCount, 1, triangles);
  std::vector<WeldPart> parts(partCount);
  for (size_t p = 0; p < partCount; ++p) {
    parts[p].firstTriangle = triangles * p / partCount;
    parts[p].endTriangle = triangles * (p + 1) / partCount;
    // Part 0's keys take every part's new positions in step 2.
    parts[p].Allocate(p == 0 ? cornerCount : 3 * (parts[p].endTriangle - parts[p].firstTriangle));
  }
  std::atomic<bool> outOfMemory{false};
  RunOnLoadThreads(static_cast<int>(partCount), [&](int p) {
    try {
      parts[static_cast<size_t>(p)].Weld(bytes, mesh.faceCorners.data(), owned);
    } catch (const std::bad_alloc&) {
      outOfMemory = true;
    }
  });
  if (outOfMemory) throw std::bad_alloc();

  // Step 2: each later part's new positions numbered after those before
  // (part 0's table and keys grow to hold them all): the numbering of
  // meshopt_generateVertexRemap, first occurrence first.
  WeldPart& first = parts[0];
  std::vector<uint32_t> globalOf;
  for (size_t p = 1; p < partCount; ++p) {
    const WeldPart& part = parts[p];
    globalOf.resize(part.distinct);
    first.InsertAll(
        part.distinct, [&part](size_t local) { return part.KeyAt(static_cast<uint32_t>(local)); },
        globalOf.data());
    // The part's corners renumbered, split over the load threads.
    uint32_t* corners = mesh.faceCorners.data() + 3 * part.firstTriangle;
    const size_t count = 3 * (part.endTriangle - part.firstTriangle);
    RunRangesOnLoadThreads(LoadThreadCount(count), count, [&](int, size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) corners[i] = globalOf[corners[i]];
    });
    parts[p].Clear();
  }
  if (owned != nullptr) owned->Free();
  FreeAndReleasePages(globalOf);
  ResizeFaultedIn(mesh.verticesFile, first.distinct);
  for (uint32_t v = 0; v < first.distinct; ++v) {
    float xyz[3];
    std::memcpy(xyz, first.KeyAt(v), sizeof xyz);
    mesh.verticesFile[v] = {xyz[0], xyz[1], xyz[2]};
  }
  first.Clear();

  // Step 3: one face per triangle in file order.
  ResizeFaultedIn(mesh.faceStarts, triangles + 1);
  ResizeFaultedIn(mesh.edgeHidden, mesh.faceCorners.size());  // zeros: no edge hidden
  RunRangesOnLoadThreads(LoadThreadCount(triangles + 1), triangles + 1,
                         [&mesh](int, size_t begin, size_t end) {
                           for (size_t t = begin; t < end; ++t) {
                             mesh.faceStarts[t] = static_cast<uint32_t>(t * 3);
                           }
                         });
  return mesh;
}

}  // namespace

bool IsBinaryStlLayout(std::string_view bytes) {
  return LaidOutTriangleCount(bytes).has_value();
}

std::optional<LoadError> MisSizedBinaryStl(std::string_view bytes, const std::string& path) {
  if (IsBinaryStlLayout(bytes)) return std::nullopt;
  const size_t text = bytes.find_first_not_of(" \t\r\n\f\v");
  if (text != std::string_view::npos && bytes.substr(text, 5) == "solid") return std::nullopt;
  if (bytes.size() < kFirstRecord) {
    return LoadError{path, 0, 0,
                     "not an ASCII STL (no 'solid') and too short for a binary one: " +
                         std::to_string(bytes.size()) + " bytes, its header alone takes " +
                         std::to_string(kFirstRecord)};
  }
  const uint32_t count = TriangleCount(bytes);
  const uint64_t expected = kFirstRecord + uint64_t{count} * kRecordBytes;
  return LoadError{
      path, 0, 0,
      "binary STL header counts " + std::to_string(count) + " triangles, so 84 + 50 x " +
          std::to_string(count) + " = " + std::to_string(expected) + " bytes, but the file has " +
          std::to_string(bytes.size()) +
          (bytes.size() < expected ? " (cut short?)" : " (bytes after the last triangle)")};
}

bool BinaryStlHasColours(std::string_view bytes) {
  return bytes.substr(0, kHeaderBytes).find("COLOR=") != std::string_view::npos;
}

Loaded<Mesh> ReadBinaryStl(std::string_view bytes, const std::string& path, FileBytes* owned) {
  const std::optional<uint32_t> triangles = LaidOutTriangleCount(bytes);
  if (!triangles) return NotBinaryStlError(path);
  const auto parts = static_cast<size_t>(LoadThreadCount(3 * size_t{*triangles}));
  return ReadLaidOut(bytes, path, *triangles, parts, owned);
}

Loaded<Mesh> ReadBinaryStlInParts(std::string_view bytes, const std::string& path, size_t partCount,
                                  FileBytes* owned) {
  const std::optional<uint32_t> triangles = LaidOutTriangleCount(bytes);
  if (!triangles) return NotBinaryStlError(path);
  return ReadLaidOut(bytes, path, *triangles, partCount, owned);
}

}  // namespace termshade
