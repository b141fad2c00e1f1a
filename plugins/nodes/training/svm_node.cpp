#include "svm_node.hpp"

#include <cmath>
#include <string>

#include "kernel_names.hpp"

namespace antipode::training {
namespace {

bool positive(double value) { return value > 0.0 && std::isfinite(value); }

}  // namespace

std::vector<bt::PortInfo> SvmNode::svm_ports() {
  const SvmTrainingOptions d;
  return {bt::input_port<std::vector<std::string>>(
              "kernels", std::vector<std::string>{"poly"},
              "kernel families tried by cross-validation: poly, rbf (Gaussian)"),
          bt::input_port<int>("degree", d.degree, "polynomial kernel degree"),
          bt::input_port<std::vector<double>>("c_values", d.c_values,
                                              "soft-margin costs tried by cross-validation"),
          bt::input_port<std::vector<double>>("gamma_values", d.gamma_values,
                                              "kernel scales tried; empty = 1 / components"),
          bt::input_port<int>("components", static_cast<int>(d.pca_components),
                              "PCA components the descriptors are reduced to"),
          bt::input_port<int>("folds", d.folds,
                              "cross-validation folds (TrainClassifier also takes 0: none)"),
          bt::input_port<std::string>("folds_by", std::string("scene"),
                                      "what a fold keeps together: scene (objects held out), hand "
                                      "(its C1, C2 and C12 descriptors) or example (the paper)"),
          bt::input_port<int>("cache_mib", static_cast<int>(d.cache_mib),
                              "kernel row cache of each solver in MiB (a fold per worker)"),
          bt::input_port<double>("positive_weight", d.positive_weight,
                                 "C of grasps over C of non-grasps (above 1: a missed grasp costs "
                                 "more)"),
          bt::input_port<int>("threads", 0, "workers (0: all cores)")};
}

SvmTrainingOptions SvmNode::read_svm_options() const {
  SvmTrainingOptions o;
  try {
    o.kernels = kernel_types(get_input<std::vector<std::string>>("kernels"));
  } catch (const Error& e) {
    fail("kernels", e.message());
  }
  o.degree = get_input<int>("degree");
  if (o.degree < 1 || o.degree > 10) fail("degree", "degree must be in [1, 10]");
  o.c_values = get_input<std::vector<double>>("c_values");
  if (o.c_values.empty()) fail("c_values", "c_values is empty; give at least one C");
  for (const double c : o.c_values) {
    if (!positive(c)) fail("c_values", "every C must be positive");
  }
  o.gamma_values = get_input<std::vector<double>>("gamma_values");
  for (const double g : o.gamma_values) {
    if (!positive(g)) fail("gamma_values", "every gamma must be positive");
  }
  const int components = get_input<int>("components");
  if (components < 1) fail("components", "components must be at least 1");
  o.pca_components = static_cast<std::size_t>(components);
  o.folds = get_input<int>("folds");
  if (o.folds < 0 || o.folds == 1) {
    fail("folds", "folds must be 0 (no cross-validation) or at least 2");
  }
  try {
    o.folds_by = fold_unit(get_input<std::string>("folds_by"));
  } catch (const Error& e) {
    fail("folds_by", e.message());
  }
  const int cache_mib = get_input<int>("cache_mib");
  if (cache_mib < 1) fail("cache_mib", "cache_mib must be at least 1");
  o.cache_mib = static_cast<std::size_t>(cache_mib);
  o.positive_weight = get_input<double>("positive_weight");
  if (!positive(o.positive_weight)) fail("positive_weight", "positive_weight must be positive");
  o.threads = get_input<int>("threads");
  if (o.threads < 0) fail("threads", "threads must be 0 (all cores) or more");
  o.seed = random().next_u64();
  return o;
}

}  // namespace antipode::training
