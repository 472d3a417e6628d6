# Smoke test of the command-line tools, run by ctest as
#   cmake -DVISFEAT=<visfeat> -DGENERATE=<visfeat_generate> -DWORK_DIR=<dir> -P smoke_test.cmake
# 1. visfeat_generate cube -> visfeat -voxels: exit codes, PCD headers (fields, POINTS);
#    -paper_noise: opacity 3 on the summary line and in the graph JSON;
#    every CAD model of visfeat_generate with its -truth JSON (counts); a -mesh PLY
#    and an -organized view (headers).
# 2. .ply input (double coordinates, upper-case extension) and an input that already has
#    a label field.
# Bad inputs have a ctest each (bad_input_test.cmake); graphs, meshes and the automatic
# resolution are checked by end_to_end_test.cmake.

cmake_minimum_required(VERSION 3.19) # string(JSON); policies NEW (CMP0053)

include("${CMAKE_CURRENT_LIST_DIR}/script_test_common.cmake")
require_definitions(smoke_test.cmake VISFEAT GENERATE WORK_DIR)

fresh_directory("${WORK_DIR}")

function(expect_success name)
  run(${name} ${ARGN})
  if(NOT ${name}_rc EQUAL 0)
    report_failure("${name}: exit code ${${name}_rc}\n  ${ARGN}\n${${name}_out}")
  else()
    message(STATUS "ok: ${name}")
  endif()
  set(${name}_out "${${name}_out}" PARENT_SCOPE)
endfunction()

# The fields and POINTS of a PCD file, from its header only (binary data follows DATA).
function(read_pcd_header file fields_var points_var)
  set(${fields_var} "" PARENT_SCOPE)
  set(${points_var} "" PARENT_SCOPE)
  if(NOT EXISTS "${file}")
    report_failure("${file} was not written")
    return()
  endif()
  file(READ "${file}" head LIMIT 2048)
  string(FIND "${head}" "\nDATA " data_pos)
  if(data_pos LESS 0)
    report_failure("${file}: no DATA line in the first 2048 bytes")
    return()
  endif()
  string(SUBSTRING "${head}" 0 ${data_pos} header)
  string(REGEX MATCH "\nFIELDS ([^\n]*)" _ "${header}")
  set(fields "${CMAKE_MATCH_1}")
  string(REGEX MATCH "\nPOINTS ([0-9]+)" _ "${header}")
  set(points "${CMAKE_MATCH_1}")
  string(STRIP "${fields}" fields)
  set(${fields_var} "${fields}" PARENT_SCOPE)
  set(${points_var} "${points}" PARENT_SCOPE)
endfunction()

function(expect_header file expected_fields expected_points)
  read_pcd_header("${file}" fields points)
  if(NOT fields STREQUAL expected_fields)
    report_failure("${file}: FIELDS '${fields}', expected '${expected_fields}'")
  endif()
  if(expected_points STREQUAL ">0")
    if(NOT points OR points EQUAL 0)
      report_failure("${file}: POINTS '${points}', expected > 0")
    endif()
  elseif(NOT points STREQUAL expected_points)
    report_failure("${file}: POINTS '${points}', expected ${expected_points}")
  endif()
  message(STATUS "ok: ${file}: FIELDS ${fields}; POINTS ${points}")
endfunction()

set(xyz_fields "x y z visibility_radius label feature_class")
set(voxel_fields "x y z i j k visibility_radius label feature_class")
# visfeat_generate's fields; visfeat keeps them (after x y z) in its output.
set(generated_fields "x y z curve_distance face_id")
string(REPLACE "x y z" "${generated_fields}" cube_out_fields "${xyz_fields}")

# --- 1. generate -> visfeat ---------------------------------------------------
set(cube "${WORK_DIR}/cube.pcd")
expect_success(generate "${GENERATE}" cube "${cube}" -resolution 48 -seed 3)
read_pcd_header("${cube}" cube_fields cube_points)
if(NOT cube_fields STREQUAL generated_fields OR NOT cube_points GREATER 0)
  report_failure("${cube}: FIELDS '${cube_fields}', POINTS '${cube_points}'")
endif()

set(out "${WORK_DIR}/cube_out.pcd")
set(cells "${WORK_DIR}/cube_cells.pcd")
expect_success(visfeat "${VISFEAT}" "${cube}" "${out}" -resolution 48 -voxels "${cells}")
expect_header("${out}" "${cube_out_fields}" "${cube_points}")
expect_header("${cells}" "${voxel_fields}" ">0")
foreach(phase "Grid:" "Phases:" "Visibility radius")
  if(NOT visfeat_out MATCHES "${phase}")
    report_failure("visfeat output lacks '${phase}':\n${visfeat_out}")
  endif()
endforeach()

expect_success(visfeat_quiet "${VISFEAT}" "${cube}" "${WORK_DIR}/cube_q.pcd" -resolution 48
               -q -threads 1 -opacity 1.5 -max_radius 4 -min_radius 4 -no_repair)
string(STRIP "${visfeat_quiet_out}" quiet_out)
if(NOT quiet_out STREQUAL "")
  report_failure("visfeat -q printed:\n${visfeat_quiet_out}")
endif()
expect_header("${WORK_DIR}/cube_q.pcd" "${cube_out_fields}" "${cube_points}")

# -paper_noise: the paper's opacity, on the summary line and in the graph's parameters.
set(paper_graph "${WORK_DIR}/cube_paper.json")
expect_success(visfeat_paper "${VISFEAT}" "${cube}" "${WORK_DIR}/cube_paper.pcd"
               -resolution 48 -paper_noise -graph "${paper_graph}")
if(NOT visfeat_paper_out MATCHES "opacity 3, smoothing 0,")
  report_failure("visfeat -paper_noise: no 'opacity 3, smoothing 0,' in\n"
                 "${visfeat_paper_out}")
endif()
if(EXISTS "${paper_graph}")
  read_json(paper_json "${paper_graph}")
  json_value(opacity "${paper_json}" parameters opacity)
  json_value(paper_noise "${paper_json}" parameters paper_noise)
  if(NOT opacity EQUAL 3 OR NOT paper_noise STREQUAL "ON")
    report_failure("${paper_graph}: no opacity 3 and paper_noise true in its parameters")
  endif()
else()
  report_failure("${paper_graph} was not written")
endif()

# Every CAD model, with its truth: the counts in the JSON and on stdout.
# model vertices edges faces
set(models
  "cube 8 12 6" "tetrahedron 4 6 4" "icosahedron 12 30 20" "triangular_prism 6 9 5"
  "u_prism 16 24 10" "box_with_hole 8 14 7" "cylinder 0 2 3")
foreach(entry IN LISTS models)
  separate_arguments(entry UNIX_COMMAND "${entry}")
  list(GET entry 0 model)
  list(GET entry 1 nv)
  list(GET entry 2 ne)
  list(GET entry 3 nf)
  set(pcd "${WORK_DIR}/model_${model}.pcd")
  set(json "${WORK_DIR}/model_${model}.json")
  expect_success(generate_${model} "${GENERATE}" ${model} "${pcd}" -resolution 32
                 -noise 0.2 -seed 5 -truth "${json}")
  expect_header("${pcd}" "${generated_fields}" ">0")
  if(NOT generate_${model}_out MATCHES "Truth: ${nv} vertices, ${ne} edges")
    report_failure("generate_${model}: no 'Truth: ${nv} vertices, ${ne} edges' in\n"
                   "${generate_${model}_out}")
  endif()
  if(NOT EXISTS "${json}")
    report_failure("${json} was not written")
  else()
    read_json(truth "${json}")
    json_value(truth_vertices "${truth}" counts vertices)
    json_value(truth_edges "${truth}" counts edges)
    json_value(truth_faces "${truth}" counts faces)
    if(NOT "${truth_vertices}/${truth_edges}/${truth_faces}" STREQUAL "${nv}/${ne}/${nf}")
      report_failure("${json}: counts are not ${nv}/${ne}/${nf}")
    else()
      message(STATUS "ok: ${json}: ${nv} vertices, ${ne} edges, ${nf} faces")
    endif()
  endif()
endforeach()

# visfeat_generate -mesh: a binary PLY mesh of the model; -organized: an organized PCD
# of W x H points with the generated fields.
set(mesh_ply "${WORK_DIR}/box_with_hole_mesh.ply")
expect_success(generate_mesh "${GENERATE}" box_with_hole "${mesh_ply}" -mesh -resolution 32
               -seed 5)
if(EXISTS "${mesh_ply}")
  file(READ "${mesh_ply}" mesh_head LIMIT 400)
  if(NOT mesh_head MATCHES "format binary_little_endian" OR
     NOT mesh_head MATCHES "element vertex [1-9]" OR NOT mesh_head MATCHES "element face [1-9]")
    report_failure("${mesh_ply}: not a binary PLY mesh with vertices and faces")
  else()
    message(STATUS "ok: ${mesh_ply}")
  endif()
else()
  report_failure("${mesh_ply} was not written")
endif()
set(view_pcd "${WORK_DIR}/cube_view.pcd")
expect_success(generate_view "${GENERATE}" cube "${view_pcd}" -organized 64x48
               -baseline 0.2 -noise_a 0.001 -noise_b 0.001)
expect_header("${view_pcd}" "${generated_fields}" 3072)
if(EXISTS "${view_pcd}")
  file(READ "${view_pcd}" view_head LIMIT 400)
  if(NOT view_head MATCHES "\nWIDTH 64\n" OR NOT view_head MATCHES "\nHEIGHT 48\n")
    report_failure("${view_pcd}: not organized as 64 x 48")
  endif()
endif()

# --- 2. PLY input, existing label field ------------------------------------------
# 150 points on the faces of the cube [0,4]^3 (5x5 per face).
# The same points with a label field (x y label z) for the second file.
set(points "")
set(labelled_points "")
foreach(a RANGE 4)
  foreach(b RANGE 4)
    string(APPEND points "0 ${a} ${b}\n4 ${a} ${b}\n${a} 0 ${b}\n${a} 4 ${b}\n${a} ${b} 0\n${a} ${b} 4\n")
    string(APPEND labelled_points "0 ${a} 7 ${b}\n4 ${a} 7 ${b}\n${a} 0 7 ${b}\n${a} 4 7 ${b}\n"
                                  "${a} ${b} 7 0\n${a} ${b} 7 4\n")
  endforeach()
endforeach()
set(ply "${WORK_DIR}/grid_cube.PLY")
file(WRITE "${ply}" "ply\nformat ascii 1.0\nelement vertex 150\nproperty double x\n"
                    "property double y\nproperty double z\nend_header\n${points}")
expect_success(visfeat_ply "${VISFEAT}" "${ply}" "${WORK_DIR}/ply_out.pcd" -resolution 8)
expect_header("${WORK_DIR}/ply_out.pcd" "${xyz_fields}" 150)

set(labelled "${WORK_DIR}/labelled.pcd")
file(WRITE "${labelled}" "# .PCD v0.7\nVERSION 0.7\nFIELDS x y label z\nSIZE 4 4 4 4\n"
                         "TYPE F F U F\nCOUNT 1 1 1 1\nWIDTH 150\nHEIGHT 1\n"
                         "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 150\nDATA ascii\n")
file(APPEND "${labelled}" "${labelled_points}")
expect_success(visfeat_label "${VISFEAT}" "${labelled}" "${WORK_DIR}/labelled_out.pcd"
               -resolution 8)
expect_header("${WORK_DIR}/labelled_out.pcd" "${xyz_fields}" 150)

file(GLOB leftovers "${WORK_DIR}/*.tmp")
if(leftovers)
  report_failure("temporary files left behind: ${leftovers}")
endif()
