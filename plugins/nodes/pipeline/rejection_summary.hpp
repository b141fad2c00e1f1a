#pragma once
// "12 clustered, 3 in collision, ...": how many hands of a set each reason dropped, for the
// nodes' log lines and failure reasons.

#include <string>

#include "antipode/interfaces/hand_set.hpp"

namespace antipode::pipeline {

/// The count of each rejection among `hands`, most frequent first (ties by name); hands
/// without a rejection are counted as "none" when `count_kept`, else left out. "no hands"
/// when nothing is counted.
std::string rejection_summary(const HandSet& hands, bool count_kept = true);

}  // namespace antipode::pipeline
