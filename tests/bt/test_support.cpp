#include "test_support.hpp"

#include <numeric>

namespace antipode::bt::testing {
namespace {

Status parse_status(const std::string& text) {
  if (text == "RUNNING") return Status::kRunning;
  if (text == "SUCCESS") return Status::kSuccess;
  if (text == "FAILURE") return Status::kFailure;
  throw Error("bad scripted status '" + text + "'");
}

NodeManifest leaf(std::string type, std::vector<PortInfo> ports,
                  NodeCategory category = NodeCategory::kAction) {
  NodeManifest manifest;
  manifest.type = std::move(type);
  manifest.category = category;
  manifest.ports = std::move(ports);
  manifest.summary = "test node";
  return manifest;
}

}  // namespace

std::map<std::string, Probe>& probes() {
  static std::map<std::string, Probe> all;
  return all;
}

Scripted::Scripted(const NodeConfig& config) : Node(config) {
  id_ = get_input<std::string>("id");
  for (const auto& text : get_input<std::vector<std::string>>("script")) {
    script_.push_back(parse_status(text));
  }
}

NodeManifest Scripted::manifest() {
  return leaf("Scripted",
              {input_port<std::string>("id", "probe name"),
               input_port<std::vector<std::string>>("script", std::vector<std::string>{"SUCCESS"},
                                                    "statuses returned in turn")});
}

Status Scripted::tick() {
  Probe& probe = probes()[id_];
  ++probe.ticks;
  const Status status = script_[std::min(next_, script_.size() - 1)];
  ++next_;
  probe.returned.push_back(status);
  return status;
}

void Scripted::halt() { ++probes()[id_].halts; }

NodeManifest WriteInt::manifest() {
  return leaf("WriteInt",
              {input_port<int>("value", "the value"), output_port<int>("out", "where it goes")});
}

Status WriteInt::tick() {
  set_output("out", get_input<int>("value"));
  return Status::kSuccess;
}

NodeManifest ReadInt::manifest() {
  return leaf("ReadInt",
              {input_port<int>("in", "the value read"), input_port<int>("expect", 0, "wanted")},
              NodeCategory::kCondition);
}

Status ReadInt::tick() {
  return get_input<int>("in") == get_input<int>("expect") ? Status::kSuccess : Status::kFailure;
}

NodeManifest SumList::manifest() {
  return leaf("SumList", {input_port<std::vector<double>>("in", "numbers"),
                          output_port<double>("sum", "their sum")});
}

Status SumList::tick() {
  const auto& numbers = get_input_ref<std::vector<double>>("in");
  set_output("sum", std::accumulate(numbers.begin(), numbers.end(), 0.0));
  return Status::kSuccess;
}

NodeManifest MakeBig::manifest() {
  return leaf("MakeBig", {output_port<std::shared_ptr<const std::vector<int>>>("out", "data")});
}

Status MakeBig::tick() {
  set_output("out", std::make_shared<const std::vector<int>>(1000, 7));
  return Status::kSuccess;
}

NodeManifest ReadBig::manifest() {
  return leaf("ReadBig", {input_port<std::shared_ptr<const std::vector<int>>>("in", "data"),
                          output_port<int>("size", "its size")});
}

Status ReadBig::tick() {
  const auto& data = get_input_ref<std::shared_ptr<const std::vector<int>>>("in");
  set_output("size", static_cast<int>(data->size()));
  return Status::kSuccess;
}

NodeManifest Draw::manifest() {
  return leaf("Draw", {output_port<std::vector<double>>("out", "three uniform draws")});
}

Status Draw::tick() {
  RandomStream stream = random();
  set_output("out", std::vector<double>{stream.uniform(), stream.uniform(), stream.uniform()});
  return Status::kSuccess;
}

NodeManifest UseSampler::manifest() {
  return leaf("UseSampler", {component_port<Sampler>("sampler", "the sampler"),
                             output_port<int>("out", "its samples parameter")});
}

Status UseSampler::tick() {
  set_output("out", dynamic_cast<FakeSampler&>(component<Sampler>("sampler")).samples);
  return Status::kSuccess;
}

NodeManifest FailWithReason::manifest() {
  return leaf("FailWithReason", {input_port<std::string>("reason", "why")});
}

Status FailWithReason::tick() {
  set_failure_reason(get_input<std::string>("reason"));
  return Status::kFailure;
}

std::vector<std::string> FakeComponentSource::component_types() const {
  return {"fake_sampler", "fake_classifier"};
}

std::optional<ComponentKind> FakeComponentSource::kind_of(const std::string& type) const {
  if (type == "fake_sampler") return ComponentKind::kSampler;
  if (type == "fake_classifier") return ComponentKind::kClassifier;
  return std::nullopt;
}

std::shared_ptr<Component> FakeComponentSource::create(const std::string& type,
                                                       const Parameters& params) const {
  if (type != "fake_sampler") throw Error("cannot make '" + type + "' in tests");
  int samples = params.get<int>("samples", 100);
  if (params.has("extra")) {  // a nested parameter: `extra: { add, more }` add to samples
    const Parameters extra = params.child("extra");
    samples += extra.get<int>("add", 0) + extra.get<int>("more", 0);
    extra.reject_unknown();
  }
  params.reject_unknown();
  ++created;
  return std::make_shared<FakeSampler>(samples);
}

NodeRegistry test_registry() {
  NodeRegistry registry = builtin_node_registry();
  registry.register_node<Scripted>();
  registry.register_node<WriteInt>();
  registry.register_node<ReadInt>();
  registry.register_node<SumList>();
  registry.register_node<MakeBig>();
  registry.register_node<ReadBig>();
  registry.register_node<Draw>();
  registry.register_node<UseSampler>();
  registry.register_node<FailWithReason>();
  return registry;
}

void Recorder::on_status_change(const Node& node, Status previous, Status current,
                                std::chrono::steady_clock::time_point) {
  events.push_back(node.name() + ":" + to_string(previous) + "->" + to_string(current));
}

TreeTest::TreeTest() : registry(test_registry()) {
  probes().clear();
  options.registry = &registry;
  options.components = &components;
}

Tree TreeTest::load(const std::string& yaml, std::uint64_t seed) {
  LoadOptions with_seed = options;
  with_seed.seed = seed;
  Tree tree = load_tree_string(yaml, "trees/t.yaml", with_seed);
  tree.set_log_sink([this](const Node&, const std::string& message) { log.push_back(message); });
  return tree;
}

std::string TreeTest::validation_error(const std::string& yaml) {
  try {
    validate_tree_string(yaml, "trees/t.yaml", options);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

std::string TreeTest::load_error(const std::string& yaml) {
  try {
    load_tree_string(yaml, "trees/t.yaml", options);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

}  // namespace antipode::bt::testing
