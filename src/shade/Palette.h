#pragma once

namespace termshade {

/// The textbook look in the xterm 256-colour palette: faces in shades of
/// yellow on a light blue background. Fixed indices, no palette changes.
constexpr int kBackground256 = 153;

/// The 256-colour index for shade level `level` of `levelCount` (dark to bright).
int FaceColour256(int level, int levelCount);

}  // namespace termshade
