#include "edit_form.hpp"

#include "edgeland/kernel/errors.hpp"

namespace edgeland::detail {
namespace {

std::size_t changed_count(const MaterialMap& map) {
  std::size_t n = 0;
  for (std::size_t m = 0; m < kMaterialCount; ++m)
    n += map[static_cast<std::uint8_t>(m)] != Material(m) ? 1 : 0;
  return n;
}

}  // namespace

bool has_its_form(const Edit& e) {
  using Kind = Edit::Kind;
  const Material first = e.map[kEmpty];
  switch (e.kind) {
    case Kind::kCarve:
      return e.map == MaterialMap::uniform(kEmpty);
    case Kind::kFill:
      return e.map == MaterialMap::uniform(first);
    case Kind::kFillEmpty:
      return e.map == MaterialMap().set(kEmpty, first);
    case Kind::kReplace:
      return changed_count(e.map) <= 1;
    case Kind::kRelabel:
      return true;
  }
  return false;
}

std::pair<Material, Material> replaced(const MaterialMap& map) {
  for (std::size_t m = 0; m < kMaterialCount; ++m) {
    const Material from = static_cast<std::uint8_t>(m);
    if (map[from] != from) return {from, map[from]};
  }
  return {kEmpty, kEmpty};
}

}  // namespace edgeland::detail

namespace edgeland {

ValidSet edit_shape(PolygonSet shape) {
  for (std::size_t i = 0; i < shape.size(); ++i)
    for (std::size_t j = 0; j < shape[i].size(); ++j)
      if (!in_range(shape[i][j])) throw CoordinateOutOfRange(Operand::kClip, i, 0, j, shape[i][j]);
  return ValidSet(std::move(shape), Operand::kClip);
}

}  // namespace edgeland
