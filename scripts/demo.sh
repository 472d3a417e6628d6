#!/usr/bin/env bash
# End-to-end demo: builds visfeat (Release, build/), generates a sample cloud of an
# icosahedron, labels its sharp features, and tells how to look at the result.
#   scripts/demo.sh [OUTPUT_DIR]     (default: demo_output)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

out="${1:-demo_output}"
build_dir="${BUILD_DIR:-build}"
resolution=128

bash "$root/scripts/install_deps.sh"

echo "== build ($build_dir)"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
# Only what the demo runs (the tool's target is visfeat_tool, its file visfeat).
cmake --build "$build_dir" -j"$(nproc 2>/dev/null || echo 2)" \
  --target visfeat_tool visfeat_generate

mkdir -p "$out"
echo "== generate a sample cloud"
"$build_dir/tools/visfeat_generate" icosahedron "$out/icosahedron.pcd" \
  -resolution "$resolution" -seed 1
echo "== label sharp features"
"$build_dir/tools/visfeat" "$out/icosahedron.pcd" "$out/icosahedron_labeled.pcd" \
  -resolution "$resolution" -voxels "$out/icosahedron_cells.pcd"

cat <<MSG

Outputs:
  $out/icosahedron.pcd           input cloud (sampled icosahedron)
  $out/icosahedron_labeled.pcd   per point: visibility_radius, label, feature_class
  $out/icosahedron_cells.pcd     one point per voxel-band cell, same fields

View them with:
  pcl_viewer $out/icosahedron_labeled.pcd
    pcl_viewer colours by the 'label' field (one colour per component) by default;
    components are not computed yet, so colour by visibility_radius instead:
    keys: l lists the colour handlers (one per field), 0-9 switches between them
    (e.g. visibility_radius, feature_class), +/- changes the point size,
    r resets the camera, j saves a PNG snapshot, h prints help, q quits.
  pcl_viewer $out/icosahedron_cells.pcd
MSG
