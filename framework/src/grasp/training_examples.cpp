#include "antipode/grasp/training_examples.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <string>

#include "antipode/core/error.hpp"
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

// The closing points of `hand` seen from `view` (-1: all of them).
std::vector<std::int32_t> points_seen_from(const Cloud& cloud, const Hand& hand, int view) {
  if (view < 0 || cloud.view_masks.empty()) return hand.closing_points;
  std::vector<std::int32_t> seen;
  const std::uint32_t bit = 1u << static_cast<unsigned>(view);
  for (const std::int32_t i : hand.closing_points) {
    if ((cloud.view_masks[static_cast<std::size_t>(i)] & bit) != 0) seen.push_back(i);
  }
  return seen;
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
  HandSet out{reference, set.hands, set.geometry};
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

  // One pseudo-hand per (hand, view) whose closing points are that view's; imaged together.
  std::vector<int> views = options.single_views;
  if (options.all_views) views.push_back(-1);
  HandSet images{labelled.cloud, {}, labelled.geometry};
  std::vector<std::pair<std::size_t, bool>> owner;  // hand index, positive
  for (const std::size_t h : chosen_hands(labelled, options.max_hands_per_label, random, counts)) {
    const Hand& hand = labelled.hands[h];
    const bool positive = hand.label == HandLabel::kPositive;
    for (const int view : views) {
      Hand seen = hand;
      seen.closing_points = points_seen_from(*labelled.cloud, hand, view);
      if (seen.closing_points.size() < options.min_points) continue;
      images.hands.push_back(std::move(seen));
      owner.emplace_back(h, positive);
    }
  }
  const auto descriptors =
      hand_descriptors(images, labelled.geometry, options.descriptor, options.threads);
  const std::int32_t first_group = out.next_group();
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    out.add(descriptors[i], owner[i].second,
            first_group + static_cast<std::int32_t>(owner[i].first), source);
    ++(owner[i].second ? counts.positive_examples : counts.negative_examples);
  }
  return counts;
}

}  // namespace antipode
