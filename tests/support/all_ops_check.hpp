#pragma once
// Named test cases checked under every operation, both ways round, against the exact reference
// (accuracy_contract.hpp), in checked mode.
#include <gtest/gtest.h>

#include "accuracy_contract.hpp"
#include "checked_clip.hpp"
#include "edgeland/kernel/validate.hpp"
#include "edgeland/kernel/wkt_writer.hpp"

namespace edgeland::test {

inline void expect_all_ops_exact(const PolygonSet& a, const PolygonSet& b) {
  ASSERT_TRUE(validate(a).ok()) << to_wkt(a);
  ASSERT_TRUE(validate(b).ok()) << to_wkt(b);
  for (ClipOp op : {ClipOp::kUnion, ClipOp::kIntersection, ClipOp::kDifference, ClipOp::kXor}) {
    for (bool swapped : {false, true}) {
      const PolygonSet& s = swapped ? b : a;
      const PolygonSet& c = swapped ? a : b;
      const Outcome o = run_clip(op, s, c);
      ASSERT_TRUE(o.ok()) << o.error;
      const ContractReport r = check_clip(op, s, c, *o.result);
      EXPECT_TRUE(r.ok()) << r.failure;
    }
  }
}

}  // namespace edgeland::test
