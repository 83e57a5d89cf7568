#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "io/read/LoadError.h"

namespace termshade {

/// Reads a whole regular file into memory. Anything else (a FIFO, device,
/// socket or folder) is refused without blocking: the file is opened with
/// O_NONBLOCK and checked with fstat before any read. refuseSize sees the
/// size before anything is allocated and may refuse it with a message.
/// cancel (may be null) is polled between reads.
Loaded<std::string> ReadRegularFile(
    const std::string& path, const std::function<std::optional<std::string>(size_t)>& refuseSize,
    const std::atomic<bool>* cancel = nullptr);

/// Reads an already open descriptor (standard input) to its end, refusing more
/// than maxBytes; name is used in messages.
Loaded<std::string> ReadStream(int fd, const std::string& name, size_t maxBytes,
                               const std::atomic<bool>* cancel = nullptr);

/// "12.3 MiB": a byte count for messages.
std::string FormatBytes(double bytes);

}  // namespace termshade
