// EDGELAND_ASSERT as a release build compiles it (EDGELAND_CHECKED off, NDEBUG defined): the
// condition is not evaluated and nothing throws. This file sets both before including
// assert.hpp, which no earlier header of this file includes (the precompiled header holds only
// GoogleTest, RapidCheck and standard headers).
#include <gtest/gtest.h>

#ifdef EDGELAND_ASSERT
#error "assert.hpp was included before this file could compile it as a release build"
#endif
#undef EDGELAND_CHECKED
#ifndef NDEBUG
#define NDEBUG
#endif
#include "edgeland/kernel/assert.hpp"

namespace edgeland::detail {
namespace {

TEST(StageCheckAssert, CompiledOutInReleaseBuilds) {
  EXPECT_EQ(EDGELAND_ASSERTS_ENABLED, 0);
  int evaluated = 0;
  EXPECT_NO_THROW(EDGELAND_ASSERT(++evaluated < 0, "snap rounding", "never thrown"));
  EXPECT_EQ(evaluated, 0);
}

}  // namespace
}  // namespace edgeland::detail
