// Node::random(): determined by the seed, the node's path and its run count.
#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

using RandomTest = TreeTest;

const char* kTwoDraws = R"(
main: t
trees:
  t:
    Sequence:
      - Draw: { out: "{a}" }
      - Draw: { out: "{b}" }
)";

std::vector<double> draw(Tree& tree, const std::string& key) {
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  return tree.blackboard().get<std::vector<double>>(key);
}

TEST_F(RandomTest, TheSameSeedGivesTheSameDraws) {
  Tree first = load(kTwoDraws, 7);
  Tree second = load(kTwoDraws, 7);
  EXPECT_EQ(draw(first, "a"), draw(second, "a"));
  EXPECT_EQ(first.blackboard().get<std::vector<double>>("b"),
            second.blackboard().get<std::vector<double>>("b"));
}

TEST_F(RandomTest, SeedsNodesAndRunsGiveDifferentDraws) {
  Tree tree = load(kTwoDraws, 7);
  Tree other_seed = load(kTwoDraws, 8);
  const auto a = draw(tree, "a");
  EXPECT_NE(a, tree.blackboard().get<std::vector<double>>("b"));
  EXPECT_NE(a, draw(other_seed, "a"));
  EXPECT_NE(a, draw(tree, "a"));  // the second run of the same node
}

TEST_F(RandomTest, DrawsDoNotDependOnUnrelatedNodes) {
  // Adding a node of another type - before or after - leaves Draw's path (numbered among
  // its own type) and so its stream unchanged.
  Tree tree = load(kTwoDraws, 3);
  Tree longer = load(R"(
main: t
trees:
  t:
    Sequence:
      - AlwaysSuccess
      - Draw: { out: "{a}" }
      - Draw: { out: "{b}" }
      - AlwaysSuccess
)",
                     3);
  EXPECT_EQ(draw(tree, "a"), draw(longer, "a"));
  EXPECT_EQ(tree.blackboard().get<std::vector<double>>("b"),
            longer.blackboard().get<std::vector<double>>("b"));
}

}  // namespace
}  // namespace antipode::bt::testing
