#include "antipode/core/error.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace antipode {
namespace {

TEST(ErrorTest, FormatsLocationMessageAndHintOnOneLine) {
  const Error error("unknown node 'X'\nsecond line", {"trees/x.yaml", 3, 7}, "see docs");
  EXPECT_STREQ(error.what(), "trees/x.yaml:3:7: unknown node 'X' second line (see docs)");
  EXPECT_EQ(error.where().line, 3);
}

TEST(ErrorTest, OmitsUnknownParts) {
  EXPECT_STREQ(Error("plain").what(), "plain");
  EXPECT_STREQ(Error("m", {"f.yaml", 2, 0}).what(), "f.yaml:2: m");
  EXPECT_STREQ(Error("").what(), "unknown error");
}

TEST(DidYouMeanTest, SuggestsNearNamesOnly) {
  const std::vector<std::string> names = {"Sequence", "Fallback", "Parallel"};
  EXPECT_EQ(did_you_mean("Sequnce", names), " (did you mean 'Sequence'?)");
  EXPECT_EQ(closest_match("Fallbak", names), "Fallback");
  EXPECT_EQ(did_you_mean("CompletelyDifferent", names), "");
  EXPECT_EQ(closest_match("x", {}), "");
}

TEST(RethrowWithContextTest, LocatesErrorsAndMarksOtherExceptionsInternal) {
  const SourceLocation here{"t.yaml", 4, 2};
  auto rethrown = [&](auto thrown) -> std::exception_ptr {
    try {
      try {
        throw thrown;
      } catch (...) {
        rethrow_with_context("Node", here);
      }
    } catch (...) {
      return std::current_exception();
    }
    return nullptr;
  };
  try {
    std::rethrow_exception(rethrown(std::out_of_range("index 9")));
  } catch (const InternalError& error) {
    EXPECT_STREQ(error.what(), "t.yaml:4:2: Node: index 9");
  }
  try {
    std::rethrow_exception(rethrown(Error("bad value")));
  } catch (const InternalError&) {
    FAIL() << "an Error must stay an input error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "t.yaml:4:2: Node: bad value");
  }
  try {
    std::rethrow_exception(rethrown(Error("bad value", {"other.yaml", 1, 1})));
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "other.yaml:1:1: bad value");  // already located: unchanged
  }
  EXPECT_THROW(std::rethrow_exception(rethrown(42)), InternalError);
}

}  // namespace
}  // namespace antipode
