#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/Scene.h"

namespace termshade {

/// What the exact reference sees along the ray through one sample.
struct RaySample {
  uint32_t faceNumber = 0;        ///< 1-based nearest face, 0 = background
  double depth = 0.0;             ///< -z (eye) of the nearest hit, 0 for background
  double secondDepth = 0.0;       ///< -z of the next-nearest hit of another face, 0 if none
  uint32_t secondFaceNumber = 0;  ///< that face
};

/// The exact reference of SPEC 8: for a sample in cell coordinates, a
/// double-precision ray cast against the model's polygons (planes and point
/// in polygon; no triangulation, no rasterization, no fixed point).
class ReferenceRayCaster {
 public:
  ReferenceRayCaster(const Scene& scene, const Camera& camera, bool cullBackFaces);

  /// Sorts faces into the cells their outlines' bounding boxes touch, so a
  /// cast tests only the faces of its cell. Casts outside the grid test all.
  void BinFaces(int widthCells, int heightCells);

  RaySample Cast(double uCells, double vCells) const;

  /// Distance in cells from (u, v) to the nearest projected edge of a face
  /// (infinity if the face projects to nothing).
  double DistanceToFaceEdgeCells(uint32_t faceNumber, double uCells, double vCells) const;

  /// |d(1/z)/du| + |d(1/z)/dv| of a face's plane, per cell: how fast its w changes on screen.
  double WGradientPerCell(uint32_t faceNumber) const;

 private:
  struct FacePolygon {
    std::vector<Vec3> cornersEye;
    std::vector<double> projectedU;  ///< near-clipped outline in cells
    std::vector<double> projectedV;
    Vec3 normalEye;
    double planeOffset = 0.0;  ///< n . p = h in eye space
    int dropAxis = 2;          ///< coordinate dropped for the point-in-polygon test
    bool active = false;
  };

  bool HitFace(const FacePolygon& face, Vec3 rayEye, double& depth) const;

  Camera camera_;
  std::vector<FacePolygon> faces_;
  int binWidth_ = 0;
  int binHeight_ = 0;
  std::vector<uint32_t> binStarts_;  ///< per cell, into binFaces_
  std::vector<uint32_t> binFaces_;
};

}  // namespace termshade
