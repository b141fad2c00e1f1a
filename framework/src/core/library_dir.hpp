#pragma once
// The folder holding this libantipode.so, from the dynamic loader: installed files lie
// relative to it, wherever the installation's prefix is.

#include <filesystem>

namespace antipode::detail {

/// "" when the loader cannot say.
std::filesystem::path library_dir();

}  // namespace antipode::detail
