// Convex pieces through Box2D 2.4's b2PolygonShape::Set (box2d_piece.hpp).
#include "box2d_piece.hpp"

#include <box2d/box2d.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace edgeland::testing {
namespace {

b2Vec2 to_engine(Point64 p, const Box2dFrame& f) {
  return {static_cast<float>(static_cast<double>(p.x - f.origin.x) * f.meters_per_unit),
          static_cast<float>(static_cast<double>(p.y - f.origin.y) * f.meters_per_unit)};
}

bool same_cycle(const b2PolygonShape& shape, const std::vector<b2Vec2>& v) {
  const auto n = static_cast<int>(v.size());
  if (shape.m_count != n) return false;
  for (int start = 0; start < n; ++start) {
    bool all = true;
    for (int i = 0; i < n && all; ++i) {
      const b2Vec2 a = shape.m_vertices[(start + i) % n];
      all = a.x == v[static_cast<std::size_t>(i)].x && a.y == v[static_cast<std::size_t>(i)].y;
    }
    if (all) return true;
  }
  return false;
}

// Runs the pieces [first, last) in a child: exit 0 when Set kept them all, 1 otherwise; killed
// by SIGABRT when an assertion failed.
Box2dVerdict run_in_child(const std::vector<Polygon>& pieces, const std::vector<Box2dFrame>& frames,
                          std::size_t first, std::size_t last) {
  const pid_t pid = fork();
  if (pid == 0) {
    bool kept = true;
    for (std::size_t i = first; i < last; ++i) kept = box2d_keeps(pieces[i], frames[i]) && kept;
    _exit(kept ? 0 : 1);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status))
    return WEXITSTATUS(status) == 0 ? Box2dVerdict::kKept : Box2dVerdict::kAltered;
  return Box2dVerdict::kAborted;
}

// a t - b r = 1 for coprime (a, b): the step (r, t) that turns (a, b) by the least lattice
// angle (extended Euclid).
bool least_turn(std::int64_t a, std::int64_t b, std::int64_t& r, std::int64_t& t) {
  std::int64_t old_r = a, cur_r = b, old_s = 1, cur_s = 0, old_u = 0, cur_u = 1;
  while (cur_r != 0) {
    const std::int64_t q = old_r / cur_r;
    old_r = std::exchange(cur_r, old_r - q * cur_r);
    old_s = std::exchange(cur_s, old_s - q * cur_s);
    old_u = std::exchange(cur_u, old_u - q * cur_u);
  }
  if (old_r != 1 && old_r != -1) return false;  // not coprime
  // a old_s + b old_u = old_r = +-1, so t = old_s old_r, r = -old_u old_r give a t - b r = 1.
  t = old_s * old_r;
  r = -old_u * old_r;
  return true;
}

bool strictly_convex(const Polygon& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point64 a = p[i], b = p[(i + 1) % p.size()], c = p[(i + 2) % p.size()];
    if (__int128(b.x - a.x) * (c.y - a.y) - __int128(b.y - a.y) * (c.x - a.x) <= 0) return false;
  }
  return true;
}

}  // namespace

Polygon least_turn_piece(LeastTurnKind kind, std::int64_t extent, std::int64_t offset,
                         bool transpose) {
  const int edges = kind == LeastTurnKind::kArc ? 7 : 2;
  std::int64_t a = extent / edges, b = offset, r = 0, t = 0;
  if (transpose) std::swap(a, b);
  if (a == 0 && b == 0) return {};
  if (!least_turn(a, b, r, t)) return {};
  Polygon p{{0, 0}};
  for (int k = 0; k < edges; ++k) p.push_back({p.back().x + a + k * r, p.back().y + b + k * t});
  if (kind == LeastTurnKind::kKinkedQuad) {
    const Point64 w = p.back();
    p.push_back({(w.x - w.y) / 2, (w.y + w.x) / 2});
  }
  return strictly_convex(p) ? p : Polygon{};
}

Polygon placed(Polygon piece, std::int64_t reach, int quarter_turns) {
  std::int64_t mx = piece[0].x, my = piece[0].y;
  for (const Point64& q : piece) mx = std::max(mx, q.x), my = std::max(my, q.y);
  for (Point64& q : piece) {
    q = {q.x - mx + reach, q.y - my + reach};
    for (int i = 0; i < quarter_turns; ++i) q = {-q.y, q.x};
  }
  return piece;
}

bool box2d_keeps(const Polygon& piece, const Box2dFrame& frame) {
  if (piece.size() < 3 || piece.size() > static_cast<std::size_t>(b2_maxPolygonVertices))
    return false;
  std::vector<b2Vec2> v;
  for (const Point64& p : piece) v.push_back(to_engine(p, frame));
  b2PolygonShape shape;
  shape.Set(v.data(), static_cast<int32>(v.size()));
  return same_cycle(shape, v);
}

std::vector<Box2dVerdict> box2d_verdicts(const std::vector<Polygon>& pieces,
                                         const std::vector<Box2dFrame>& frames) {
  constexpr std::size_t kBatch = 4096;
  std::vector<Box2dVerdict> out(pieces.size(), Box2dVerdict::kKept);
  for (std::size_t first = 0; first < pieces.size(); first += kBatch) {
    const std::size_t last = std::min(pieces.size(), first + kBatch);
    if (run_in_child(pieces, frames, first, last) == Box2dVerdict::kKept) continue;
    for (std::size_t i = first; i < last; ++i) out[i] = run_in_child(pieces, frames, i, i + 1);
  }
  return out;
}

std::int64_t reach(const Polygon& piece, Point64 origin) {
  std::int64_t r = 0;
  for (const Point64& p : piece)
    r = std::max({r, std::abs(p.x - origin.x), std::abs(p.y - origin.y)});
  return r;
}

std::int64_t extent(const Polygon& piece) {
  const auto [xl, xh] = std::minmax_element(piece.begin(), piece.end(),
                                            [](Point64 a, Point64 b) { return a.x < b.x; });
  const auto [yl, yh] = std::minmax_element(piece.begin(), piece.end(),
                                            [](Point64 a, Point64 b) { return a.y < b.y; });
  return std::max(xh->x - xl->x, yh->y - yl->y);
}

}  // namespace edgeland::testing
