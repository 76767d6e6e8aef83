#include "edgeland/net/edit_policy.hpp"

#include <algorithm>

namespace edgeland::net {

RateLimiter::RateLimiter(std::uint32_t per_second, std::uint32_t burst, Clock::time_point now)
    : per_second_(per_second),
      capacity_(std::uint64_t{burst} * 1000),
      milli_tokens_(capacity_),
      last_(now) {}

// A token is 1000 milli-tokens; a millisecond brings per_second of them.
bool RateLimiter::take(Clock::time_point now) {
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now - last_).count();
  if (ms > 0) {
    milli_tokens_ =
        std::min(capacity_, milli_tokens_ + static_cast<std::uint64_t>(ms) * per_second_);
    last_ = now;
  }
  if (milli_tokens_ < 1000) return false;
  milli_tokens_ -= 1000;
  return true;
}

bool FloodCounter::add(Clock::time_point now) {
  times_.push_back(now);
  while (!times_.empty() && now - times_.front() > std::chrono::seconds(10)) times_.pop_front();
  return times_.size() > limit_;
}

}  // namespace edgeland::net
