#!/usr/bin/env bash
# Writes the seed corpus of the fuzz targets (corpus/<reader>/seed_*): small valid and
# broken files, a few hundred bytes each. The files are checked in; run this again only
# to change the seeds. Regression files (inputs the fuzzer found, named
# regression_<what>) are kept as they are.
#   test/fuzz/make_seed_corpus.sh
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
corpus="$here/corpus"
mkdir -p "$corpus"/{pcd,off,stl,ply_obj,xyz}
rm -f "$corpus"/*/seed_*

put() { printf '%b' "$2" >"$corpus/$1"; } # put reader/seed_name 'bytes (printf %b)'

# little-endian float32: 0, 1, 0.5
F0='\x00\x00\x00\x00'
F1='\x00\x00\x80\x3f'
FH='\x00\x00\x00\x3f'

# --- pcd: checkPcdHeader + loadCloud ------------------------------------------------
xyz_header='VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n'
put pcd/seed_ascii.pcd "# .PCD v.7\n${xyz_header}WIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n0 0 0\n1 0 0\n0 1 0.5\n"
put pcd/seed_ascii_nan.pcd "${xyz_header}WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\nnan nan nan\n1 2 3\n"
put pcd/seed_organized.pcd "${xyz_header}WIDTH 2\nHEIGHT 2\nVIEWPOINT 1 2 3 1 0 0 0\nPOINTS 4\nDATA ascii\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
put pcd/seed_binary.pcd "${xyz_header}WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary\n${F0}${F0}${F0}${F1}${FH}${F1}"
put pcd/seed_binary_rgb_label.pcd "FIELDS x y z rgb label\nSIZE 4 4 4 4 4\nTYPE F F F U U\nCOUNT 1 1 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n${F1}${F0}${FH}\xff\x00\x00\x00\x07\x00\x00\x00"
put pcd/seed_double_xyz.pcd "FIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n0.5 0.25 1e3\n-1 -2 -3\n"
put pcd/seed_int16_xyz_count.pcd "FIELDS x y z normal\nSIZE 2 2 2 4\nTYPE I I I F\nCOUNT 1 1 1 3\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 -2 3 0 0 1\n"
put pcd/seed_columns_padding.pcd "COLUMNS x y z _\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 4\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n${F1}${F1}${F1}\x00\x00\x00\x00"
put pcd/seed_no_fields.pcd "SIZE 4\nTYPE F\nWIDTH 1\nPOINTS 1\nDATA ascii\n1\n"
put pcd/seed_no_xyz.pcd "FIELDS a b\nSIZE 4 4\nTYPE F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2\n"
put pcd/seed_truncated_binary.pcd "${xyz_header}WIDTH 1000\nHEIGHT 1\nPOINTS 1000\nDATA binary\n${F1}${F1}"
put pcd/seed_short_ascii.pcd "${xyz_header}WIDTH 5\nHEIGHT 1\nPOINTS 5\nDATA ascii\n1 2 3\n"
put pcd/seed_compressed_short.pcd "${xyz_header}WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary_compressed\n\x10\x00\x00\x00\x18\x00\x00\x00\x00"
put pcd/seed_text.pcd "hello, this is not a point cloud\n"
put pcd/seed_zero_points.pcd "${xyz_header}WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n"
put pcd/seed_crlf.pcd "FIELDS x y z\r\nSIZE 4 4 4\r\nTYPE F F F\r\nWIDTH 1\r\nHEIGHT 1\r\nPOINTS 1\r\nDATA ascii\r\n1 2 3\r\n"

# --- xyz: readTextCloud through loadCloud ---------------------------------------------
put xyz/seed_plain.xyz "0 0 0\n1 0 0\n0 1 0.5\n"
put xyz/seed_header_commas.xyz "x,y,z,intensity\n0.5,0.25,1e3,7\n-1,-2,-3,8\n"
put xyz/seed_survey.xyz "512345.678 4312345.123 120.456\n512346.678 4312345.123 120.456\n512345.678 4312346.123 121.456\n"
put xyz/seed_tabs_crlf.xyz "1\t2\t3\r\n4\t5\t6\r\n"
put xyz/seed_short_row.xyz "0 0 0\n1 0\n"
put xyz/seed_nan_text.xyz "nan 0 0\n1 inf 0\nabc 1 2\n"
put xyz/seed_empty_lines.xyz "\n\n# comment\n0 0 0\n"

# --- off: visfeat::readOff through loadMeshAsCloud ------------------------------------
put off/seed_tetrahedron.off "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
put off/seed_quads_comments.off "OFF # a square\n# comment line\n4 1 0\n\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 255 0 0 255\n"
put off/seed_counts_line.off "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
put off/seed_bad_index.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"
put off/seed_nan.off "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"
put off/seed_short.off "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n"
put off/seed_zero_area.off "OFF\n3 1 0\n0 0 0\n1 1 1\n2 2 2\n3 0 1 2\n"
put off/seed_no_faces.off "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"
put off/seed_huge_counts.off "OFF\n4294967295 4294967295 0\n0 0 0\n"
put off/seed_two_vertex_face.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"
put off/seed_trailing.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\nextra\n"
put off/seed_not_off.off "COFF\n1 0 0\n"

# --- stl: stlProblem + loadMeshAsCloud (VTK's reader) ---------------------------------
facet='facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n'
facet2='facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n endloop\nendfacet\n'
put stl/seed_ascii.stl "solid square\n${facet}${facet2}endsolid square\n"
put stl/seed_ascii_no_end.stl "solid t\n${facet}"
put stl/seed_ascii_nan.stl "solid t\nfacet normal 0 0 1\n outer loop\n  vertex nan 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\nendsolid t\n"
put stl/seed_ascii_two_vertices.stl "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n endloop\nendfacet\nendsolid t\n"
put stl/seed_ascii_degenerate.stl "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 1\n  vertex 2 2 2\n endloop\nendfacet\nendsolid t\n"
head80="$(printf 'binary stl%.0s' 1 2 3 4 5 6 7 8)" # 80 bytes
tri="${F0}${F0}${F1}${F0}${F0}${F0}${F1}${F0}${F0}${F0}${F1}${F0}\x00\x00"
tri2="${F0}${F0}${F1}${F1}${F0}${F0}${F1}${F1}${F0}${F0}${F1}${F0}\x00\x00"
put stl/seed_binary_one.stl "${head80}\x01\x00\x00\x00${tri}"
put stl/seed_binary_two.stl "${head80}\x02\x00\x00\x00${tri}${tri2}"
solid80="$(printf '%-80s' 'solid but binary')" # a binary STL may start with solid
put stl/seed_binary_solid_header.stl "${solid80}\x01\x00\x00\x00${tri}"
put stl/seed_binary_truncated.stl "${head80}\x05\x00\x00\x00${tri}"
put stl/seed_binary_zero.stl "${head80}\x00\x00\x00\x00"
put stl/seed_garbage.stl "not an stl at all\n"

# --- ply_obj: loadPLYFile (cloud or mesh) and loadOBJFile -----------------------------
put ply_obj/seed_cloud_ascii.ply "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
put ply_obj/seed_cloud_double_binary.ply "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n\x00\x00\x00\x00\x00\x00\xf0\x3f\x00\x00\x00\x00\x00\x00\x00\x40\x00\x00\x00\x00\x00\x00\x08\x40"
put ply_obj/seed_cloud_rgb_normals.ply "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nproperty float nx\nproperty float ny\nproperty float nz\nend_header\n0 0 0 255 0 0 0 0 1\n1 1 1 0 255 0 0 1 0\n"
put ply_obj/seed_mesh_ascii.ply "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
put ply_obj/seed_mesh_binary_be.ply "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x3f\x80\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x3f\x80\x00\x00\x00\x00\x00\x00\x03\x00\x00\x00\x00\x00\x00\x00\x01\x00\x00\x00\x02"
put ply_obj/seed_mesh_bad_index.ply "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"
put ply_obj/seed_truncated.ply "ply\nformat ascii 1.0\nelement vertex 10\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n"
put ply_obj/seed_header_only.ply "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
put ply_obj/seed_tetrahedron.obj "# tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
put ply_obj/seed_slashes_normals.obj "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\ng square\nusemtl none\nf 1/1/1 2/2/1 3/3/1 4/1/1\n"
put ply_obj/seed_negative_index.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
put ply_obj/seed_bad_index.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"
put ply_obj/seed_two_vertex_face.obj "v 0 0 0\nv 1 0 0\nf 1 2\n"
put ply_obj/seed_garbage.obj "\x7fELF not an obj\n"

echo "make_seed_corpus: $(find "$corpus" -name 'seed_*' | wc -l) seeds in $corpus"
