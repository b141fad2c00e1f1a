#!/usr/bin/env bash
# Installs the antipode SDK into a temporary prefix, builds the out-of-tree example plugin
# against it with find_package(antipode), and checks that the installed `antipode` loads it.
set -euo pipefail
build_dir="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/plugins/examples/out_of_tree" -B "$work/plugin" \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/plugin" -j2 >/dev/null
antipode="$(find "$work/prefix" -path '*/bin/antipode')"
listing="$(ANTIPODE_PLUGIN_PATH="$work/plugin/plugins" "$antipode" plugins)"
echo "$listing"
grep -q "^loaded  $work/plugin/plugins/libantipode_width_preference.so" <<<"$listing"
grep -q "provides classifier width_preference" <<<"$listing"
grep -q "provides node CountGrasps" <<<"$listing"
# The installed plugins are found beside the installed library.
grep -q "$work/prefix/lib.*/antipode/plugins/libantipode_pipeline_nodes.so" <<<"$listing"
echo "out-of-tree plugin built against the installed SDK and loaded"
