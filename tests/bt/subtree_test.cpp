// SubTree: isolated blackboards connected only through explicit port remapping.
#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

using SubTreeTest = TreeTest;

TEST_F(SubTreeTest, InnerWritesAreVisibleOutsideOnlyThroughRemapping) {
  Tree tree = load(R"(
main: outer
trees:
  outer:
    Sequence:
      - SubTree: { tree: inner, ports: { result: "{answer}" } }
      - ReadInt: { in: "{answer}", expect: 42 }
  inner:
    ports: { result: output }
    Sequence:
      - WriteInt: { value: 42, out: "{result}" }
      - WriteInt: { value: 7, out: "{private}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().keys(), std::vector<std::string>{"answer"});
  EXPECT_EQ(tree.blackboard().get<int>("answer"), 42);
}

TEST_F(SubTreeTest, OuterEntriesAreInvisibleInsideUnlessRemapped) {
  Tree tree = load(R"(
main: outer
trees:
  outer:
    Sequence:
      - WriteInt: { value: 3, out: "{n}" }
      - SubTree: inner
  inner:
    ReadInt: { in: "{n}", expect: 3 }
)");
  EXPECT_THROW(tree.tick_once(), Error);
  Tree remapped = load(R"(
main: outer
trees:
  outer:
    Sequence:
      - WriteInt: { value: 3, out: "{n}" }
      - SubTree: { tree: inner, ports: { value: "{n}" } }
  inner:
    ports: { value: input }
    ReadInt: { in: "{value}", expect: 3 }
)");
  EXPECT_EQ(remapped.tick_once(), Status::kSuccess);
}

TEST_F(SubTreeTest, LiteralInputsAreConvertedToTheTypeTheSubtreeUses) {
  Tree tree = load(R"(
main: outer
trees:
  outer:
    Sequence:
      - SubTree: { tree: check, ports: { value: 5, numbers: [1, 2] } }
      - SubTree: { tree: check, ports: { value: "5", numbers: [] } }
  check:
    ports: { value: input, numbers: input }
    Sequence:
      - ReadInt: { in: "{value}", expect: 5 }
      - SumList: { in: "{numbers}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(validation_error(R"(
main: outer
trees:
  outer:
    SubTree: { tree: check, ports: { value: five } }
  check:
    ports: { value: input }
    ReadInt: { in: "{value}", expect: 5 }
)"),
            "trees/t.yaml:5:45: port 'value' of tree 'check' is used as int by port 'in' of "
            "ReadInt at trees/t.yaml:8:20, but got 'five'");
}

TEST_F(SubTreeTest, EachSubtreeInstanceHasItsOwnBlackboardAndRandomStream) {
  Tree tree = load(R"(
main: outer
trees:
  outer:
    Sequence:
      - SubTree: { tree: draw, ports: { out: "{a}" }, name: first }
      - SubTree: { tree: draw, ports: { out: "{b}" } }
  draw:
    ports: { out: output }
    Sequence:
      - Draw: { out: "{local}" }
      - SetBlackboard: { key: out, value: "{local}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  const auto a = tree.blackboard().get<std::vector<double>>("a");
  const auto b = tree.blackboard().get<std::vector<double>>("b");
  EXPECT_NE(a, b);
  std::vector<std::string> names;
  tree.visit([&](const Node& node, int depth) {
    if (node.type() == "SubTree") names.push_back(node.name() + "@" + std::to_string(depth));
  });
  EXPECT_EQ(names, (std::vector<std::string>{"first@1", "draw@1"}));
}

TEST_F(SubTreeTest, HaltingASubtreeHaltsItsRunningNodes) {
  Tree tree = load(R"(
main: outer
trees:
  outer:
    SubTree: inner
  inner:
    Sequence:
      - Scripted: { id: a, script: [RUNNING] }
)");
  EXPECT_EQ(tree.tick_once(), Status::kRunning);
  tree.halt();
  EXPECT_EQ(probes()["a"].halts, 1);
}

TEST_F(SubTreeTest, NodePathsAreUniqueAndNameTheirPlace) {
  Tree tree = load(R"(
main: outer
trees:
  outer:
    Sequence:
      - AlwaysSuccess
      - SubTree: inner
  inner:
    Inverter: { child: AlwaysFailure }
)");
  std::vector<std::string> paths;
  tree.visit([&](const Node& node, int) { paths.push_back(node.path()); });
  EXPECT_EQ(paths, (std::vector<std::string>{
                       "outer/Sequence",
                       "outer/Sequence/AlwaysSuccess#0",
                       "outer/Sequence/SubTree#0",
                       "outer/Sequence/SubTree#0/inner/Inverter",
                       "outer/Sequence/SubTree#0/inner/Inverter/AlwaysFailure#0",
                   }));
}

}  // namespace
}  // namespace antipode::bt::testing
