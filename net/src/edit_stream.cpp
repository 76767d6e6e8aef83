#include "edgeland/net/edit_stream.hpp"

#include "edgeland/kernel/shapes.hpp"

namespace edgeland::net {

Edit EditStream::next() {
  const auto r = static_cast<std::int64_t>(8 + random() % 33);
  const auto at = [&](std::int64_t lo, std::int64_t hi) {
    return lo + r +
           static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(hi - lo - 2 * r));
  };
  const std::int64_t x = at(box_.min.x, box_.max.x), y = at(box_.min.y, box_.max.y);
  ValidSet shape(PolygonSet{circle({x, y}, r)});
  switch (random() % 3) {
    case 0:
      return Edit::carve(std::move(shape));
    case 1:
      return Edit::fill(std::move(shape), static_cast<std::uint8_t>(1 + random() % 3));
    default:
      return Edit::fill_empty(std::move(shape), 4);
  }
}

}  // namespace edgeland::net
