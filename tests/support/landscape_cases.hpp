#pragma once
// Random landscapes for property tests: a world box, a configuration (quadtree or kd-tree, caps,
// sometimes a grid) and a few random edits (carve, fill, fill_empty, replace of random shapes),
// shared by the landscape's and the game layer's properties.
#include <rapidcheck.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "generators.hpp"
#include "landscape_oracle.hpp"

namespace edgeland::test {

struct LandscapeCase {
  Box64 world;
  Material fill = kEmpty;
  LandscapeConfig config;
  std::vector<LandscapeEdit> edits;
};

inline void showValue(const LandscapeCase& c, std::ostream& os) {
  os << "world " << c.world.min.x << ' ' << c.world.min.y << ' ' << c.world.max.x << ' '
     << c.world.max.y << ' ' << int(c.fill.value()) << "\n  config: tree " << int(c.config.tree)
     << " cap " << c.config.edge_cap << " merge " << c.config.merge_below << " min "
     << c.config.min_cell_size << " grid " << c.config.grid_depth;
  for (const LandscapeEdit& e : c.edits) os << "\n  " << describe(e);
}

inline rc::Gen<LandscapeEdit> edit_in(const Box64& w) {
  return rc::gen::exec([w] {
    const std::int64_t size = w.max.x - w.min.x;
    const std::int64_t r =
        *rc::gen::element<std::int64_t>(3, 8, 20, std::max<std::int64_t>(4, size / 4));
    const Point64 c{*gen::coord(w.min.x - r / 2, w.max.x + r / 2),
                    *gen::coord(w.min.y - r / 2, w.max.y + r / 2)};
    LandscapeEdit e;
    e.shape = *rc::gen::weightedOneOf<PolygonSet>(
        {{5, rc::gen::map(gen::shape(c, r), [](Polygon p) { return PolygonSet{std::move(p)}; })},
         {1, gen::polygon_set(c, r)}});
    e.kind = *rc::gen::element(LandscapeEdit::Kind::kCarve, LandscapeEdit::Kind::kFill,
                               LandscapeEdit::Kind::kFillEmpty, LandscapeEdit::Kind::kReplace);
    e.a = static_cast<Material>(*rc::gen::inRange(1, 5));
    e.b = static_cast<Material>(*rc::gen::inRange(0, 5));
    if (e.kind == LandscapeEdit::Kind::kReplace && *rc::gen::inRange(0, 4) == 0) e.a = kEmpty;
    return e;
  });
}

// Sized to RapidCheck's nominal size throughout (inRange would shrink its range with the size
// and give one edit in a tiny world to most of the early cases).
inline rc::Gen<LandscapeCase> landscape_case(int max_edits = 8) {
  return rc::gen::resize(
      rc::kNominalSize, rc::gen::exec([max_edits] {
        LandscapeCase c;
        const std::int64_t size = *rc::gen::element<std::int64_t>(64, 256, 1000);
        const Point64 origin{*gen::coord(-300, 300), *gen::coord(-300, 300)};
        c.world = {origin, {origin.x + size, origin.y + size / (*rc::gen::inRange(1, 3))}};
        c.fill = static_cast<Material>(*rc::gen::element(0, 0, 1, 2));
        c.config.tree = *rc::gen::element(TreeKind::kQuadtree, TreeKind::kKdTree);
        c.config.edge_cap = *rc::gen::element<std::uint32_t>(32, 40, 64, 1000);
        c.config.merge_below = c.config.edge_cap / 3;
        c.config.min_cell_size = *rc::gen::element<std::int64_t>(1, 2, 8);
        if (*rc::gen::inRange(0, 10) == 0) c.config.grid_depth = *rc::gen::inRange(1, 4);
        const int n = *rc::gen::inRange(1, max_edits + 1);
        for (int i = 0; i < n; ++i) c.edits.push_back(*edit_in(c.world));
        return c;
      }));
}

// The landscape of a case after its edits, checked; fails the property on any exception.
inline Landscape run_case(const LandscapeCase& c, const LandscapeConfig& config,
                          std::uint32_t* deepest = nullptr) {
  Landscape l(c.world, c.fill, config);
  l.set_checked(true);
  for (const LandscapeEdit& e : c.edits) {
    try {
      apply(l, e);
    } catch (const std::exception& ex) {
      RC_FAIL(std::string("edit threw: ") + ex.what() + "\n  edit: " + describe(e));
    }
    if (deepest)
      *deepest = std::max<std::uint32_t>(*deepest, static_cast<std::uint32_t>(l.stats().depth));
  }
  return l;
}

// The edit as a batch takes it (types.hpp Edit).
inline Edit as_edit(const LandscapeEdit& e) {
  ValidSet shape(e.shape, Operand::kClip);
  switch (e.kind) {
    case LandscapeEdit::Kind::kCarve:
      return Edit::carve(std::move(shape));
    case LandscapeEdit::Kind::kFill:
      return Edit::fill(std::move(shape), e.a);
    case LandscapeEdit::Kind::kFillEmpty:
      return Edit::fill_empty(std::move(shape), e.a);
    case LandscapeEdit::Kind::kReplace:
      break;
  }
  return Edit::replace(std::move(shape), e.a, e.b);
}

// The case's edits cut into consecutive batches of 1-4 (sizes drawn here), in order.
inline std::vector<std::vector<Edit>> batches_of(const LandscapeCase& c) {
  std::vector<std::vector<Edit>> out;
  for (std::size_t i = 0; i < c.edits.size();) {
    const std::size_t n = std::min<std::size_t>(*rc::gen::inRange(1, 5), c.edits.size() - i);
    std::vector<Edit>& batch = out.emplace_back();
    for (std::size_t k = 0; k < n; ++k) batch.push_back(as_edit(c.edits[i + k]));
    i += n;
  }
  return out;
}

// The landscape of a case after its edits applied as `batches` (Landscape::apply_batch), checked;
// fails the property on any exception.
inline Landscape run_batches(const LandscapeCase& c, const LandscapeConfig& config,
                             const std::vector<std::vector<Edit>>& batches,
                             std::uint32_t* deepest = nullptr) {
  Landscape l(c.world, c.fill, config);
  l.set_checked(true);
  for (const std::vector<Edit>& batch : batches) {
    try {
      l.apply_batch(batch);
    } catch (const std::exception& ex) {
      RC_FAIL(std::string("batch threw: ") + ex.what());
    }
    if (deepest)
      *deepest = std::max<std::uint32_t>(*deepest, static_cast<std::uint32_t>(l.stats().depth));
  }
  return l;
}

}  // namespace edgeland::test
