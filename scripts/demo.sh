#!/usr/bin/env bash
# End-to-end demo: builds visfeat (Release, build/), generates a sample cloud of a box
# with a cylindrical through-hole (8 corners, 12 straight and 2 circular edges, 7
# faces), labels its vertices, edges and faces, writes the topology graph, renders
# pictures of the result, and tells how to look at it.
#   scripts/demo.sh [OUTPUT_DIR]     (default: demo_output)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

out="${1:-demo_output}"
build_dir="${BUILD_DIR:-build}"
resolution=256
model=box_with_hole

bash "$root/scripts/install_deps.sh"

echo "== build ($build_dir)"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
# The libraries, every tool (the tool's target is visfeat_tool, its file visfeat) and
# the sample: all that README's commands and `cmake --install` need, but not the
# tests (scripts/test.sh builds those).
cmake --build "$build_dir" -j"$(nproc 2>/dev/null || echo 2)" \
  --target visfeat_tool visfeat_generate visfeat_benchmark visfeat_eval label_features

mkdir -p "$out"
echo "== generate a sample cloud"
"$build_dir/tools/visfeat_generate" "$model" "$out/$model.pcd" \
  -resolution "$resolution" -seed 1 -truth "$out/${model}_truth.json"
echo "== label sharp features"
"$build_dir/tools/visfeat" "$out/$model.pcd" "$out/${model}_labeled.pcd" \
  -resolution "$resolution" -voxels "$out/${model}_cells.pcd" \
  -graph "$out/${model}_graph.json"
# The same run again for the DOT graph and the pictures. VTK (Debian's is built for
# X only) needs a display even to render offscreen: the caller's, else a private
# virtual one (xvfb-run, installed by install_deps.sh).
display_cmd=()
if [ -z "${DISPLAY:-}" ]; then
  display_cmd=(xvfb-run -a)
fi
"${display_cmd[@]}" "$build_dir/tools/visfeat" "$out/$model.pcd" \
  "$out/${model}_labeled.pcd" -resolution "$resolution" -q \
  -graph "$out/${model}_graph.dot" \
  -png "$out/${model}.png" -png_radius "$out/${model}_radius.png"
echo "== pictures: $out/${model}.png $out/${model}_radius.png"

cat <<MSG

Outputs:
  $out/$model.pcd
      input cloud (x y z, curve_distance = distance to the true sharp curves,
      face_id); its truth in $out/${model}_truth.json
  $out/${model}_labeled.pcd
      per point: visibility_radius, label (region id), feature_class (1 vertex,
      2 edge, 3 face)
  $out/${model}_cells.pcd
      one point per voxel-band cell, same fields
  $out/${model}_graph.json, $out/${model}_graph.dot
      topology graph (regions, arcs, grid, parameters); DOT for GraphViz (dot -Tpng)
  $out/${model}.png
      picture: vertices red, edges blue, faces pastel, with the topology graph
      (spheres at region centroids, arcs)
  $out/${model}_radius.png
      picture: visibility radius, blue (small) to red (cap)

View them with:
  pcl_viewer $out/${model}_labeled.pcd
    pcl_viewer colours by the 'label' field (one colour per region) by default;
    keys: 1 random colours, then one key per field in file order: 2-4 x y z,
    5 curve_distance, 6 face_id, 7 visibility_radius, 8 label, 9 feature_class
    (l lists them); +/- changes the point size, r resets the camera,
    j saves a PNG snapshot, h prints help, q quits.
  pcl_viewer $out/${model}_cells.pcd
MSG
