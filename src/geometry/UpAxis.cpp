#include "geometry/UpAxis.h"

#include <array>

namespace termshade {
namespace {

struct AxisInfo {
  UpAxis axis;
  std::string_view name;
};

constexpr std::array<AxisInfo, 6> kAxes = {{{UpAxis::kPlusX, "+x"},
                                            {UpAxis::kMinusX, "-x"},
                                            {UpAxis::kPlusY, "+y"},
                                            {UpAxis::kMinusY, "-y"},
                                            {UpAxis::kPlusZ, "+z"},
                                            {UpAxis::kMinusZ, "-z"}}};

// Rows of the turn: zUp component i = sign[i] * file component source[i].
// ±y turn about x and ±x about y (the other horizontal axis stays), -z is a
// half turn about x; every one has determinant +1.
struct Permutation {
  std::array<int, 3> source;
  std::array<double, 3> sign;
};

Permutation PermutationFor(UpAxis axis) {
  switch (axis) {
    case UpAxis::kPlusX:
      return {{2, 1, 0}, {-1.0, 1.0, 1.0}};  // (x, y, z) -> (-z, y, x)
    case UpAxis::kMinusX:
      return {{2, 1, 0}, {1.0, 1.0, -1.0}};  // (x, y, z) -> (z, y, -x)
    case UpAxis::kPlusY:
      return {{0, 2, 1}, {1.0, -1.0, 1.0}};  // (x, y, z) -> (x, -z, y)
    case UpAxis::kMinusY:
      return {{0, 2, 1}, {1.0, 1.0, -1.0}};  // (x, y, z) -> (x, z, -y)
    case UpAxis::kPlusZ:
      break;
    case UpAxis::kMinusZ:
      return {{0, 1, 2}, {1.0, -1.0, -1.0}};  // (x, y, z) -> (x, -y, -z)
  }
  return {{0, 1, 2}, {1.0, 1.0, 1.0}};
}

double Component(Vec3 p, int index) {
  return index == 0 ? p.x : (index == 1 ? p.y : p.z);
}

// Exact: a component is copied or its sign flipped, never multiplied or summed.
double Signed(double sign, double value) {
  return sign < 0.0 ? -value : value;
}

}  // namespace

std::optional<UpAxis> ParseUpAxis(std::string_view text) {
  if (text.size() == 1) {
    for (const AxisInfo& info : kAxes) {
      if (info.name[0] == '+' && info.name[1] == text[0]) return info.axis;
    }
    return std::nullopt;
  }
  for (const AxisInfo& info : kAxes) {
    if (info.name == text) return info.axis;
  }
  return std::nullopt;
}

std::string_view UpAxisName(UpAxis axis) {
  for (const AxisInfo& info : kAxes) {
    if (info.axis == axis) return info.name;
  }
  return "+z";
}

UpAxis NextUpAxis(UpAxis axis) {
  static constexpr std::array<UpAxis, 6> kCycle = {UpAxis::kPlusZ,  UpAxis::kPlusY,
                                                   UpAxis::kPlusX,  UpAxis::kMinusZ,
                                                   UpAxis::kMinusY, UpAxis::kMinusX};
  for (size_t i = 0; i < kCycle.size(); ++i) {
    if (kCycle[i] == axis) return kCycle[(i + 1) % kCycle.size()];
  }
  return UpAxis::kPlusZ;
}

Mat4 ZUpFromFile(UpAxis axis) {
  const Permutation turn = PermutationFor(axis);
  Mat4 zUpFromFile = Mat4::Identity();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      zUpFromFile.At(row, col) =
          col == turn.source[static_cast<size_t>(row)] ? turn.sign[static_cast<size_t>(row)] : 0.0;
    }
  }
  return zUpFromFile;
}

Vec3 ZUpFromFile(UpAxis axis, Vec3 pFile) {
  const Permutation turn = PermutationFor(axis);
  return {Signed(turn.sign[0], Component(pFile, turn.source[0])),
          Signed(turn.sign[1], Component(pFile, turn.source[1])),
          Signed(turn.sign[2], Component(pFile, turn.source[2]))};
}

Vec3 FileFromZUp(UpAxis axis, Vec3 pZUp) {
  const Permutation turn = PermutationFor(axis);
  std::array<double, 3> file{};
  for (size_t i = 0; i < 3; ++i) {
    file[static_cast<size_t>(turn.source[i])] =
        Signed(turn.sign[i], Component(pZUp, static_cast<int>(i)));
  }
  return {file[0], file[1], file[2]};
}

}  // namespace termshade
