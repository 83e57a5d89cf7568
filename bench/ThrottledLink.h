#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// A link's rate and one-way delay, as `--link 256kbit:50ms` gives them.
struct LinkSpec {
  double bytesPerSecond = 0.0;  ///< 0: no limit
  double delaySeconds = 0.0;    ///< each way
};

/// "RATE:DELAY": RATE a number with kbit or mbit (bits a second, 1000-based),
/// DELAY a number with ms; nullopt when it is not one.
std::optional<LinkSpec> ParseLinkSpec(std::string_view text);

/// One direction of a slow link: bytes leave in order at the link's rate and
/// arrive its delay later. The queue before the link is the sender's to
/// bound (QueuedBytes): sshd's send buffer held about a megabyte.
class ThrottledLink {
 public:
  explicit ThrottledLink(LinkSpec spec) : spec_(spec) {}
  /// Bytes handed to the link at `now` (seconds).
  void Push(double now, std::string_view bytes);
  /// The bytes that have arrived by `now`, in order.
  std::string TakeArrived(double now);
  /// When the next bytes arrive; a huge value when none are on their way.
  double NextArrival() const;
  bool Empty() const { return pieces_.empty(); }
  /// Bytes pushed that have not arrived yet.
  size_t QueuedBytes() const { return queuedBytes_; }

 private:
  struct Piece {
    double arrival = 0.0;
    std::string bytes;
  };
  LinkSpec spec_;
  std::deque<Piece> pieces_;
  double freeAt_ = 0.0;  ///< when the link has sent what it was given
  size_t queuedBytes_ = 0;
};

}  // namespace termshade
