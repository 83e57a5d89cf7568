#include "geometry/RayCast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/FaceNormal.h"
#include "geometry/ViewingTransform.h"

namespace termshade {
namespace {

double Coordinate(Vec3 p, int axis) {
  return axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
}

// Crossing-number test in the plane that drops `dropAxis`.
bool PointInPolygon(const std::vector<Vec3>& corners, Vec3 p, int dropAxis) {
  const int a = (dropAxis + 1) % 3, b = (dropAxis + 2) % 3;
  const double pa = Coordinate(p, a), pb = Coordinate(p, b);
  bool inside = false;
  for (size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
    const double ia = Coordinate(corners[i], a), ib = Coordinate(corners[i], b);
    const double ja = Coordinate(corners[j], a), jb = Coordinate(corners[j], b);
    if ((ib > pb) != (jb > pb) && pa < (ja - ia) * (pb - ib) / (jb - ib) + ia) inside = !inside;
  }
  return inside;
}

double DistanceToSegment(double pu, double pv, double au, double av, double bu, double bv) {
  const double du = bu - au, dv = bv - av;
  const double lengthSquared = du * du + dv * dv;
  double t = lengthSquared > 0.0 ? ((pu - au) * du + (pv - av) * dv) / lengthSquared : 0.0;
  t = std::fmax(0.0, std::fmin(1.0, t));
  return std::hypot(pu - (au + t * du), pv - (av + t * dv));
}

}  // namespace

ReferenceRayCaster::ReferenceRayCaster(const Scene& scene, const Camera& camera, bool cullBackFaces)
    : camera_(camera) {
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  const Vec3 eyeWorld = EyePositionWorld(camera.view);
  const double nearZ = -1e-6 * (scene.diagonalModelUnits > 0.0 ? scene.diagonalModelUnits : 1.0);
  faces_.resize(scene.FaceCount());
  for (size_t f = 0; f < scene.FaceCount(); ++f) {
    FacePolygon& face = faces_[f];
    for (uint32_t v : scene.Face(f)) {
      face.cornersEye.push_back(TransformPoint(eyeFromWorld, scene.verticesWorld[v]));
    }
    const Vec3 nWorld = scene.facePlanesWorld[f].normal;
    const bool front = scene.facePlanesWorld[f].FacesPoint(eyeWorld);
    face.active = (front || !cullBackFaces) && nWorld != Vec3{} && IsFinite(nWorld);
    if (!face.active) continue;
    face.normalEye = TransformDirection(eyeFromWorld, nWorld);
    Vec3 mean;
    for (const Vec3& p : face.cornersEye) mean = mean + p;
    mean = mean * (1.0 / static_cast<double>(face.cornersEye.size()));
    face.planeOffset = Dot(face.normalEye, mean);
    const Vec3 n = face.normalEye;
    face.dropAxis = std::fabs(n.x) > std::fabs(n.y) ? (std::fabs(n.x) > std::fabs(n.z) ? 0 : 2)
                                                    : (std::fabs(n.y) > std::fabs(n.z) ? 1 : 2);
    // Outline in cells, clipped to the near plane (Sutherland-Hodgman, one plane).
    const size_t count = face.cornersEye.size();
    for (size_t i = 0; i < count; ++i) {
      const Vec3 a = face.cornersEye[i], b = face.cornersEye[(i + 1) % count];
      const bool aIn = a.z <= nearZ, bIn = b.z <= nearZ;
      auto emit = [&](Vec3 p) {
        const CellPoint c = ProjectToCell(camera.projection, p);
        face.projectedU.push_back(c.u);
        face.projectedV.push_back(c.v);
      };
      if (aIn) emit(a);
      if (aIn != bIn) emit(a + (b - a) * ((nearZ - a.z) / (b.z - a.z)));
    }
  }
}

bool ReferenceRayCaster::HitFace(const FacePolygon& face, Vec3 rayEye, double& depth) const {
  const double denominator = Dot(face.normalEye, rayEye);
  if (denominator == 0.0) return false;
  const double t = face.planeOffset / denominator;
  if (!(t > 0.0) || !std::isfinite(t)) return false;
  const Vec3 hit = rayEye * t;
  if (!PointInPolygon(face.cornersEye, hit, face.dropAxis)) return false;
  depth = -hit.z;
  return depth > 0.0;
}

void ReferenceRayCaster::BinFaces(int widthCells, int heightCells) {
  binWidth_ = widthCells;
  binHeight_ = heightCells;
  std::vector<std::vector<uint32_t>> bins(static_cast<size_t>(widthCells) * heightCells);
  for (size_t f = 0; f < faces_.size(); ++f) {
    const FacePolygon& face = faces_[f];
    if (!face.active || face.projectedU.empty()) continue;
    const auto [uLow, uHigh] = std::minmax_element(face.projectedU.begin(), face.projectedU.end());
    const auto [vLow, vHigh] = std::minmax_element(face.projectedV.begin(), face.projectedV.end());
    // One cell of slack: rays sit anywhere in their cell, outlines are straight.
    const int col0 = static_cast<int>(std::max(0.0, std::floor(*uLow) - 1));
    const int col1 = static_cast<int>(std::min(widthCells - 1.0, std::floor(*uHigh) + 1));
    const int row0 = static_cast<int>(std::max(0.0, std::floor(*vLow) - 1));
    const int row1 = static_cast<int>(std::min(heightCells - 1.0, std::floor(*vHigh) + 1));
    for (int row = row0; row <= row1; ++row) {
      for (int col = col0; col <= col1; ++col) {
        bins[static_cast<size_t>(row) * widthCells + col].push_back(static_cast<uint32_t>(f));
      }
    }
  }
  binStarts_.assign(1, 0);
  binFaces_.clear();
  for (const auto& bin : bins) {
    binFaces_.insert(binFaces_.end(), bin.begin(), bin.end());
    binStarts_.push_back(static_cast<uint32_t>(binFaces_.size()));
  }
}

RaySample ReferenceRayCaster::Cast(double uCells, double vCells) const {
  const Projection& p = camera_.projection;
  const Vec3 rayEye{uCells - p.cx, (p.cy - vCells) * p.cellAspect, -p.d};
  RaySample sample;
  double nearest = std::numeric_limits<double>::infinity();
  double second = nearest;
  // Step 1: the candidate faces: the cell's bin, or all of them.
  const uint32_t* candidates = nullptr;
  size_t candidateCount = faces_.size();
  const int col = static_cast<int>(std::floor(uCells)), row = static_cast<int>(std::floor(vCells));
  if (binWidth_ > 0 && col >= 0 && row >= 0 && col < binWidth_ && row < binHeight_) {
    const size_t bin = static_cast<size_t>(row) * binWidth_ + col;
    candidates = binFaces_.data() + binStarts_[bin];
    candidateCount = binStarts_[bin + 1] - binStarts_[bin];
  }
  // Step 2: the nearest two hits.
  for (size_t k = 0; k < candidateCount; ++k) {
    const size_t f = candidates != nullptr ? candidates[k] : k;
    double depth = 0.0;
    if (!faces_[f].active || !HitFace(faces_[f], rayEye, depth)) continue;
    const auto number = static_cast<uint32_t>(f + 1);
    if (depth < nearest) {
      second = nearest;
      sample.secondFaceNumber = sample.faceNumber;
      nearest = depth;
      sample.faceNumber = number;
    } else if (depth < second) {
      second = depth;
      sample.secondFaceNumber = number;
    }
  }
  sample.depth = sample.faceNumber != 0 ? nearest : 0.0;
  sample.secondDepth = sample.secondFaceNumber != 0 ? second : 0.0;
  return sample;
}

double ReferenceRayCaster::DistanceToFaceEdgeCells(uint32_t faceNumber, double uCells,
                                                   double vCells) const {
  double best = std::numeric_limits<double>::infinity();
  if (faceNumber == 0 || faceNumber > faces_.size()) return best;
  const FacePolygon& face = faces_[faceNumber - 1];
  const size_t count = face.projectedU.size();
  for (size_t i = 0; i < count; ++i) {
    const size_t j = (i + 1) % count;
    best = std::fmin(best, DistanceToSegment(uCells, vCells, face.projectedU[i], face.projectedV[i],
                                             face.projectedU[j], face.projectedV[j]));
  }
  return best;
}

double ReferenceRayCaster::WGradientPerCell(uint32_t faceNumber) const {
  if (faceNumber == 0 || faceNumber > faces_.size()) return 0.0;
  const FacePolygon& face = faces_[faceNumber - 1];
  const Projection& p = camera_.projection;
  // On the plane n . (t r) = h with r = (X, Y, -d): w = 1/(-z) = (n . r) / (d h),
  // linear in X and Y; u = cx + X and v = cy - Y / a.
  const double scale = 1.0 / (p.d * face.planeOffset);
  return std::fabs(face.normalEye.x * scale) + std::fabs(face.normalEye.y * scale * p.cellAspect);
}

}  // namespace termshade
