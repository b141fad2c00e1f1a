// NodeRegistry: registration rules and lookups.
#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

NodeManifest manifest(std::string type, NodeCategory category, int min_children, int max_children) {
  NodeManifest made;
  made.type = std::move(type);
  made.category = category;
  made.min_children = min_children;
  made.max_children = max_children;
  made.create = [](const NodeConfig&) -> std::unique_ptr<Node> { return nullptr; };
  return made;
}

TEST(RegistryTest, HoldsTheBuiltinNodes) {
  const NodeRegistry registry = builtin_node_registry();
  for (const char* type :
       {"Sequence", "ReactiveSequence", "Fallback", "ReactiveFallback", "Parallel", "Inverter",
        "ForceSuccess", "ForceFailure", "Retry", "Repeat", "KeepRunningUntilFailure",
        "RetryUntilFailure", "Timeout", "SubTree", "SetBlackboard", "Log", "Wait", "AlwaysSuccess",
        "AlwaysFailure"}) {
    EXPECT_TRUE(registry.has(type)) << type;
  }
  const auto types = registry.types();
  EXPECT_TRUE(std::is_sorted(types.begin(), types.end()));
  EXPECT_EQ(registry.get("Retry").port("num_attempts")->type_name, "int");
  EXPECT_TRUE(registry.get("Retry").port("num_attempts")->required);
  EXPECT_EQ(registry.get("Parallel").port("success_count")->default_text, "-1");
}

TEST(RegistryTest, UnknownTypesAreSuggested) {
  const NodeRegistry registry = builtin_node_registry();
  try {
    registry.get("Fallbak");
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "unknown node 'Fallbak' (did you mean 'Fallback'?)");
  }
}

TEST(RegistryTest, RejectsBadManifests) {
  NodeRegistry registry = builtin_node_registry();
  EXPECT_THROW(registry.add(manifest("Sequence", NodeCategory::kControl, 1, -1)), Error);
  EXPECT_THROW(registry.add(manifest("", NodeCategory::kAction, 0, 0)), Error);
  EXPECT_THROW(registry.add(manifest("Leaf", NodeCategory::kAction, 0, 1)), Error);
  EXPECT_THROW(registry.add(manifest("Deco", NodeCategory::kDecorator, 0, 2)), Error);
  EXPECT_THROW(registry.add(manifest("Ctl", NodeCategory::kControl, 3, 2)), Error);
  EXPECT_THROW(registry.add(manifest("Sub", NodeCategory::kSubTree, 1, 1)), Error);
  NodeManifest no_create = manifest("NoCreate", NodeCategory::kAction, 0, 0);
  no_create.create = nullptr;
  EXPECT_THROW(registry.add(no_create), Error);
  NodeManifest reserved = manifest("Reserved", NodeCategory::kAction, 0, 0);
  reserved.ports = {input_port<int>("name", "clashes with the node's name")};
  EXPECT_THROW(registry.add(reserved), Error);
  NodeManifest twice = manifest("Twice", NodeCategory::kAction, 0, 0);
  twice.ports = {input_port<int>("a", ""), output_port<int>("a", "")};
  EXPECT_THROW(registry.add(twice), Error);
  EXPECT_NO_THROW(registry.add(manifest("Fine", NodeCategory::kControl, 0, 2)));
}

TEST(RegistryTest, PortHelpersDescribeTheirPorts) {
  const PortInfo required = input_port<double>("radius_m", "search radius");
  EXPECT_TRUE(required.required);
  EXPECT_EQ(required.direction, PortDirection::kInput);
  const PortInfo optional = input_port<double>("radius_m", 0.01, "search radius");
  EXPECT_FALSE(optional.required);
  EXPECT_EQ(optional.default_text, "0.01");
  EXPECT_EQ(std::any_cast<double>(optional.default_value), 0.01);
  const PortInfo text = input_port_text_default<std::vector<double>>("xs", "[1, 2]", "");
  EXPECT_EQ(text.default_text, "[1, 2]");
  // Typed defaults are documented as a tree would write them.
  EXPECT_EQ(input_port<std::vector<int>>("views", std::vector<int>{0, 1}, "").default_text,
            "[0, 1]");
  EXPECT_EQ(input_port<std::vector<double>>("none", std::vector<double>{}, "").default_text, "[]");
  EXPECT_EQ(input_port<std::shared_ptr<const int>>("cloud", nullptr, "").default_text, "unset");
  const PortInfo component = component_port<Classifier>("classifier", "");
  EXPECT_EQ(component.component_kind, ComponentKind::kClassifier);
  EXPECT_EQ(component.type_name, "classifier component");
  EXPECT_EQ(output_port<int>("n", "").direction, PortDirection::kOutput);
  EXPECT_TRUE(inout_port<int>("n", "").required);
}

using DefaultTest = TreeTest;

TEST_F(DefaultTest, TextDefaultsMayReadAnEntry) {
  NodeManifest reader;
  reader.type = "ReadDefault";
  reader.ports = {input_port_text_default<int>("in", "{n}", "defaults to {n}"),
                  input_port_text_default<std::vector<double>>("xs", "[1, 2]", "")};
  reader.create = [](const NodeConfig& config) -> std::unique_ptr<Node> {
    struct Reader : SyncActionNode {
      using SyncActionNode::SyncActionNode;
      Status tick() override {
        const bool ok = get_input<int>("in") == 4 &&
                        get_input<std::vector<double>>("xs") == std::vector<double>{1, 2};
        return ok ? Status::kSuccess : Status::kFailure;
      }
    };
    return std::make_unique<Reader>(config);
  };
  registry.add(reader);
  Tree tree = load(R"(
main: t
trees:
  t:
    Sequence:
      - WriteInt: { value: 4, out: "{n}" }
      - ReadDefault: {}
)");
  EXPECT_EQ(tree.tick_once(), Status::kSuccess);
}

}  // namespace
}  // namespace antipode::bt::testing
