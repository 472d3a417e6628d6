# Runs samples/label_features on a generated cube (resolution 128), as
#   cmake -DSAMPLE=<label_features> -DGENERATE=<visfeat_generate> -DWORK_DIR=<dir>
#         -P sample_test.cmake
# and checks its output: the graph counts, 12 edge lines each with 2 vertices and
# 2 faces, point counts per class that add up to the cloud, and the graph file it
# writes (resolution reason, warnings, nodes).
cmake_minimum_required(VERSION 3.16)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(cloud "${WORK_DIR}/cube.pcd")
execute_process(COMMAND "${GENERATE}" cube "${cloud}" -resolution 128 -seed 1 -q
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "visfeat_generate failed (${rc})")
endif()
file(READ "${cloud}" head LIMIT 1024)
string(REGEX MATCH "\nPOINTS ([0-9]+)" _ "${head}")
set(total "${CMAKE_MATCH_1}")

set(graph "${WORK_DIR}/graph.json")
execute_process(COMMAND "${SAMPLE}" "${cloud}" 128 "${graph}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "label_features output:\n${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "label_features exited with ${rc}")
endif()
if(NOT out MATCHES "graph: 8 vertices, 12 edges, 6 faces, 72 arcs\n")
  message(FATAL_ERROR "no 'graph: 8 vertices, 12 edges, 6 faces, 72 arcs'")
endif()
# "; faces" would split the list of matches: commas instead.
string(REPLACE ";" "," flat "${out}")
string(REGEX MATCHALL "edge [0-9]+ \\([0-9]+ points\\): vertices [0-9]+ [0-9]+, faces [0-9]+ [0-9]+\n" edges "${flat}")
list(LENGTH edges n)
if(NOT n EQUAL 12)
  message(FATAL_ERROR "${n} edge lines with 2 vertices and 2 faces, expected 12")
endif()
if(NOT out MATCHES "points: ([0-9]+) vertex, ([0-9]+) edge, ([0-9]+) face, ([0-9]+) none")
  message(FATAL_ERROR "no per-class point counts")
endif()
math(EXPR sum "${CMAKE_MATCH_1} + ${CMAKE_MATCH_2} + ${CMAKE_MATCH_3} + ${CMAKE_MATCH_4}")
if(NOT sum EQUAL total OR CMAKE_MATCH_3 LESS CMAKE_MATCH_2 OR CMAKE_MATCH_2 EQUAL 0
   OR CMAKE_MATCH_1 EQUAL 0)
  message(FATAL_ERROR "point counts ${CMAKE_MATCH_1}/${CMAKE_MATCH_2}/${CMAKE_MATCH_3}/${CMAKE_MATCH_4} for ${total} points")
endif()
# the graph file carries the grid, the resolution's reason and the warnings
if(NOT EXISTS "${graph}")
  message(FATAL_ERROR "no ${graph}")
endif()
file(READ "${graph}" json)
string(JSON reason GET "${json}" parameters resolution_reason)
string(JSON n_warnings LENGTH "${json}" warnings)
string(JSON n_nodes LENGTH "${json}" nodes)
if(NOT reason STREQUAL "set by setResolution()" OR NOT n_warnings EQUAL 0
   OR NOT n_nodes EQUAL 26)
  message(FATAL_ERROR "graph.json: reason '${reason}', ${n_warnings} warnings, ${n_nodes} nodes (expected 'set by setResolution()', 0, 26)")
endif()
message(STATUS "ok: label_features")
