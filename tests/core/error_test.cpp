#include "antipode/core/error.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace antipode
