#pragma once
/// @file
/// Where antipode's shipped trees, models, robots and scenes are, so that commands and trees
/// work from any folder: an installed antipode keeps them in <prefix>/share/antipode (found
/// from where libantipode.so is, wherever the prefix was), a build tree in its source tree.

#include <string>

namespace antipode {

/// The folder holding the shipped `trees/`, `models/`, `robots/` and `scenes/`: the
/// installation's share/antipode, else the source tree this libantipode was built from;
/// "" when neither exists.
std::string shipped_data_dir();

/// `path` as given when it is empty, absolute or present from the working directory; else
/// the shipped file of that relative path when there is one (`trees/detect.yaml` ->
/// <prefix>/share/antipode/trees/detect.yaml); else as given, so that the reader's own
/// "cannot open" error names it.
std::string resolve_shipped(const std::string& path);

}  // namespace antipode
