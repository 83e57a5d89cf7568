#pragma once

#include <cstddef>
#include <string>

namespace termshade {

/// What the viewer's status line tells, as values (no terminal code).
struct StatusFields {
  std::string lead;         ///< a message, or the model's label; sanitized
  bool leadIsModel = true;  ///< a model label keeps its tail (file name, [i/n])
  std::string view;         ///< "theta .. phi .. rho .."
  std::string method;       ///< "zbuffer contrast"
  std::string glyphs;       ///< the glyph mode, "sextants"; empty: not shown
  std::string colour;       ///< the colour mode, "truecolor", "16", "mono"; empty: not shown
  std::string upAxis;       ///< "+z"; empty: not shown
  std::string detail;       ///< the level of detail drawn, "lod 2/4 30.8k"; empty: exact
  size_t vertices = 0;
  size_t faces = 0;
  int facesVisible = 0;
  int trianglesDrawn = 0;
  double frameMs = 0.0;
};

/// The status line in widthCells. Left: the lead, glyph mode, colour mode, level of detail, method,
/// up axis, faces, triangles, vertices; right: the view, ms per frame and
/// "? help". When space is short the least useful go first: vertices, ms,
/// triangles, faces, up axis, method, view, level of detail, colour mode, glyph mode; the model's
/// file name and "? help" stay.
std::string ComposeViewerStatus(const StatusFields& fields, int widthCells);

/// A count in at most 6 characters: 950, 12345, 123.4k, 2.1M.
std::string CompactCount(size_t count);

}  // namespace termshade
