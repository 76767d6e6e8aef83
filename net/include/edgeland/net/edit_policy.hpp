#pragma once
// What the server accepts from a client (net/README.md, "Messages"): message sizes, a rate of
// edits, a limit on rejected messages before a disconnect, and the box a client may edit in.
// Integer arithmetic on milliseconds, so the same messages meet the same decisions anywhere.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"

namespace edgeland::net {

struct EditPolicy {
  std::size_t max_message = 64 * 1024;  // bytes of one EDIT message (kTooLarge beyond)
  std::size_t max_packet = 1 << 20;     // ENet refuses any packet larger than this
  std::uint32_t edits_per_second = 20;  // a client's sustained rate (kRate beyond)
  std::uint32_t burst = 40;             // edits it may send at once
  std::uint32_t flood_limit = 200;      // rejected messages within ten seconds: disconnect
  // Repair requests (HASHES, PATCH_REQUEST): a rate of their own, so repairing never costs an
  // edit, and paths per request (a repair round asks about the children of the nodes that
  // differ: 4096 paths is 1,024 differing nodes at one level).
  std::uint32_t repairs_per_second = 20;
  std::uint32_t repair_burst = 40;
  std::size_t max_repair_paths = 4096;
};

using Clock = std::chrono::steady_clock;

// A token bucket: `burst` tokens, refilled at `per_second`.
class EDGELAND_EXPORT RateLimiter {
 public:
  RateLimiter(std::uint32_t per_second, std::uint32_t burst, Clock::time_point now);
  // Takes a token if there is one.
  bool take(Clock::time_point now);

 private:
  std::uint64_t per_second_, capacity_, milli_tokens_;
  Clock::time_point last_;
};

// Rejected messages in the last ten seconds.
class EDGELAND_EXPORT FloodCounter {
 public:
  explicit FloodCounter(std::uint32_t limit) : limit_(limit) {}
  // Counts one; true when the client is now over the limit.
  bool add(Clock::time_point now);

 private:
  std::uint32_t limit_;
  std::deque<Clock::time_point> times_;
};

// Whether a shape whose bounding box is `shape` lies in the box granted to a client.
inline bool permitted(const Box64& granted, const Box64& shape) {
  return granted.min.x <= shape.min.x && granted.min.y <= shape.min.y &&
         shape.max.x <= granted.max.x && shape.max.y <= granted.max.y;
}

}  // namespace edgeland::net
