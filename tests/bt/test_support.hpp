#pragma once
// Test node types, a fake component source and load helpers shared by the bt tests.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "antipode/bt/bt.hpp"
#include "antipode/plugin/component_source.hpp"

namespace antipode::bt::testing {

// Counters a Scripted node updates, keyed by its `id` port.
struct Probe {
  int ticks = 0;
  int halts = 0;
  std::vector<Status> returned;
};

// The probes of the current test; cleared by TreeTest's constructor.
std::map<std::string, Probe>& probes();

// An action returning the statuses of its `script` port in turn (the last one repeats),
// counting ticks and halts in probes()[id].
class Scripted : public Node {
 public:
  explicit Scripted(const NodeConfig& config);
  static NodeManifest manifest();

 protected:
  Status tick() override;
  void halt() override;

 private:
  std::string id_;
  std::vector<Status> script_;
  std::size_t next_ = 0;
};

// Writes `value` (int) to output `out`.
class WriteInt : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Reads input `in` (int) and fails unless it equals `expect`.
class ReadInt : public ConditionNode {
 public:
  using ConditionNode::ConditionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Reads input `in` as a list of double and writes their sum to `sum`.
class SumList : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Writes a std::shared_ptr<const std::vector<int>> to `out` (a large value by pointer).
class MakeBig : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Reads input `in` (written by MakeBig) and writes its size to `size`.
class ReadBig : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Writes three draws of random() to `out` (list of double).
class Draw : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Uses component port `sampler` and writes the sampler's `samples` parameter to `out`.
class UseSampler : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Fails with a reason.
class FailWithReason : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// A sampler whose only parameter is `samples`.
class FakeSampler : public Sampler {
 public:
  explicit FakeSampler(int samples) : samples(samples) {}
  HandSet sample(const Cloud&, const RandomStream&, const StopToken&) const override { return {}; }
  int samples;
};

// Creates "fake_sampler" (Sampler) and "fake_classifier" (Classifier) components.
class FakeComponentSource : public ComponentSource {
 public:
  std::vector<std::string> component_types() const override;
  std::optional<ComponentKind> kind_of(const std::string& type) const override;
  std::shared_ptr<Component> create(const std::string& type,
                                    const Parameters& params) const override;
  mutable int created = 0;
};

// The built-in nodes plus the test nodes above.
NodeRegistry test_registry();

// Records observed status changes as "Type:FROM->TO".
class Recorder : public TreeObserver {
 public:
  void on_status_change(const Node& node, Status previous, Status current,
                        std::chrono::steady_clock::time_point when) override;
  std::vector<std::string> events;
};

// Loads and validates YAML text with the test registry and component source.
class TreeTest : public ::testing::Test {
 protected:
  TreeTest();
  Tree load(const std::string& yaml, std::uint64_t seed = 0);
  // what() of the Error validation throws ("" when it does not throw).
  std::string validation_error(const std::string& yaml);
  // what() of the Error loading throws ("" when it does not throw).
  std::string load_error(const std::string& yaml);

  NodeRegistry registry;
  FakeComponentSource components;
  LoadOptions options;
  std::vector<std::string> log;
};

}  // namespace antipode::bt::testing
