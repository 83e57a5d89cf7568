#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "geometry/Mat4.h"

namespace termshade {

/// The file-space axis that points up in a model (SPEC 10).
enum class UpAxis : uint8_t { kPlusX, kMinusX, kPlusY, kMinusY, kPlusZ, kMinusZ };

/// Parses `x y z -x -y -z` (also `+x`...); nullopt for anything else.
std::optional<UpAxis> ParseUpAxis(std::string_view text);

/// `+x`, `-x`, ... as shown on the status line and accepted by ParseUpAxis.
std::string_view UpAxisName(UpAxis axis);

/// The next axis in the viewer's cycle: +z, +y, +x, -z, -y, -x, then +z again.
UpAxis NextUpAxis(UpAxis axis);

/// The exact signed axis permutation that turns `axis` into +z (a proper rotation).
Mat4 ZUpFromFile(UpAxis axis);

/// The same turn applied to a point: components copied with their signs, so exact.
Vec3 ZUpFromFile(UpAxis axis, Vec3 pFile);
/// Its inverse, as exact.
Vec3 FileFromZUp(UpAxis axis, Vec3 pZUp);

}  // namespace termshade
