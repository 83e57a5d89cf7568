#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "io/read/LoadError.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "shade/CellColour.h"

namespace termshade::test {

/// Absolute path of a file in the source tree.
std::string SourcePath(const std::string& relative);

/// Reads a whole file (empty string if it cannot be read).
std::string ReadFile(const std::string& path);

/// A folder of a test's own under the temporary folder (name plus the
/// process id), removed with its files at the end.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name);
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  ~ScratchFolder();
  /// Writes a file of these bytes in the folder; its path.
  std::string Write(const std::string& name, const std::string& bytes) const;

 private:
  std::string path_;
};

/// Loads a model from the source tree; fails the test on error (then an empty mesh).
Mesh LoadMesh(const std::string& relative);

/// Loads and prepares a model from the source tree; fails the test on error.
Scene LoadScene(const std::string& relative);

/// An entry of the 256-colour palette as a terminal colour.
TermColour IndexedColour(int index);

/// One four-cornered face per quad, each with its own vertices.
Mesh QuadMesh(const std::vector<std::array<Vec3, 4>>& quads);

/// The scene moved by shiftWorld, with what depends on the vertices (face
/// planes, clusters, radius) moved or rebuilt to match: a test's scene placed
/// off its bounding-box center.
Scene ShiftedScene(Scene scene, Vec3 shiftWorld);

/// A rendered frame with its camera.
struct Frame {
  Camera camera;
  CellBuffer cells;
  DepthBuffer depth;
  std::string Text() const;
};

/// The default 80x24 text frame of a mesh taken as z-up, for comparing two readings of one file.
std::string FrameText(Mesh mesh);

/// A reader's result as text: the mesh's vertices, faces, segments and edge
/// flags, or the error message, or "(importer)" for nullopt; equal texts, equal results.
std::string ReadResultText(std::optional<Loaded<Mesh>> read);

/// Renders a scene as `termshade render` would (default distance when rho <= 0).
Frame RenderFrame(const Scene& scene, double theta, double phi, int widthCells, int heightCells,
                  const RenderOptions& options, double rho = 0.0, double cellAspect = 2.0);

}  // namespace termshade::test
