#include "antipode/geometry/sample_hands.hpp"

#include <memory>

namespace antipode {

HandSet sample_hands(const Cloud& cloud, const HandSamplingOptions& options,
                     const RandomStream& random, HandSearchStats* stats) {
  options.search.validate();
  cloud.validate();
  std::shared_ptr<Cloud> prepared;
  if (cloud.view_origins_m.empty()) {
    Cloud seen = cloud;
    seen.view_origins_m.push_back(options.default_view_origin_m);
    prepared = std::make_shared<Cloud>(preprocess(seen, options.preprocess));
  } else {
    prepared = std::make_shared<Cloud>(preprocess(cloud, options.preprocess));
  }
  HandSearchResult result = search_hands(*prepared, options.search, random);
  if (stats != nullptr) *stats = result.stats;
  return HandSet{std::move(prepared), std::move(result.hands)};
}

}  // namespace antipode
