#pragma once
// A component source for the tree fuzz targets: one type, "fake" (a sampler), whose factory
// reads a few parameters of different types as a real plugin does, so that bad values in a
// tree or a --set reach the parameter conversions.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "antipode/plugin/component_source.hpp"

namespace antipode::fuzz {

class FakeSampler final : public Sampler {
 public:
  explicit FakeSampler(const Parameters& params) {
    params.get<int>("samples", 1);
    params.get<double>("radius_m", 0.1);
    params.get<std::string>("mode", "auto");
    params.get<std::vector<double>>("point", {});
    params.child("box").get<std::vector<double>>("min", {});
    params.reject_unknown();
  }
  HandSet sample(const Cloud&, const RandomStream&, const StopToken&) const override { return {}; }
};

class FakeSource final : public ComponentSource {
 public:
  std::vector<std::string> component_types() const override { return {"fake"}; }
  std::optional<ComponentKind> kind_of(const std::string& type) const override {
    if (type == "fake") return ComponentKind::kSampler;
    return std::nullopt;
  }
  std::shared_ptr<Component> create(const std::string&, const Parameters& params) const override {
    return std::make_shared<FakeSampler>(params);
  }
};

}  // namespace antipode::fuzz
