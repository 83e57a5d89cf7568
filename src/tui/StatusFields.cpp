#include "tui/StatusFields.h"

#include <cstdio>

#include "tui/StatusLine.h"

namespace termshade {

std::string CompactCount(size_t count) {
  char text[32];
  if (count < 100000) {
    std::snprintf(text, sizeof text, "%zu", count);
  } else if (count < 1000000) {
    std::snprintf(text, sizeof text, "%.1fk", static_cast<double>(count) / 1e3);
  } else {
    std::snprintf(text, sizeof text, "%.1fM", static_cast<double>(count) / 1e6);
  }
  return text;
}

std::string ComposeViewerStatus(const StatusFields& fields, int widthCells) {
  constexpr int kLeadMinCells = 32;  // a long path keeps its tail: file name and [i/n]
  // Priorities: lower numbers are kept longest.
  enum : int {
    kLead,
    kHelp,
    kGlyphs,
    kColour,
    kDetail,
    kView,
    kMethod,
    kUp,
    kFaces,
    kTriangles,
    kMs,
    kVertices
  };
  StatusSegment lead{fields.lead, kLead, false, Elision::kMiddle};
  if (fields.leadIsModel) {
    lead.elision = Elision::kFront;
    lead.minWidthCells = kLeadMinCells;
  }
  char faces[64], triangles[48], vertices[48], ms[32];
  std::snprintf(faces, sizeof faces, "%s/%s faces",
                CompactCount(static_cast<size_t>(fields.facesVisible)).c_str(),
                CompactCount(fields.faces).c_str());
  std::snprintf(triangles, sizeof triangles, "%s tris",
                CompactCount(static_cast<size_t>(fields.trianglesDrawn)).c_str());
  std::snprintf(vertices, sizeof vertices, "%s verts", CompactCount(fields.vertices).c_str());
  std::snprintf(ms, sizeof ms, "%.2f ms", fields.frameMs);
  std::vector<StatusSegment> segments{lead,
                                      {fields.method, kMethod, false},
                                      {faces, kFaces, false},
                                      {triangles, kTriangles, false},
                                      {vertices, kVertices, false},
                                      {fields.view, kView, true},
                                      {ms, kMs, true},
                                      {"? help", kHelp, true}};
  if (!fields.upAxis.empty()) {
    segments.insert(segments.begin() + 2, {"up " + fields.upAxis, kUp, false});
  }
  if (!fields.detail.empty())
    segments.insert(segments.begin() + 1, {fields.detail, kDetail, false});
  if (!fields.colour.empty())
    segments.insert(segments.begin() + 1, {fields.colour, kColour, false});
  if (!fields.glyphs.empty())
    segments.insert(segments.begin() + 1, {fields.glyphs, kGlyphs, false});
  return ComposeStatusLine(std::move(segments), widthCells);
}

}  // namespace termshade
