#include "antipode/grasp/training_examples.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <string>

#include "antipode/core/error.hpp"
#include "antipode/core/view_selection.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "antipode/grasp/svm_model.hpp"

namespace antipode {
namespace {

template <typename Work>
void in_arena(int threads, Work&& work) {
  if (threads < 0) throw Error("threads must be >= 0, got " + std::to_string(threads));
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute(work);
}

// The closing points of `hand` seen from the view whose points `new_index` renumbers (see
// points_of_views), in that view's numbering.
std::vector<std::int32_t> points_seen(const Hand& hand,
                                      const std::vector<std::int32_t>& new_index) {
  std::vector<std::int32_t> seen;
  for (const std::int32_t i : hand.closing_points) {
    const std::int32_t j = new_index[static_cast<std::size_t>(i)];
    if (j >= 0) seen.push_back(j);
  }
  return seen;
}

// What one view (or all of them) shows of the chosen hands, as the classifier would get it:
// a hand set on the points of that view alone, so that descriptors (normals included) are
// computed from what that view saw.
struct ViewImages {
  HandSet hands;
  std::vector<std::size_t> owner;  // per image: index into the chosen hands
};

ViewImages view_images(const HandSet& labelled, const std::vector<std::size_t>& chosen, int view,
                       std::size_t min_points) {
  ViewImages out;
  out.hands.geometry = labelled.geometry;
  std::vector<std::int32_t> new_index;
  if (view < 0) {
    out.hands.cloud = labelled.cloud;
  } else {
    out.hands.cloud =
        std::make_shared<const Cloud>(points_of_views(*labelled.cloud, {view}, &new_index));
  }
  for (std::size_t c = 0; c < chosen.size(); ++c) {
    Hand seen = labelled.hands[chosen[c]];
    if (view >= 0) {
      seen.closing_points = points_seen(seen, new_index);
      seen.sample_index = -1;  // an index into the two-view cloud
    }
    if (seen.closing_points.size() < min_points) continue;
    out.hands.hands.push_back(std::move(seen));
    out.owner.push_back(c);
  }
  return out;
}

void check_views(const Cloud& cloud, const ExampleOptions& options) {
  for (const int view : options.single_views) {
    if (view < 0 || view >= 32 || static_cast<std::size_t>(view) >= cloud.view_origins_m.size()) {
      throw Error("training examples: view " + std::to_string(view) +
                  " is not in the cloud (it has " + std::to_string(cloud.view_origins_m.size()) +
                  " view(s))");
    }
  }
  if (options.single_views.empty() && !options.all_views) {
    throw Error("training examples: no view selected for descriptors");
  }
}

void adopt_or_check(TrainingSet& out, const HandImageOptions& descriptor,
                    const HandGeometry& geometry) {
  if (out.empty()) {
    out.descriptor = descriptor;
    out.geometry = geometry;
    out.dimension = descriptor.descriptor_size();
    return;
  }
  if (!SvmDescriptorSpec::of(out.descriptor, out.geometry)
           .matches(SvmDescriptorSpec::of(descriptor, geometry))) {
    throw Error(
        "training examples: these hands' descriptors (or hand geometry) differ from the "
        "training set's; collect one set per descriptor and hand");
  }
}

// The hands of each label that make examples: all, or max_per_label drawn at random.
std::vector<std::size_t> chosen_hands(const HandSet& set, std::size_t max_per_label,
                                      RandomStream& random, ExampleCounts& counts) {
  std::vector<std::size_t> chosen;
  for (const HandLabel label : {HandLabel::kPositive, HandLabel::kNegative}) {
    std::vector<std::size_t> hands;
    for (std::size_t h = 0; h < set.hands.size(); ++h) {
      if (set.hands[h].label == label) hands.push_back(h);
    }
    if (max_per_label > 0 && hands.size() > max_per_label) {
      for (std::size_t i = 0; i < max_per_label; ++i) {  // partial Fisher-Yates
        std::swap(hands[i], hands[i + random.below(hands.size() - i)]);
      }
      counts.dropped_hands += hands.size() - max_per_label;
      hands.resize(max_per_label);
    }
    (label == HandLabel::kPositive ? counts.positive_hands : counts.negative_hands) = hands.size();
    chosen.insert(chosen.end(), hands.begin(), hands.end());
  }
  std::sort(chosen.begin(), chosen.end());
  counts.skipped_hands = set.hands.size() - chosen.size() - counts.dropped_hands;
  return chosen;
}

}  // namespace

HandSet with_closing_points_in(const HandSet& set, std::shared_ptr<const Cloud> reference,
                               int threads) {
  if (reference == nullptr) throw Error("closing points: no reference cloud");
  reference->validate();
  // Another cloud: the objects' point indices would name other points, so they stay behind.
  HandSet out{reference, set.hands, set.geometry, set.support, {}, set.scores};
  for (Hand& hand : out.hands) hand.object = -1;
  const HandBody body = make_hand_body(set.geometry, 0.0);
  in_arena(threads, [&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.hands.size(), 16),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t h = range.begin(); h != range.end(); ++h) {
                          Hand& hand = out.hands[h];
                          hand.closing_points =
                              points_in_closing_region(body, hand.X_FrameHand, reference->points_m);
                          hand.sample_index = -1;
                        }
                      });
  });
  return out;
}

ExampleCounts add_examples(const HandSet& labelled, const ExampleOptions& options,
                           std::int32_t source, RandomStream random, TrainingSet& out) {
  ExampleCounts counts;
  if (labelled.hands.empty()) return counts;
  if (labelled.cloud == nullptr) throw Error("training examples: the hand set has no cloud");
  check_views(*labelled.cloud, options);
  adopt_or_check(out, options.descriptor, labelled.geometry);

  // Per view, the descriptors of the chosen hands it shows; then examples hand by hand.
  std::vector<int> views = options.single_views;
  if (options.all_views) views.push_back(-1);
  const std::vector<std::size_t> chosen =
      chosen_hands(labelled, options.max_hands_per_label, random, counts);
  std::vector<std::vector<const std::vector<float>*>> per_hand(chosen.size());
  std::vector<std::vector<std::vector<float>>> descriptors;
  descriptors.reserve(views.size());
  for (const int view : views) {
    const ViewImages images = view_images(labelled, chosen, view, options.min_points);
    descriptors.push_back(
        hand_descriptors(images.hands, labelled.geometry, options.descriptor, options.threads));
    for (std::size_t i = 0; i < images.owner.size(); ++i) {
      per_hand[images.owner[i]].push_back(&descriptors.back()[i]);
    }
  }
  const std::int32_t first_group = out.next_group();
  for (std::size_t c = 0; c < chosen.size(); ++c) {
    const bool positive = labelled.hands[chosen[c]].label == HandLabel::kPositive;
    for (const std::vector<float>* descriptor : per_hand[c]) {
      out.add(*descriptor, positive, first_group + static_cast<std::int32_t>(chosen[c]), source);
      ++(positive ? counts.positive_examples : counts.negative_examples);
    }
  }
  return counts;
}

}  // namespace antipode
