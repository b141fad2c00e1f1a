// The complete examples in docs/trees.md (YAML blocks with a `main`) validate and run.
#include <fstream>
#include <sstream>

#include "test_support.hpp"

namespace antipode::bt::testing {
namespace {

std::vector<std::string> yaml_examples() {
  std::ifstream in(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/docs/trees.md");
  std::vector<std::string> blocks;
  std::string line;
  std::string block;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!inside && line == "```yaml") {
      inside = true;
      block.clear();
    } else if (inside && line == "```") {
      inside = false;
      if (block.find("\nmain:") != std::string::npos || block.rfind("main:", 0) == 0) {
        blocks.push_back(block);
      }
    } else if (inside) {
      block += line + "\n";
    }
  }
  return blocks;
}

// Stand-ins for the plugin nodes the examples use.
class SampleHands : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest() {
    NodeManifest made;
    made.type = "SampleHands";
    made.ports = {component_port<Sampler>("sampler", ""),
                  input_port<std::shared_ptr<const Cloud>>("cloud", ""),
                  output_port<HandSetPtr>("hands", "")};
    return made;
  }

 protected:
  Status tick() override {
    set_output("hands", std::make_shared<const HandSet>());
    return Status::kSuccess;
  }
};

class Compute : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest() {
    NodeManifest made;
    made.type = "Compute";
    made.ports = {input_port<int>("factor", ""), output_port<int>("out", "")};
    return made;
  }

 protected:
  Status tick() override {
    set_output("out", 2 * get_input<int>("factor"));
    return Status::kSuccess;
  }
};

class DocSource : public FakeComponentSource {
 public:
  std::vector<std::string> component_types() const override { return {"antipodal_sampler"}; }
  std::optional<ComponentKind> kind_of(const std::string& type) const override {
    if (type == "antipodal_sampler") return ComponentKind::kSampler;
    return std::nullopt;
  }
  std::shared_ptr<Component> create(const std::string&, const Parameters& params) const override {
    return std::make_shared<FakeSampler>(params.get<int>("samples", 1));
  }
};

TEST(DocsTest, CompleteExamplesValidateAndRun) {
  NodeRegistry registry = test_registry();
  registry.register_node<SampleHands>();
  registry.register_node<Compute>();
  DocSource source;
  LoadOptions options;
  options.registry = &registry;
  options.components = &source;
  const auto examples = yaml_examples();
  ASSERT_GE(examples.size(), 2u);
  for (const auto& yaml : examples) {
    SCOPED_TRACE(yaml);
    EXPECT_NO_THROW(validate_tree_string(yaml, "docs/trees.md", options));
    Tree tree = load_tree_string(yaml, "docs/trees.md", options);
    tree.set_log_sink([](const Node&, const std::string&) {});
    tree.blackboard().set("cloud", std::make_shared<const Cloud>());
    EXPECT_EQ(tree.tick_while_running(), Status::kSuccess);
  }
}

}  // namespace
}  // namespace antipode::bt::testing
