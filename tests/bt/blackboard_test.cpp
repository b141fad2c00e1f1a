// Blackboard typing, text conversion, remapping, and entries flowing between nodes.
#include <stdexcept>

#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

// Counts copies, to show that values are moved into and read from the blackboard in place.
struct CopyCounter {
  CopyCounter() = default;
  CopyCounter(const CopyCounter&) { ++copies; }
  CopyCounter(CopyCounter&&) noexcept = default;
  CopyCounter& operator=(const CopyCounter&) {
    ++copies;
    return *this;
  }
  CopyCounter& operator=(CopyCounter&&) noexcept = default;
  static int copies;
};
int CopyCounter::copies = 0;

TEST(BlackboardTest, StoresTypedValues) {
  Blackboard board;
  EXPECT_FALSE(board.has("n"));
  board.set("n", 3);
  board.set("n", 4);
  EXPECT_EQ(board.get<int>("n"), 4);
  EXPECT_EQ(board.type_of("n"), std::type_index(typeid(int)));
  EXPECT_EQ(board.text("n"), "4");
  EXPECT_EQ(board.text("m"), "<unset>");
}

TEST(BlackboardTest, TypeConflictsThrowOnSetAndGet) {
  Blackboard board;
  board.set("n", 3);
  EXPECT_EQ(error_of([&] { board.set("n", 2.5); }),
            "blackboard entry {n} holds int; cannot store double in it");
  EXPECT_EQ(error_of([&] { board.get<std::vector<double>>("n"); }),
            "blackboard entry {n} holds int, not list of double");
  EXPECT_EQ(error_of([&] { board.get<int>("m"); }), "blackboard entry {m} has not been written");
}

TEST(BlackboardTest, TextEntriesConvertToTheRequestedType) {
  Blackboard board;
  board.set<std::string>("n", "12");
  board.set<std::string>("list", "[1, 2.5]");
  EXPECT_EQ(board.get<int>("n"), 12);
  EXPECT_EQ(board.get<std::vector<double>>("list"), (std::vector<double>{1, 2.5}));
  EXPECT_EQ(error_of([&] { board.get<int>("list"); }),
            "blackboard entry {list} holds the text '[1, 2.5]', which is not a valid int");
  board.set("m", 1);
  board.set<std::string>("m", "5");  // text written to an int entry is converted
  EXPECT_EQ(board.get_ref<int>("m"), 5);
  EXPECT_THROW(board.set<std::string>("m", "five"), Error);
  board.set("n", 7);  // a typed write replaces text
  EXPECT_EQ(board.type_of("n"), std::type_index(typeid(int)));
  EXPECT_EQ(board.get<int>("n"), 7);
}

TEST(BlackboardTest, LargeValuesAreMovedInAndReadWithoutCopies) {
  Blackboard board;
  CopyCounter::copies = 0;
  board.set("big", CopyCounter{});
  const CopyCounter& first = board.get_ref<CopyCounter>("big");
  const CopyCounter& second = board.get_ref<CopyCounter>("big");
  EXPECT_EQ(&first, &second);
  EXPECT_EQ(CopyCounter::copies, 0);
  EXPECT_EQ(board.text("big"), "<antipode::bt::testing::(anonymous namespace)::CopyCounter>");
}

TEST(BlackboardTest, RemappedKeysActOnTheTarget) {
  auto outer = std::make_shared<Blackboard>();
  Blackboard inner;
  inner.remap("result", outer, "answer");
  inner.set("result", 42);
  inner.set("private", 1);
  outer->set("hidden", 2);
  EXPECT_EQ(outer->get<int>("answer"), 42);
  EXPECT_FALSE(outer->has("private"));
  EXPECT_FALSE(outer->has("result"));
  EXPECT_FALSE(inner.has("hidden"));
  EXPECT_EQ(inner.keys(), (std::vector<std::string>{"private", "result"}));
}

TEST(BlackboardTest, ReferencesAndKeysAreRecognised) {
  EXPECT_EQ(parse_reference("{cloud}"), "cloud");
  EXPECT_EQ(parse_reference("{_a1}"), "_a1");
  EXPECT_EQ(parse_reference("cloud"), std::nullopt);
  EXPECT_EQ(parse_reference("{a b}"), std::nullopt);
  EXPECT_EQ(parse_reference("{1a}"), std::nullopt);
  EXPECT_FALSE(is_valid_key(""));
}

using EntryTest = TreeTest;

TEST_F(EntryTest, OutputsReachInputsThroughTheBlackboard) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - WriteInt: { value: 7, out: "{n}" }
      - WriteInt: { value: 8, out: m }
      - ReadInt: { in: "{n}", expect: 7 }
      - ReadInt: { in: "{m}", expect: 8 }
      - MakeBig: { out: "{big}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<int>("n"), 7);
  EXPECT_EQ(tree.blackboard().get_ref<std::shared_ptr<const std::vector<int>>>("big")->size(),
            1000u);
}

TEST_F(EntryTest, ReadingAnUnwrittenEntryNamesTheNodePortAndPlace) {
  Tree tree = load(R"(
main: t
trees:
  t:
    ReadInt: { in: "{cloud}" }
)");
  try {
    tree.tick_once();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "trees/t.yaml:5:20: port 'in' of ReadInt reads {cloud}, which no node has "
                 "written yet");
  }
}

TEST_F(EntryTest, ReadingTextThatDoesNotConvertIsALocatedError) {
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - SetBlackboard: { key: x, value: abc }
      - ReadInt: { in: "{x}", name: check }
)");
  try {
    tree.tick_once();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "trees/t.yaml:7:24: port 'in' of ReadInt 'check' reads {x} as int, but it "
                 "holds the text 'abc'");
  }
}

TEST_F(EntryTest, SetOverridesBecomeTextEntriesOfTheMainTree) {
  options.overrides = {{"n", "5"}};
  Tree tree = load(R"(
main: t
trees:
  t:
    ReadInt: { in: "{n}", expect: 5 }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
}

// SetBlackboard with if_unset writes a default that a --set entry (or an earlier write) keeps.
TEST_F(EntryTest, SetBlackboardIfUnsetKeepsAnEntryThatExists) {
  const std::string yaml = R"(
main: t
trees:
  t:
    Sequence:
      - SetBlackboard: { key: n, value: "3", if_unset: true }
      - SetBlackboard: { key: m, value: "4", if_unset: true }
      - SetBlackboard: { key: m, value: "6", if_unset: true }
      - ReadInt: { in: "{n}", expect: 5 }
      - ReadInt: { in: "{m}", expect: 4 }
)";
  options.overrides = {{"n", "5"}};
  EXPECT_EQ(load(yaml).tick_once(), Status::kSuccess);
  options.overrides = {};
  Tree defaulted = load(yaml);
  EXPECT_EQ(defaulted.tick_once(), Status::kFailure) << "n is 3 without --set";
  EXPECT_EQ(defaulted.blackboard().get<std::string>("n"), "3");
}

TEST_F(EntryTest, ListLiteralsAndListEntriesReachListPorts) {
  options.overrides = {{"values", "[0.5, 1.5]"}};
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - SumList: { in: [1, 2, 3.5], sum: "{a}" }
      - SumList: { in: "{values}", sum: "{b}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_DOUBLE_EQ(tree.blackboard().get<double>("a"), 6.5);
  EXPECT_DOUBLE_EQ(tree.blackboard().get<double>("b"), 2.0);
}

TEST_F(EntryTest, ComponentPortsReachTheirComponent) {
  options.overrides = {{"sampler.samples", "7"}};
  Tree tree = load(R"(
components:
  sampler: { plugin: fake_sampler, samples: 3 }
main: t
trees:
  t:
    UseSampler: { sampler: sampler, out: "{n}" }
)");
  EXPECT_EQ(components.created, 1);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<int>("n"), 7);
  EXPECT_NE(tree.component("sampler"), nullptr);
  EXPECT_EQ(tree.component_names(), std::vector<std::string>{"sampler"});
}

// A nested parameter set from the command line: the siblings in the file stay, a missing
// level is made, and an unknown one is reported as the component's.
TEST_F(EntryTest, NestedSetOverridesReachNestedParameters) {
  const std::string file = R"(
components:
  sampler: { plugin: fake_sampler, samples: 3, extra: { add: 1, more: 10 } }
main: t
trees:
  t:
    UseSampler: { sampler: sampler, out: "{n}" }
)";
  options.overrides = {{"sampler.extra.add", "5"}};
  Tree tree = load(file);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<int>("n"), 18);  // 3 + 5 + 10

  options.overrides = {{"sampler.extra.more", "20"}, {"sampler.extra.add", "2"}};
  Tree again = load(R"(
components:
  sampler: { plugin: fake_sampler, samples: 3 }
main: t
trees:
  t:
    UseSampler: { sampler: sampler, out: "{n}" }
)");
  EXPECT_EQ(again.tick_once(), Status::kSuccess);
  EXPECT_EQ(again.blackboard().get<int>("n"), 25);

  options.overrides = {{"sampler.a.b.c", "3"}};
  try {
    load(file);
    FAIL() << "an unknown nested parameter was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("unknown parameter 'a'"), std::string::npos)
        << error.what();
  }
}

// A file's settings: named once, taken by components as "{name}" (nested too) and read by
// the tree as entries; one --set replaces a setting everywhere.
TEST_F(EntryTest, SettingsReachComponentsAndTheMainBlackboard) {
  const std::string file = R"(
settings: { samples: 4, add: 2 }
components:
  sampler: { plugin: fake_sampler, samples: "{samples}", extra: { add: "{add}" } }
main: t
trees:
  t:
    Sequence:
      - UseSampler: { sampler: sampler, out: "{n}" }
      - ReadInt: { in: "{samples}", expect: 4 }
)";
  Tree tree = load(file);
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<int>("n"), 6);  // 4 + 2

  options.overrides = {{"add", "7"}};
  Tree again = load(file);
  EXPECT_EQ(again.tick_once(), Status::kSuccess);
  EXPECT_EQ(again.blackboard().get<int>("n"), 11);  // 4 + 7
}

TEST_F(EntryTest, BadSettingsAreLocatedErrors) {
  const auto error = [this](const std::string& file) {
    try {
      load(file);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string tree = "main: t\ntrees:\n  t:\n    AlwaysSuccess: {}\n";
  const std::string unknown = error(
      "settings: { robot: r.yaml }\ncomponents:\n  sampler: { plugin: fake_sampler, samples: "
      "\"{robt}\" }\n" +
      tree);
  EXPECT_NE(unknown.find("component 'sampler': '{robt}' names no setting of the file (did you "
                         "mean 'robot'?)"),
            std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find(":3:"), std::string::npos) << unknown;
  EXPECT_NE(
      error("settings: { robot: [a, b] }\n" + tree).find("setting 'robot' must be a single value"),
      std::string::npos);
  EXPECT_NE(error("settings: [robot]\n" + tree).find("'settings' must be a mapping"),
            std::string::npos);
  EXPECT_NE(error("settings: { 1robot: x }\n" + tree).find("setting '1robot': not an entry name"),
            std::string::npos);
}

TEST_F(EntryTest, SettingAComponentsPluginStartsItsParametersAfresh) {
  // `classifier` was written for another plugin; its parameters mean nothing to the new one.
  options.overrides = {{"sampler.plugin", "fake_sampler"}, {"sampler.samples", "9"}};
  Tree tree = load(R"(
components:
  sampler: { plugin: fake_classifier, model: m.model, threads: 2 }
main: t
trees:
  t:
    UseSampler: { sampler: sampler, out: "{n}" }
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
  EXPECT_EQ(tree.blackboard().get<int>("n"), 9);
}

TEST_F(EntryTest, AnotherTreeOfTheFileCanBeRunAsTheMainOne) {
  options.overrides = {{"n", "5"}};
  options.main_tree = "inner";
  Tree tree = load(R"(
main: outer
trees:
  outer:
    SubTree: { tree: inner, ports: { n: 4 } }
  inner:
    ports: { n: input }
    ReadInt: { in: "{n}", expect: 5 }
)");
  EXPECT_EQ(tree.main_tree(), "inner");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess) << "{n} is the main blackboard's entry";
  options.main_tree = "inne";
  try {
    load("main: t\ntrees:\n  t: AlwaysSuccess\n  inner: AlwaysSuccess\n");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("no tree 'inne' to run (did you mean 'inner'?)"),
              std::string::npos)
        << error.what();
  }
}

// A node type "Thrower" whose tick calls `fault`, which throws.
NodeManifest thrower(void (*fault)()) {
  NodeManifest made;
  made.type = "Thrower";
  made.create = [fault](const NodeConfig& config) -> std::unique_ptr<Node> {
    struct Throwing : SyncActionNode {
      Throwing(const NodeConfig& config, void (*fault)()) : SyncActionNode(config), fault(fault) {}
      Status tick() override {
        fault();
        return Status::kSuccess;
      }
      void (*fault)();
    };
    return std::make_unique<Throwing>(config, fault);
  };
  return made;
}

TEST_F(EntryTest, ErrorsThrownByATickAreLocatedAtTheNode) {
  registry.add(thrower([] { throw Error("no finite point"); }));
  Tree tree = load("main: t\ntrees:\n  t:\n    Sequence: [AlwaysSuccess, Thrower]\n");
  try {
    tree.tick_once();
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "trees/t.yaml:4:31: Thrower: no finite point");
  }
  EXPECT_EQ(tree.root().status(), Status::kIdle);
  // Nodes left RUNNING by the failed tick are halted.
  Tree parallel = load(R"(
main: t
trees:
  t:
    Sequence:
      - Parallel:
          - Scripted: { id: a, script: [RUNNING] }
          - Thrower
)");
  EXPECT_THROW(parallel.tick_once(), Error);
  EXPECT_EQ(probes()["a"].halts, 1);
  parallel.visit(
      [](const Node& node, int) { EXPECT_EQ(node.status(), Status::kIdle) << node.path(); });
}

// A standard exception from a tick is a bug of plugin code: the node fails (the run ends as a
// failure, exit 1) with the exception's type and message as the reason.
TEST_F(EntryTest, AStandardExceptionFromATickFailsTheNode) {
  registry.add(thrower([] { throw std::length_error("vector::reserve"); }));
  Tree tree = load("main: t\ntrees:\n  t:\n    Sequence: [AlwaysSuccess, Thrower]\n");
  EXPECT_EQ(tree.tick_once(), Status::kFailure);
  std::string reason;
  tree.visit([&](const Node& node, int) {
    if (node.type() == "Thrower") reason = node.failure_reason();
  });
  EXPECT_EQ(reason, "Thrower's code threw std::length_error: vector::reserve");
}

}  // namespace
}  // namespace antipode::bt::testing
