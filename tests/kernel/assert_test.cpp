// EDGELAND_ASSERT and fail_stage (edgeland/kernel/assert.hpp) in the test build, where
// EDGELAND_CHECKED is on: a failed assert throws std::logic_error naming the stage, the
// message, and the file and line of the assert, which the pipeline turns into an
// InternalError. assert_release_test.cpp compiles the same macro as a release build does.
#include "edgeland/kernel/assert.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace edgeland::detail {
namespace {

std::string failure_text(void (*call)()) {
  try {
    call();
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "no failure";
}

int assert_line = 0;

void failing_assert() {
  const int two = 2;
  assert_line = __LINE__ + 1;
  EDGELAND_ASSERT(two + two == 5, "plane graph", "arithmetic is broken: " + std::to_string(two));
}

TEST(StageCheckAssert, OnInTheCheckedBuild) {
#if defined(EDGELAND_CHECKED) && EDGELAND_CHECKED
  EXPECT_EQ(EDGELAND_ASSERTS_ENABLED, 1);
#else
  GTEST_SKIP() << "not the checked build";
#endif
}

TEST(StageCheckAssert, FailureNamesStageMessageFileAndLine) {
  if (!EDGELAND_ASSERTS_ENABLED) GTEST_SKIP() << "asserts compiled out";
  const std::string text = failure_text(failing_assert);  // sets assert_line
  EXPECT_EQ(text, "plane graph: arithmetic is broken: 2 (assert_test.cpp:" +
                      std::to_string(assert_line) + ")");
}

TEST(StageCheckAssert, HoldingConditionDoesNotBuildTheMessage) {
  int built = 0;
  auto message = [&] {
    ++built;
    return std::string("never");
  };
  EDGELAND_ASSERT(built == 0, "labeling", message());
  EXPECT_EQ(built, 0);
}

int fail_line = 0;

void failing_stage() {
  fail_line = __LINE__ + 1;
  fail_stage("assembly", "region boundary does not close");
}

TEST(StageCheckAssert, FailStageIsAlwaysOn) {
  const std::string text = failure_text(failing_stage);  // sets fail_line
  EXPECT_EQ(text, "assembly: region boundary does not close (assert_test.cpp:" +
                      std::to_string(fail_line) + ")");
}

}  // namespace
}  // namespace edgeland::detail
