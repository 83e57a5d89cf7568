#pragma once

#include <cstddef>

namespace termshade {

/// Watches a read-only file mapping while it is read. When the file shrinks
/// under it, reading a page past the new end raises SIGBUS; inside a watched
/// range the process's SIGBUS handler maps a page of zeros there instead,
/// marks the range, and the read goes on (the reader's result is then
/// refused). Any other SIGBUS (another address, a sent signal, another
/// si_code than BUS_ADRERR) goes to the action there before: its handler,
/// ignored if it was ignored and sent, else the default action (the
/// process ends). The handler is (re)installed by each watch when something
/// else replaced it. Returns the watch's slot, or -1 when every slot is
/// taken or the handler cannot be installed (the caller reads instead).
int WatchMappedRange(const void* begin, size_t bytes);

/// Ends a watch; true when a page of the range had to be replaced by zeros.
bool StopWatchingMappedRange(int slot);

/// Whether a page of the watched range was replaced by zeros so far.
bool MappedRangeShrank(int slot);

}  // namespace termshade
