#include "segment_states.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace antipode::planning {

namespace {

void fill_rake_order(std::size_t steps, std::size_t lanes, std::vector<std::size_t>& order) {
  order.clear();
  order.reserve(steps);
  const std::size_t teeth = std::min(lanes, steps);
  if (teeth <= 1) {  // one tooth (or none): in order
    order.resize(steps);
    std::iota(order.begin(), order.end(), std::size_t(0));
    return;
  }
  const auto begin = [&](std::size_t t) { return t * steps / teeth; };  // tooth t's first
  const std::size_t longest = (steps + teeth - 1) / teeth;
  for (std::size_t back = 0; back < longest; ++back)
    for (std::size_t t = 0; t < teeth; ++t)
      if (begin(t) + back < begin(t + 1)) order.push_back(begin(t + 1) - 1 - back);
}

}  // namespace

std::vector<std::size_t> rake_order(std::size_t steps, std::size_t lanes) {
  std::vector<std::size_t> order;
  fill_rake_order(steps, lanes, order);
  return order;
}

void segment_states(const Eigen::Ref<const Eigen::VectorXd>& a,
                    const Eigen::Ref<const Eigen::VectorXd>& b, double resolution_rad,
                    bool include_start, std::size_t lanes, std::vector<Eigen::VectorXd>& states) {
  const auto steps = std::size_t(std::max(1.0, std::ceil((b - a).norm() / resolution_rad)));
  const std::size_t first = include_start ? 0 : 1;
  thread_local std::vector<std::size_t> order;
  fill_rake_order(steps + 1 - first, lanes, order);
  states.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    states[k] = a + (b - a) * (double(order[k] + first) / double(steps));
}

}  // namespace antipode::planning
