#include "io/load/ModelLoader.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <new>
#include <optional>
#include <string_view>

#include "geometry/FaceNormal.h"
#include "geometry/SceneTextures.h"
#include "io/import/AssimpModule.h"
#include "io/import/IsolatedImport.h"
#include "io/import/OpenGexGuard.h"
#include "io/import/Quick3dGuard.h"
#include "io/load/FileBytesLoader.h"
#include "io/read/ContentSniff.h"
#include "io/read/DatReader.h"
#include "io/read/FileBytes.h"
#include "io/read/LoadBudget.h"
#include "io/read/OwnReaders.h"
#include "io/read/PlyReader.h"
#include "io/read/RegularFile.h"
#include "process/HeapPolicy.h"

namespace termshade {
namespace {

// Formats that are ZIP archives inside, so a ZIP signature is no reason to refuse them.
bool IsZipBasedFormat(const std::string& format) {
  return format == "3mf" || format == "zae" || format == "pk3" || format == "zip" ||
         format == "amf" || format == "ifczip";
}

std::string ToUpper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string Normalized(std::string format) {
  if (!format.empty() && format.front() == '.') format.erase(0, 1);
  std::transform(format.begin(), format.end(), format.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return format;
}

size_t LargestFaceCorners(const Mesh& mesh) {
  size_t largest = 0;
  for (size_t face = 0; face < mesh.FaceCount(); ++face) {
    largest = std::max(largest, mesh.Face(face).size());
  }
  return largest;
}

// Where a model was read from, and what its references may reach.
struct ModelPlace {
  std::string displayName;  ///< as the user gave it
  std::string folder;       ///< canonical; empty for standard input
  std::string canonical;    ///< the model's canonical path; empty for standard input
};

Loaded<Mesh> LoadDat(std::string_view bytes, const ModelPlace& place, const LoadOptions& options) {
  const auto needed = static_cast<double>(EstimateImportBytes("dat", bytes.size()));
  if (needed > static_cast<double>(options.memoryBudgetBytes)) {
    return LoadError{place.displayName, 0, 0, OverBudgetMessage(needed, options.memoryBudgetBytes)};
  }
  Loaded<Mesh> mesh = ParseDat(bytes, place.displayName, options.cancel, options.progress);
  if (mesh.Ok()) mesh.Value().upAxisFile = UpAxis::kPlusZ;
  return mesh;
}

// A mapped file that shrank while it was read gave zeros for its lost
// pages, one that changed otherwise a mix of old and new bytes: whatever
// was read from it is refused.
std::optional<LoadError> ChangedError(const FileBytes& bytes, const std::string& name) {
  if (bytes.Shrank()) return LoadError{name, 0, 0, kFilePagesLostMessage};
  if (bytes.ChangedSinceOpened()) return LoadError{name, 0, 0, kFileChangedMessage};
  return std::nullopt;
}

Loaded<Mesh> LoadImported(FileBytes bytes, const std::string& format, const ModelPlace& place,
                          const LoadOptions& options) {
  const auto fail = [&](std::string message) {
    return LoadError{place.displayName, 0, 0, std::move(message)};
  };
  // Counts in the header against the bytes that follow it (under another
  // name, the message says which format the content was read as). For the
  // importer, OFF under any name: when the importer its name picks refuses
  // the content, Assimp tries them all on it (libFuzzer: an OFF header
  // promising 9e8 vertices, named .glb, asked for 14 GB).
  const auto headerProblem = [&](std::string_view read,
                                 bool offUnderAnyName) -> std::optional<std::string> {
    const auto as = [&](const char* checked, std::optional<std::string> problem) {
      if (problem && format != checked)
        *problem = "content read as " + ToUpper(checked) + ": " + *problem;
      return problem;
    };
    if (format == "off" || format.empty() || offUnderAnyName) {
      if (auto problem = as("off", CheckHeaderCounts("off", read))) return problem;
    }
    return as("ply", CheckHeaderCounts("ply", read));
  };
  // Step 1: the header's counts, for our readers.
  if (auto problem = headerProblem(bytes.View(), false)) return fail(std::move(*problem));
  const auto overBudget = [&](size_t needed) { return needed > options.memoryBudgetBytes; };
  // Step 2: a dedicated reader where one takes the file, within its own
  // estimate, then the mesh's real size (file still held) against the budget.
  const auto ownNeeds = EstimateOwnReaderBytes(format, bytes.Size());
  if (!options.importerOnly && ownNeeds) {
    if (overBudget(*ownNeeds)) return fail(OverBudgetMessage(*ownNeeds, options.memoryBudgetBytes));
    // The reader frees the file's bytes once it has read them.
    const size_t fileBytes = bytes.Size();
    constexpr size_t kBigFileBytes = size_t{16} << 20;
    if (fileBytes >= kBigFileBytes) AdviseHugePagesForLoad(*ownNeeds);
    if (auto mesh = ReadWithOwnReader(bytes.View(), format, place.displayName,
                                      options.memoryBudgetBytes, &bytes)) {
      if (auto changed = ChangedError(bytes, place.displayName)) return *changed;
      if (!mesh->Ok()) return std::move(*mesh);
      const Mesh& read = mesh->Value();
      const size_t needed =
          std::max(*ownNeeds, EstimatePreparedBytes(fileBytes, read.verticesFile.size(),
                                                    read.faceCorners.size(), read.FaceCount(),
                                                    LargestFaceCorners(read)));
      if (overBudget(needed)) return fail(OverBudgetMessage(needed, options.memoryBudgetBytes));
      mesh->Value().reader = "termshade " + ToUpper(format) + " reader";
      return std::move(*mesh);
    }
  }
  // Step 3: the import's memory against the budget.
  const size_t importNeeds = EstimateImportBytes(format, bytes.Size());
  if (overBudget(importNeeds))
    return fail(OverBudgetMessage(importNeeds, options.memoryBudgetBytes));
  // Step 4: the import, under a name with the format's extension (Assimp picks
  // its importer by it; without one, it sniffs the content).
  ImportSource source;
  source.displayName = place.displayName;
  source.folder = place.folder;
  source.format = format;
  if (!place.canonical.empty() && LowerExtension(place.canonical) == format) {
    source.importName = place.canonical;
  } else {
    const std::string base = place.canonical.empty() ? "/standard-input" : place.canonical;
    source.importName = format.empty() ? base : base + "." + format;
  }
  // The importer reads a copy: a mapped file may have changed since step 1,
  // so the header's counts are checked again on the bytes it gets.
  std::string text = bytes.TakeString();
  if (auto changed = ChangedError(bytes, place.displayName)) return *changed;
  if (auto problem = headerProblem(text, true)) return fail(std::move(*problem));
  if (auto problem = CheckPlyHeaderForImporter(text, place.displayName)) {
    if (format != "ply") problem->message = "content read as PLY: " + problem->message;
    return *problem;
  }
  if (auto problem = CheckOpenGexStructure(text, format)) return fail(std::move(*problem));
  if (auto problem = CheckQuick3dCounts(text)) return fail(std::move(*problem));
  Loaded<Mesh> imported = options.importInProcess
                              ? ImportWithAssimp(source, std::move(text), options)
                              : ImportWithAssimpIsolated(source, std::move(text), options);
  if (imported.Ok()) {
    imported.Value().reader =
        std::string(options.importInProcess ? "Assimp (in process)" : "Assimp (import helper)") +
        (format.empty() ? ", format found by its content" : ", as " + format);
  }
  return imported;
}

// A .dat read from a mapping is checked for a changed file after the parse.
Loaded<Mesh> LoadDatBytes(const FileBytes& bytes, const ModelPlace& place,
                          const LoadOptions& options) {
  Loaded<Mesh> mesh = LoadDat(bytes.View(), place, options);
  if (auto changed = ChangedError(bytes, place.displayName)) return *changed;
  if (mesh.Ok()) mesh.Value().reader = "termshade .dat reader";
  return mesh;
}

Loaded<Mesh> LoadBytes(FileBytes bytes, const ModelPlace& place, const LoadOptions& options) {
  // Step 1: the format: the hint, the extension, else the content.
  std::string format = Normalized(options.formatHint);
  if (format.empty()) format = LowerExtension(place.displayName);
  if (format == "dat") return LoadDatBytes(bytes, place, options);
  const bool known = AssimpKnowsExtension(format);
  if (bytes.Size() == 0) return LoadError{place.displayName, 0, 0, "the file is empty"};
  if (const auto what = RecognisedNonModel(bytes.View())) {
    if (!(IsZipBasedFormat(format) && what->find("ZIP") != std::string::npos)) {
      return LoadError{place.displayName, 0, 0, "not a model file (looks like " + *what + ")"};
    }
  }
  if (!known && LooksLikeDat(bytes.View())) return LoadDatBytes(bytes, place, options);
  return LoadImported(std::move(bytes), known ? format : "", place, options);
}

// The float stages of the renderer keep about 1e-30 to 1e30 model units
// exact; a model whose size lies outside would draw blank or broken, so it is
// refused with its size instead.
Loaded<Mesh> WithDrawableSize(Loaded<Mesh> mesh) {
  if (!mesh.Ok()) return mesh;
  constexpr double kSmallest = 1e-30, kLargest = 1e30;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Vec3& p : mesh.Value().verticesFile) {
    const double xyz[3] = {p.x, p.y, p.z};
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(xyz[axis])) continue;
      lo[axis] = std::min(lo[axis], xyz[axis]);
      hi[axis] = std::max(hi[axis], xyz[axis]);
    }
  }
  double size = 0.0, largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (hi[axis] < lo[axis]) continue;
    size = std::max(size, hi[axis] - lo[axis]);
    largest = std::max({largest, std::fabs(lo[axis]), std::fabs(hi[axis])});
  }
  if (size > kLargest || largest > kLargest || (size > 0.0 && size < kSmallest)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "the model's size (%.3g model units, coordinates up to %.3g) is outside what "
                  "can be drawn (1e-30 to 1e30)",
                  size, largest);
    return LoadError{mesh.Value().name, 0, 0, text};
  }
  return mesh;
}

// A model all of whose faces have no area (corners in a line or a point) and
// no lines would draw a blank frame with no word why: refused instead.
Loaded<Mesh> WithAFaceToDraw(Loaded<Mesh> mesh) {
  if (!mesh.Ok()) return mesh;
  const Mesh& m = mesh.Value();
  if (!m.segments.empty()) return mesh;
  for (size_t face = 0; face < m.FaceCount(); ++face) {
    const std::span<const uint32_t> corners = m.Face(face);
    const Vec3 normal =
        NewellNormal(corners.size(), [&](size_t i) { return m.verticesFile[corners[i]]; });
    if (normal.x != 0.0 || normal.y != 0.0 || normal.z != 0.0) return mesh;
  }
  const std::string faces = m.FaceCount() == 1
                                ? "its one face has"
                                : "all " + std::to_string(m.FaceCount()) + " of its faces have";
  return LoadError{m.name, 0, 0,
                   faces + " no area (corners on a line or at a point): nothing to draw"};
}

// Whatever read it (a .dat, our readers, the import), the mesh's
// preparation and first frame against the budget, with its real counts and
// its largest face, before PrepareScene allocates anything.
Loaded<Mesh> WithinPreparedBudget(Loaded<Mesh> mesh, const LoadOptions& options) {
  if (!mesh.Ok()) return mesh;
  const Mesh& m = mesh.Value();
  const size_t needed = EstimatePreparedBytes(0, m.verticesFile.size(), m.faceCorners.size(),
                                              m.FaceCount(), LargestFaceCorners(m)) +
                        SceneTextureBytes(m);
  if (needed <= options.memoryBudgetBytes) return mesh;
  return LoadError{m.name, 0, 0,
                   OverBudgetMessage(static_cast<double>(needed), options.memoryBudgetBytes)};
}

// What every load returns: a mesh the renderer can draw within the budget, or why not.
Loaded<Mesh> Drawable(Loaded<Mesh> mesh, const LoadOptions& options) {
  return WithinPreparedBudget(WithAFaceToDraw(WithDrawableSize(std::move(mesh))), options);
}

Loaded<Mesh> LoadFileBytes(FileBytes bytes, const std::string& path, const LoadOptions& options);

Loaded<Mesh> LoadChecked(const std::string& path, const LoadOptions& options) {
  // Standard input: bounded by the budget, never a terminal.
  if (path == "-") {
    if (isatty(STDIN_FILENO) != 0) {
      return LoadError{"-", 0, 0, "standard input is a terminal; pipe a model into it"};
    }
    Loaded<std::string> bytes = ReadStream(
        STDIN_FILENO, "-", LargestLoadableBytes(options.memoryBudgetBytes), options.cancel);
    if (!bytes.Ok()) return bytes.Error();
    return LoadBytes(FileBytes(std::move(bytes.Value())), ModelPlace{"-", "", ""}, options);
  }
  // A file: regular only, no larger than the budget lets the smallest import be.
  const auto refuseSize = [&](size_t size) -> std::optional<std::string> {
    const auto needed = static_cast<double>(EstimateLeastLoadBytes(size));
    if (needed <= static_cast<double>(options.memoryBudgetBytes)) return std::nullopt;
    return "the file is " + FormatBytes(static_cast<double>(size)) + "; " +
           OverBudgetMessage(needed, options.memoryBudgetBytes);
  };
  Loaded<FileBytes> bytes = FileBytes::MapRegularFile(path, refuseSize, options.cancel);
  if (!bytes.Ok()) return bytes.Error();
  return LoadFileBytes(std::move(bytes.Value()), path, options);
}

Loaded<Mesh> LoadFileBytes(FileBytes bytes, const std::string& path, const LoadOptions& options) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::canonical(path, error);
  if (error) return LoadError{path, 0, 0, "cannot resolve the path: " + error.message()};
  return LoadBytes(std::move(bytes),
                   ModelPlace{path, canonical.parent_path().string(), canonical.string()}, options);
}

}  // namespace

bool UsesImporter(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext != "dat" && AssimpKnowsExtension(ext);
}

Loaded<Mesh> LoadModelBytes(std::string bytes, const std::string& name,
                            const LoadOptions& options) {
  try {
    return Drawable(LoadBytes(FileBytes(std::move(bytes)), ModelPlace{name, "", ""}, options),
                    options);
  } catch (const std::bad_alloc&) {
    return LoadError{name, 0, 0, "ran out of memory while loading"};
  } catch (const std::exception& e) {
    return LoadError{name, 0, 0, std::string("cannot import: ") + e.what()};
  }
}

Loaded<Mesh> LoadModelFileBytes(FileBytes bytes, const std::string& path,
                                const LoadOptions& options) {
  try {
    return Drawable(LoadFileBytes(std::move(bytes), path, options), options);
  } catch (const std::bad_alloc&) {
    return LoadError{path, 0, 0, "ran out of memory while loading"};
  } catch (const std::exception& e) {
    return LoadError{path, 0, 0, std::string("cannot import: ") + e.what()};
  }
}

Loaded<Mesh> LoadModelFile(const std::string& path, const LoadOptions& options) {
  try {
    return Drawable(LoadChecked(path, options), options);
  } catch (const std::bad_alloc&) {
    return LoadError{path, 0, 0,
                     "ran out of memory while loading (the memory budget is " +
                         FormatBytes(static_cast<double>(options.memoryBudgetBytes)) + ")"};
  } catch (const std::exception& e) {
    return LoadError{path, 0, 0, std::string("cannot import: ") + e.what()};
  }
}

}  // namespace termshade
