#pragma once

#include <span>
#include <string>
#include <string_view>

namespace termshade {

/// One row of the viewer's key table.
struct ViewerKey {
  /// The keys as a person reads them: "arrows, h j k l".
  std::string_view keys;
  /// What they do, short enough for the `?` overlay.
  std::string_view does;
  /// Every printable ASCII character bound to this row (in ActionForChar),
  /// aliases included ("+=" for closer); named keys are in `keys` only.
  std::string_view chars;
};

/// The one key table: the `?` overlay, `termshade --help` and the man page
/// are all made from it. A test checks it against ActionForChar.
std::span<const ViewerKey> ViewerKeyTable();

/// The table as aligned text lines, "KEYS  does", keys padded to one column.
std::string FormatViewerKeys(std::string_view indent);

}  // namespace termshade
