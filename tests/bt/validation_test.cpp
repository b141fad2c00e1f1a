// Every validation error: exact message, file:line:column, suggestion.
#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

using ValidationTest = TreeTest;

TEST_F(ValidationTest, AValidFileValidatesAndCreatesNothing) {
  EXPECT_EQ(validation_error(R"(
components:
  sampler: { plugin: fake_sampler, samples: 3 }
main: t
trees:
  t:
    UseSampler: { sampler: sampler }
)"),
            "");
  EXPECT_EQ(components.created, 0);
}

TEST_F(ValidationTest, YamlSyntaxError) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t: [AlwaysSuccess\n"),
            "trees/t.yaml:4:1: YAML syntax error: end of sequence flow not found");
}

TEST_F(ValidationTest, UnknownNodeWithSuggestion) {
  EXPECT_EQ(validation_error(R"(main: t
trees:
  t:
    Sequnce:
      - AlwaysSuccess: {}
)"),
            "trees/t.yaml:4:5: unknown node 'Sequnce' (did you mean 'Sequence'?)");
}

TEST_F(ValidationTest, UnknownNodeWithoutNearName) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Sequence: [Frobnicate]\n"),
            "trees/t.yaml:4:16: unknown node 'Frobnicate'");
}

TEST_F(ValidationTest, UnknownPortWithSuggestion) {
  EXPECT_EQ(validation_error(R"(main: t
trees:
  t:
    Retry:
      num_atempts: 3
      child: AlwaysSuccess
)"),
            "trees/t.yaml:5:7: unknown port 'num_atempts' of Retry (did you mean "
            "'num_attempts'?)");
}

TEST_F(ValidationTest, ChildrenWrittenAsPortsOfAControlNode) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Sequence: { AlwaysSuccess: {} }\n"),
            "trees/t.yaml:4:17: unknown port 'AlwaysSuccess' of Sequence (the children of "
            "Sequence go in a list: 'Sequence: [...]' or 'children: [...]')");
}

TEST_F(ValidationTest, MissingRequiredPort) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Sequence:\n      - ReadInt: {}\n"),
            "trees/t.yaml:5:9: missing required port 'in' of ReadInt");
}

TEST_F(ValidationTest, TypeConflictNamesBothPlaces) {
  EXPECT_EQ(validation_error(R"(main: t
trees:
  t:
    Sequence:
      - WriteInt: { value: 1, out: "{x}" }
      - SumList: { in: "{x}" }
)"),
            "trees/t.yaml:6:24: port 'in' of SumList uses {x} as list of double, but port "
            "'out' of WriteInt at trees/t.yaml:5:36 uses it as int");
}

TEST_F(ValidationTest, TypeConflictAcrossSubtreeRemapping) {
  EXPECT_EQ(validation_error(R"(main: t
trees:
  t:
    Sequence:
      - WriteInt: { value: 1, out: "{x}" }
      - SubTree: { tree: h, ports: { numbers: "{x}" } }
  h:
    ports: { numbers: input }
    SumList: { in: "{numbers}" }
)"),
            "trees/t.yaml:9:20: port 'in' of SumList uses {numbers} as list of double, but "
            "port 'out' of WriteInt at trees/t.yaml:5:36 uses {x} as int");
}

TEST_F(ValidationTest, WrongNumberOfChildren) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Sequence: []\n"),
            "trees/t.yaml:4:5: Sequence needs at least 1 child, got 0");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Inverter: {}\n"),
            "trees/t.yaml:4:5: Inverter needs exactly 1 child, got 0 (write it under 'child:')");
  EXPECT_EQ(
      validation_error(
          "main: t\ntrees:\n  t:\n    Inverter: { child: AlwaysSuccess, AlwaysFailure: {} }\n"),
      "trees/t.yaml:4:39: Inverter needs exactly 1 child, found a second one");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Inverter: [AlwaysSuccess]\n"),
            "trees/t.yaml:4:15: Inverter takes a mapping of ports, not a list (write its child "
            "under 'child:')");
  EXPECT_EQ(
      validation_error("main: t\ntrees:\n  t:\n    Log: { message: hi, AlwaysSuccess: {} }\n"),
      "trees/t.yaml:4:25: unknown port 'AlwaysSuccess' of Log (Log takes no children)");
}

TEST_F(ValidationTest, UnknownComponentInAComponentPort) {
  EXPECT_EQ(validation_error(R"(components:
  sampler: { plugin: fake_sampler }
main: t
trees:
  t:
    UseSampler: { sampler: samplr }
)"),
            "trees/t.yaml:6:28: unknown component 'samplr' in port 'sampler' of UseSampler (did "
            "you mean 'sampler'?)");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    UseSampler: { sampler: s }\n"),
            "trees/t.yaml:4:28: unknown component 's' in port 'sampler' of UseSampler (declare "
            "it under 'components:')");
}

TEST_F(ValidationTest, ComponentOfTheWrongKind) {
  EXPECT_EQ(validation_error(R"(components:
  judge: { plugin: fake_classifier }
main: t
trees:
  t:
    UseSampler: { sampler: judge }
)"),
            "trees/t.yaml:6:28: component 'judge' is a classifier, but port 'sampler' of "
            "UseSampler needs a sampler");
}

TEST_F(ValidationTest, UnknownPluginTypeWithSuggestion) {
  EXPECT_EQ(validation_error(R"(components:
  sampler: { plugin: fake_samplr }
main: t
trees:
  t: { AlwaysSuccess: {} }
)"),
            "trees/t.yaml:2:22: unknown plugin type 'fake_samplr' of component 'sampler' (did "
            "you mean 'fake_sampler'?)");
  EXPECT_EQ(validation_error("components:\n  sampler: { samples: 3 }\nmain: t\ntrees:\n  t: "
                             "AlwaysSuccess\n"),
            "trees/t.yaml:2:3: component 'sampler' needs a 'plugin' key naming its type");
}

TEST_F(ValidationTest, BadComponentParameterIsReportedAtLoad) {
  const std::string yaml = R"(components:
  sampler:
    plugin: fake_sampler
    sampels: 3
main: t
trees:
  t: { AlwaysSuccess: {} }
)";
  EXPECT_EQ(validation_error(yaml), "");
  EXPECT_EQ(load_error(yaml),
            "trees/t.yaml:4:5: unknown parameter 'sampels' of component 'sampler' (did you mean "
            "'samples'?)");
}

TEST_F(ValidationTest, MissingOrUnknownMain) {
  EXPECT_EQ(validation_error("trees:\n  a: AlwaysSuccess\n  b: AlwaysFailure\n"),
            "trees/t.yaml:1:1: missing 'main': name the tree to run (one of: a, b)");
  EXPECT_EQ(validation_error("main: detct\ntrees:\n  detect: { AlwaysSuccess: {} }\n"),
            "trees/t.yaml:1:7: unknown tree 'detct' in 'main' (did you mean 'detect'?)");
}

TEST_F(ValidationTest, SubtreeCycleIsNamed) {
  EXPECT_EQ(validation_error(R"(main: a
trees:
  a:
    SubTree: { tree: b }
  b:
    Sequence:
      - AlwaysSuccess
      - SubTree: { tree: a }
)"),
            "trees/t.yaml:8:26: subtree cycle: a -> b -> a");
  EXPECT_EQ(validation_error("main: a\ntrees:\n  a:\n    SubTree: a\n"),
            "trees/t.yaml:4:14: subtree cycle: a -> a");
}

TEST_F(ValidationTest, UnknownSubtreeWithSuggestion) {
  EXPECT_EQ(validation_error(R"(main: a
trees:
  a:
    SubTree: { tree: helpr }
  helper: { AlwaysSuccess: {} }
)"),
            "trees/t.yaml:4:22: unknown tree 'helpr' in SubTree (did you mean 'helper'?)");
}

TEST_F(ValidationTest, SubtreePortsAreChecked) {
  const std::string helper = R"(
  h:
    ports: { in_cloud: input, out: output }
    AlwaysSuccess: {}
)";
  EXPECT_EQ(validation_error("main: a\ntrees:\n  a:\n    SubTree: { tree: h, ports: { in_clod: "
                             "\"{c}\" } }" +
                             helper),
            "trees/t.yaml:4:34: unknown port 'in_clod' of tree 'h' (did you mean 'in_cloud'?)");
  EXPECT_EQ(validation_error("main: a\ntrees:\n  a:\n    SubTree: { tree: h }" + helper),
            "trees/t.yaml:4:5: missing required port 'in_cloud' of tree 'h'");
  EXPECT_EQ(validation_error("main: a\ntrees:\n  a:\n    SubTree: { tree: h, ports: { in_cloud: "
                             "\"{c}\", out: \"not a key\" } }" +
                             helper),
            "trees/t.yaml:4:56: port 'out' of tree 'h' is an output and must name a blackboard "
            "entry such as \"{out}\", got 'not a key'");
  EXPECT_EQ(validation_error("main: a\ntrees:\n  a:\n    SubTree: { tree: h, port: {} }" + helper),
            "trees/t.yaml:4:25: unknown port 'port' of SubTree (did you mean 'ports'?)");
  EXPECT_EQ(validation_error("main: a\ntrees:\n  a:\n    SubTree: { tree: h, ports: { x: \"{c}\" "
                             "} }\n  h: AlwaysSuccess\n"),
            "trees/t.yaml:4:34: unknown port 'x' of tree 'h' (tree 'h' declares no ports; list "
            "them under its 'ports:')");
}

TEST_F(ValidationTest, BadLiteralForATypedPort) {
  EXPECT_EQ(
      validation_error(
          "main: t\ntrees:\n  t:\n    Retry: { num_attempts: three, child: AlwaysSuccess }\n"),
      "trees/t.yaml:4:28: port 'num_attempts' of Retry expects int, got 'three'");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Wait: { msec: -5 }\n"),
            "trees/t.yaml:4:19: port 'msec' of Wait expects milliseconds, got '-5'");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    SumList: { in: [1, x] }\n"),
            "trees/t.yaml:4:20: port 'in' of SumList expects list of double, got a list");
}

TEST_F(ValidationTest, LiteralForAPortThatOnlyTakesEntries) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    ReadBig: { in: data }\n"),
            "trees/t.yaml:4:20: port 'in' of ReadBig takes std::shared_ptr<std::vector<int, "
            "std::allocator<int> > const> from a blackboard entry; write \"{name}\", not 'data'");
}

TEST_F(ValidationTest, UnquotedReferenceGetsAHint) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    ReadInt: { in: {n} }\n"),
            "trees/t.yaml:4:20: port 'in' of ReadInt: write \"{n}\" in quotes; unquoted, YAML "
            "reads {n} as a mapping");
}

TEST_F(ValidationTest, BadReferenceAndOutputLiteral) {
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    ReadInt: { in: \"{a b}\" }\n"),
            "trees/t.yaml:4:20: port 'in' of ReadInt has a bad blackboard reference '{a b}': an "
            "entry name is a letter or '_' followed by letters, digits or '_'");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    WriteInt: { value: 1, out: 12 }\n"),
            "trees/t.yaml:4:32: port 'out' of WriteInt is an output and must name a blackboard "
            "entry such as \"{out}\", got '12'");
}

TEST_F(ValidationTest, StructuralMistakes) {
  EXPECT_EQ(validation_error("main: t\ntree:\n  t: AlwaysSuccess\n"),
            "trees/t.yaml:2:1: unknown top-level key 'tree' (did you mean 'trees'?)");
  EXPECT_EQ(validation_error(""),
            "trees/t.yaml: the tree file is empty; it needs 'main' and 'trees'");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Sequence:\n      - ReadInt:\n        in: "
                             "\"{x}\"\n"),
            "trees/t.yaml:6:9: a node is a one-key mapping {Type: ports}; this one has keys "
            "'ReadInt' and 'in' (are the ports of ReadInt indented under it?)");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Log:\n    message: hi\n"),
            "trees/t.yaml:5:5: tree 't' must have exactly one root node, found 'Log' and "
            "'message' (are the ports of Log indented under it?)");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    Log: { message: a, message: b }\n"),
            "trees/t.yaml:4:24: duplicate key 'message'");
  EXPECT_EQ(validation_error("main: t\ntrees:\n  t:\n    ports: { x: input }\n"),
            "trees/t.yaml:3:3: tree 't' has no root node");
  EXPECT_EQ(
      validation_error("main: t\ntrees:\n  t:\n    ports: { x: in }\n    AlwaysSuccess: {}\n"),
      "trees/t.yaml:4:17: port 'x' of tree 't' must be input, output or inout, got 'in'");
}

TEST_F(ValidationTest, SetOverridesAreChecked) {
  const std::string yaml = R"(components:
  sampler: { plugin: fake_sampler }
main: t
trees:
  t:
    ReadInt: { in: "{n}" }
)";
  options.overrides = {{"n", "abc"}};
  EXPECT_EQ(validation_error(yaml),
            "--set n=abc: {n} is used as int by port 'in' of ReadInt at trees/t.yaml:6:20, and "
            "'abc' is not a valid int");
  options.overrides = {{"samplr.samples", "3"}};
  EXPECT_EQ(validation_error(yaml),
            "--set samplr.samples=3: unknown component 'samplr' (did you mean 'sampler'?)");
  options.overrides = {{"sampler.plugin", "fake_classifier"}};
  EXPECT_EQ(validation_error(yaml), "");
  options.overrides = {{"a b", "1"}};
  EXPECT_EQ(validation_error(yaml),
            "--set a b=1: not a blackboard entry name (a letter or '_', then letters, digits, "
            "'_') nor component.parameter");
}

// Inputs that would cost hours or gigabytes are refused with the limit named: aliases that
// expand a --set value or a tree file to millions of nodes, subtrees nested 200 deep, a file
// of 1,500 trees.
TEST_F(ValidationTest, OversizedInputsAreRefusedWithTheLimit) {
  std::string bomb = "[&a0 [x, x, x, x, x, x, x, x, x, x]";
  for (int i = 1; i < 7; ++i) {
    bomb += ", &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) bomb += std::string(k ? ", " : "") + "*a" + std::to_string(i - 1);
    bomb += "]";
  }
  bomb += "]";
  const std::string small =
      "components:\n  sampler: { plugin: fake_sampler }\nmain: t\n"
      "trees:\n  t:\n    AlwaysSuccess: {}\n";
  options.overrides = {{"sampler.samples", bomb}};
  EXPECT_NE(validation_error(small).find("more than 1000000 YAML nodes"), std::string::npos)
      << validation_error(small);
  options.overrides = {};
  EXPECT_NE(validation_error(small + "extra: " + bomb + "\n").find("more than 1000000 YAML nodes"),
            std::string::npos);

  std::string deep = "main: t0\ntrees:\n";
  for (int i = 0; i < 200; ++i)
    deep +=
        "  t" + std::to_string(i) + ":\n    SubTree: { tree: t" + std::to_string(i + 1) + " }\n";
  deep += "  t200:\n    AlwaysSuccess: {}\n";
  EXPECT_NE(validation_error(deep).find("subtrees nest deeper than 64"), std::string::npos)
      << validation_error(deep);

  std::string many = "main: t0\ntrees:\n";
  for (int i = 0; i < 1500; ++i) many += "  t" + std::to_string(i) + ":\n    AlwaysSuccess: {}\n";
  EXPECT_NE(validation_error(many).find("1500 trees, more than the 1000 a file may hold"),
            std::string::npos)
      << validation_error(many);
}

TEST_F(ValidationTest, MissingFileIsAnError) {
  try {
    validate_tree_file("/nonexistent/tree.yaml", options);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "/nonexistent/tree.yaml: cannot read tree file "
                 "'/nonexistent/tree.yaml'");
  }
}

}  // namespace
}  // namespace antipode::bt::testing
