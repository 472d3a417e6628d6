# Smoke test of the command-line tools, run by ctest as
#   cmake -DVISFEAT=<visfeat> -DGENERATE=<visfeat_generate> -DWORK_DIR=<dir> -P smoke_test.cmake
# 1. visfeat_generate cube -> visfeat -voxels: exit codes, PCD headers (fields, POINTS);
#    every CAD model of visfeat_generate with its -truth JSON (counts).
# 2. .ply input (double coordinates, upper-case extension) and an input that already has
#    a label field.
# 3. Bad inputs exit non-zero with an error line and leave no output (nor .tmp) file.

cmake_minimum_required(VERSION 3.16) # policies NEW (CMP0053: plain ${} expansion)

foreach(var VISFEAT GENERATE WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "smoke_test.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(report_failure text)
  message(SEND_ERROR "FAIL: ${text}")
endfunction()

# run(<name> <command...>): sets <name>_rc and <name>_out (stdout + stderr).
function(run name)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE out)
  set(${name}_rc "${rc}" PARENT_SCOPE)
  set(${name}_out "${out}" PARENT_SCOPE)
endfunction()

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

# expect_failure(<name> <output file> <command...>): non-zero exit, an error message,
# and neither the output nor its temporary file left behind.
function(expect_failure name output)
  file(REMOVE "${output}" "${output}.tmp")
  run(${name} ${ARGN})
  if(${name}_rc EQUAL 0)
    report_failure("${name}: exit code 0 for a bad input\n  ${ARGN}\n${${name}_out}")
  elseif(NOT ${name}_out MATCHES "error")
    report_failure("${name}: no error message\n  ${ARGN}\n${${name}_out}")
  elseif(EXISTS "${output}" OR EXISTS "${output}.tmp")
    report_failure("${name}: left '${output}' (or .tmp) behind")
  else()
    string(REGEX MATCH "error: [^\n]*" msg "${${name}_out}")
    message(STATUS "ok: ${name} fails (rc ${${name}_rc}): ${msg}")
  endif()
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
    file(READ "${json}" truth)
    if(NOT truth MATCHES "\"counts\": {\"vertices\": ${nv}, \"edges\": ${ne},"
       OR NOT truth MATCHES "\"faces\": ${nf}}")
      report_failure("${json}: counts are not ${nv}/${ne}/${nf}")
    else()
      message(STATUS "ok: ${json}: ${nv} vertices, ${ne} edges, ${nf} faces")
    endif()
  endif()
endforeach()

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

# --- 3. Bad inputs -----------------------------------------------------------------
set(bad_out "${WORK_DIR}/bad_out.pcd")
expect_failure(missing_file "${bad_out}" "${VISFEAT}" "${WORK_DIR}/missing.pcd" "${bad_out}")

configure_file("${cube}" "${WORK_DIR}/cube.xyz" COPYONLY)
expect_failure(unknown_extension "${bad_out}" "${VISFEAT}" "${WORK_DIR}/cube.xyz" "${bad_out}")

expect_failure(resolution_0 "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}" -resolution 0)
expect_failure(resolution_text "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}" -resolution abc)
expect_failure(threads_negative "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}" -threads -1)
expect_failure(opacity_nan "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}" -opacity nan)
expect_failure(unknown_option "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}" -resolutoin 64)
expect_failure(missing_value "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}" -resolution)
expect_failure(output_not_pcd "${WORK_DIR}/bad_out.ply" "${VISFEAT}" "${cube}"
               "${WORK_DIR}/bad_out.ply")
expect_failure(output_dir_missing "${WORK_DIR}/no/such/dir/out.pcd" "${VISFEAT}" "${cube}"
               "${WORK_DIR}/no/such/dir/out.pcd")

set(empty "${WORK_DIR}/empty.pcd")
file(WRITE "${empty}" "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                      "COUNT 1 1 1\nWIDTH 0\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 0\n"
                      "DATA ascii\n")
expect_failure(empty_pcd "${bad_out}" "${VISFEAT}" "${empty}" "${bad_out}")

set(truncated "${WORK_DIR}/truncated.pcd")
file(WRITE "${truncated}" "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                          "COUNT 1 1 1\nWIDTH 1000\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
                          "POINTS 1000\nDATA binary\nnot enough bytes")
expect_failure(truncated_pcd "${bad_out}" "${VISFEAT}" "${truncated}" "${bad_out}")

set(garbage "${WORK_DIR}/garbage.pcd")
file(WRITE "${garbage}" "this is not a point cloud\n")
expect_failure(garbage_pcd "${bad_out}" "${VISFEAT}" "${garbage}" "${bad_out}")

set(zero "${WORK_DIR}/zero_bytes.pcd")
file(WRITE "${zero}" "")
expect_failure(zero_byte_pcd "${bad_out}" "${VISFEAT}" "${zero}" "${bad_out}")

set(no_xyz "${WORK_DIR}/no_xyz.pcd")
file(WRITE "${no_xyz}" "# .PCD v0.7\nVERSION 0.7\nFIELDS a b\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\n"
                       "WIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n1 2\n")
expect_failure(no_xyz_fields "${bad_out}" "${VISFEAT}" "${no_xyz}" "${bad_out}")

set(bad_ply "${WORK_DIR}/bad.ply")
file(WRITE "${bad_ply}" "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n")
expect_failure(corrupt_ply "${bad_out}" "${VISFEAT}" "${bad_ply}" "${bad_out}")

# A single point: no grid can be built; the estimator's own message must come through.
set(single "${WORK_DIR}/single.pcd")
file(WRITE "${single}" "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                       "COUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\n"
                       "DATA ascii\n1 2 3\n")
expect_failure(single_point "${bad_out}" "${VISFEAT}" "${single}" "${bad_out}")

# The -voxels file must not be left behind either.
file(REMOVE "${WORK_DIR}/bad_cells.pcd")
expect_failure(voxels_on_failure "${bad_out}" "${VISFEAT}" "${cube}" "${bad_out}"
               -resolution 0 -voxels "${WORK_DIR}/bad_cells.pcd")
if(EXISTS "${WORK_DIR}/bad_cells.pcd")
  report_failure("voxels_on_failure: left bad_cells.pcd behind")
endif()

expect_failure(generate_unknown_shape "${WORK_DIR}/gen_bad.pcd" "${GENERATE}" dodecagon
               "${WORK_DIR}/gen_bad.pcd")
expect_failure(generate_bad_spacing "${WORK_DIR}/gen_bad.pcd" "${GENERATE}" cube
               "${WORK_DIR}/gen_bad.pcd" -spacing -1)
expect_failure(generate_truth_not_json "${WORK_DIR}/gen_bad.pcd" "${GENERATE}" cube
               "${WORK_DIR}/gen_bad.pcd" -truth "${WORK_DIR}/gen_bad.txt")
expect_failure(generate_truth_dir_missing "${WORK_DIR}/gen_bad.pcd" "${GENERATE}" cube
               "${WORK_DIR}/gen_bad.pcd" -truth "${WORK_DIR}/no/such/dir/t.json")
expect_failure(generate_truth_no_value "${WORK_DIR}/gen_bad.pcd" "${GENERATE}" cube
               "${WORK_DIR}/gen_bad.pcd" -truth)
if(EXISTS "${WORK_DIR}/gen_bad.txt")
  report_failure("generate_truth_not_json: left gen_bad.txt behind")
endif()

file(GLOB leftovers "${WORK_DIR}/*.tmp")
if(leftovers)
  report_failure("temporary files left behind: ${leftovers}")
endif()
