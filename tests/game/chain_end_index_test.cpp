// The chain-end index (game/src/ghosts.hpp) and its flat table (chain_end_table.hpp) against
// the index they replaced, kept here as the reference: a map from each point to a vector of its
// chains. The order of a point's chains decides which kept chains a surface update re-keys first
// (so the chain ids a game sees): it must be the reference's exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "chain_end_table.hpp"
#include "ghosts.hpp"

namespace edgeland::test {
namespace {

using game_detail::ChainEndIndex;
using game_detail::ChainEndTable;
using Chains = std::vector<const SurfaceChain*>;

// The index before the flat table, verbatim but for the container of the points: a vector per
// point, appended to by add, erased from by remove, overwritten in place by replace.
class ReferenceIndex {
 public:
  void add(const SurfaceChain& c) {
    if (c.closed) return;
    at_[c.points.front()].push_back(&c);
    if (c.points.back() != c.points.front()) at_[c.points.back()].push_back(&c);
  }
  void remove(const SurfaceChain& c) {
    if (c.closed) return;
    erase(c.points.front(), &c);
    if (c.points.back() != c.points.front()) erase(c.points.back(), &c);
  }
  void replace(const SurfaceChain* from, const SurfaceChain& to) {
    if (to.closed) return;
    for (const Point64 p : {to.points.front(), to.points.back()}) {
      const auto it = at_.find(p);
      if (it != at_.end()) std::replace(it->second.begin(), it->second.end(), from, &to);
    }
  }
  Chains at(Point64 p) const {
    const auto it = at_.find(p);
    return it == at_.end() ? Chains{} : it->second;
  }
  // Whether a chain is anywhere in the index (then its points must not change).
  bool holds(const SurfaceChain* c) const {
    return std::any_of(at_.begin(), at_.end(), [&](const auto& kv) {
      return std::find(kv.second.begin(), kv.second.end(), c) != kv.second.end();
    });
  }

 private:
  void erase(Point64 p, const SurfaceChain* c) {
    const auto it = at_.find(p);
    if (it == at_.end()) return;
    std::erase(it->second, c);
    if (it->second.empty()) at_.erase(it);
  }
  std::map<Point64, Chains> at_;
};

// Random operations on the index and the reference side by side, with a fixed seed. End points
// come from a small grid, an eighth of them from four hot points, so that many chains share a
// point; a sixteenth of the chains are closed and some open ones begin where they end.
class IndexRun {
 public:
  explicit IndexRun(std::size_t chains) : pool_(chains) {
    for (SurfaceChain& c : pool_) reshape(c);
  }

  void random_op() {
    const std::uint64_t kind = rng_() % 16;
    SurfaceChain& c = pool_[rng_() % pool_.size()];
    if (kind < add_weight_) return add(c);
    if (kind < 14) return remove(c);
    replace(c, pool_[rng_() % pool_.size()]);
  }
  void set_add_weight(std::uint64_t of16) { add_weight_ = of16; }
  void remove_all() {
    for (const SurfaceChain& c : pool_) remove(c);
  }
  // Every grid point and the hot ones, through chains_at and lookup().
  void expect_all_equal() const {
    for (std::int64_t x = 0; x < kGrid; ++x)
      for (std::int64_t y = 0; y < kGrid; ++y) expect_equal_at({x, y});
    for (std::int64_t h = 0; h < 4; ++h) expect_equal_at(hot(h));
  }
  bool reference_empty() const {
    for (const SurfaceChain& c : pool_)
      if (ref_.holds(&c)) return false;
    return true;
  }

 private:
  static constexpr std::int64_t kGrid = 24;
  static Point64 hot(std::int64_t h) { return {1000 + h, -1000}; }

  Point64 random_point() {
    if (rng_() % 8 == 0) return hot(static_cast<std::int64_t>(rng_() % 4));
    return {static_cast<std::int64_t>(rng_() % kGrid), static_cast<std::int64_t>(rng_() % kGrid)};
  }
  void reshape(SurfaceChain& c) {
    const Point64 a = random_point();
    const Point64 b = rng_() % 32 == 0 ? a : random_point();
    c.points = {a, {a.x + 1, b.y + 1}, b};
    c.closed = rng_() % 16 == 0;
  }

  // A chain in neither index takes new points first (an indexed one must keep its points).
  void add(SurfaceChain& c) {
    if (ref_.holds(&c)) return;
    reshape(c);
    index_.add(c);
    ref_.add(c);
    expect_ends_equal(c);
  }
  void remove(const SurfaceChain& c) {
    index_.remove(c);
    ref_.remove(c);
    expect_ends_equal(c);
  }
  // `to` (in neither index) takes from's points, as a surface commit's chains do, or now and
  // then other points; `from` may be absent.
  void replace(const SurfaceChain& from, SurfaceChain& to) {
    if (ref_.holds(&to)) return;
    if (rng_() % 8 == 0) {
      reshape(to);
    } else {
      to.points = from.points;
      to.closed = from.closed;
    }
    index_.replace(&from, to);
    ref_.replace(&from, to);
    expect_ends_equal(to);
  }

  void expect_ends_equal(const SurfaceChain& c) const {
    expect_equal_at(c.points.front());
    expect_equal_at(c.points.back());
  }
  // chains_at appends after what `out` holds already.
  void expect_equal_at(Point64 p) const {
    const SurfaceChain* sentinel = &pool_.front();
    Chains got{sentinel};
    index_.chains_at(p, got);
    Chains want{sentinel};
    const Chains ref = ref_.at(p);
    want.insert(want.end(), ref.begin(), ref.end());
    ASSERT_EQ(got, want) << "at (" << p.x << ", " << p.y << ")";
    Chains looked;
    index_.lookup()(p, looked);
    ASSERT_EQ(looked, ref);
  }

  std::vector<SurfaceChain> pool_;  // never resized: the indexes point into it
  ChainEndIndex index_;
  ReferenceIndex ref_;
  std::mt19937_64 rng_{20240611};
  std::uint64_t add_weight_ = 12;
};

// Growth from empty through many rehashes, churn that leaves tombstones, a drain to nothing and
// growth again: every point's chains, in order, as the reference's after every operation.
TEST(ChainEndIndex, ChainsAtKeepsTheReferenceOrderOverRandomOperations) {
  IndexRun run(1500);
  run.set_add_weight(12);  // mostly adds: about 2,000 entries
  for (int i = 0; i < 3000; ++i) ASSERT_NO_FATAL_FAILURE(run.random_op());
  ASSERT_NO_FATAL_FAILURE(run.expect_all_equal());
  run.set_add_weight(7);  // as many adds as removes
  for (int i = 0; i < 6000; ++i) ASSERT_NO_FATAL_FAILURE(run.random_op());
  ASSERT_NO_FATAL_FAILURE(run.expect_all_equal());
  run.remove_all();
  ASSERT_TRUE(run.reference_empty());
  ASSERT_NO_FATAL_FAILURE(run.expect_all_equal());
  run.set_add_weight(12);
  for (int i = 0; i < 3000; ++i) ASSERT_NO_FATAL_FAILURE(run.random_op());
  ASSERT_NO_FATAL_FAILURE(run.expect_all_equal());
}

// The table's bounds: live entries and tombstones at most half the slots after every operation,
// growth by doubling through several rehashes, and under steady churn a capacity set by the
// live entries (tombstones are cleared by rehashing in place, not by growing).
TEST(ChainEndTable, LoadStaysAtMostHalfAndChurnDoesNotGrowIt) {
  const std::vector<SurfaceChain> pool(64);
  std::mt19937_64 rng(7);
  ChainEndTable table;
  std::vector<std::pair<Point64, const SurfaceChain*>> live;
  std::size_t most_tombstones = 0;
  const auto check = [&] {
    ASSERT_EQ(table.size(), live.size());
    ASSERT_LE(2 * (table.size() + table.tombstones()), table.capacity());
    most_tombstones = std::max(most_tombstones, table.tombstones());
  };
  const auto insert = [&] {
    const Point64 p{static_cast<std::int64_t>(rng() % 5000), 0};
    live.emplace_back(p, &pool[rng() % pool.size()]);
    table.insert(p, live.back().second);
  };
  const auto erase = [&] {
    // Erases every entry (p, chain), duplicates included.
    const auto [p, c] = live[rng() % live.size()];
    table.erase(p, c);
    std::erase(live, std::pair{p, c});
  };
  for (int i = 0; i < 1000; ++i) ASSERT_NO_FATAL_FAILURE((insert(), check()));
  EXPECT_EQ(table.capacity(), 2048u);  // 16 doubled 7 times
  for (int i = 0; i < 50000; ++i)
    ASSERT_NO_FATAL_FAILURE((live.size() < 1000 ? insert() : erase(), check()));
  EXPECT_EQ(table.capacity(), 4096u);  // at most 4 x live after a rehash
  EXPECT_GT(most_tombstones, 200u);
}

}  // namespace
}  // namespace edgeland::test
