#!/usr/bin/env bash
# Installs the antipode SDK into a temporary prefix, checks that it carries no method
# internals (no antipode/grasp headers, no SVM symbols exported by libantipode), runs the
# installed detection tree from an empty folder, builds the out-of-tree example plugin
# against it with find_package(antipode), checks that the installed `antipode` loads it,
# and runs the example's tree on a cloud (argument 3), whose written hands carry the
# plugin's own rejection reason.
set -euo pipefail
build_dir="$1"
source_dir="$2"
cloud="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
if find "$work/prefix/include" -path '*antipode/grasp*' | grep -q .; then
  echo "the SDK installs the method's headers (antipode/grasp)" >&2
  exit 1
fi
library="$(find "$work/prefix" -name 'libantipode.so' | head -n 1)"
if nm -D --defined-only "$library" | c++filt | grep -i 'svm\|hand_image\|antipodal'; then
  echo "libantipode exports the method's symbols (above)" >&2
  exit 1
fi
cmake -S "$source_dir/plugins/examples/out_of_tree" -B "$work/plugin" \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/plugin" -j2 >/dev/null
antipode="$(find "$work/prefix" -path '*/bin/antipode')"
# The installation runs its own detection tree, with its shipped model, from an empty folder.
mkdir "$work/empty"
(cd "$work/empty" && "$antipode" detect "$cloud" --out grasps.json)
grep -q '"frame"' "$work/empty/grasps.json"
test -f "$work/prefix/share/antipode/models/hog_svm.model"
listing="$(ANTIPODE_PLUGIN_PATH="$work/plugin/plugins" "$antipode" plugins)"
echo "$listing"
grep -q "^loaded  $work/plugin/plugins/libantipode_width_preference.so" <<<"$listing"
grep -q "provides classifier width_preference" <<<"$listing"
grep -q "provides node CountGrasps" <<<"$listing"
for type in "sampler every_point" "selector best_score" "planner never_reaches" "cell empty_cell"; do
  grep -q "provides $type" <<<"$listing"
done
# The installed plugins are found beside the installed library, and indexed.
test -f "$(dirname "$library")/antipode/plugins/antipode_plugins.index"
grep -q "^loaded  $work/prefix/lib.*/antipode/plugins/libantipode_pipeline_nodes.so" <<<"$listing"
# ... and not shadowed by the plugins of the build tree the SDK was installed from.
if grep -q "^shadowed  $work/prefix" <<<"$listing"; then exit 1; fi
# Its tree runs with the installed host and plugins.
run="$(ANTIPODE_PLUGIN_PATH="$work/plugin/plugins" "$antipode" run \
  "$source_dir/plugins/examples/out_of_tree/width_preference.yaml" --set cloud_file="$cloud" \
  --set grasps_file="$work/hands.json")"
echo "$run"
grep -Eq "width_preference labelled [0-9]+ hands as grasps" <<<"$run"
# The plugin's own rejection reason reaches the written hands.
grep -q '"rejection": "width far from the preferred"' "$work/hands.json"
echo "out-of-tree plugin built against the installed SDK, loaded and run"
