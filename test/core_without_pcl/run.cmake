# The core_without_pcl test, run by ctest as:
#   cmake -DSOURCE_DIR=<visfeat checkout> -DWORK_DIR=<scratch build dir>
#         [-DCXX_COMPILER=...] [-DLAUNCHER=ccache] [-DGENERATOR=...] -P run.cmake
# (a) greps the core folders for a PCL include, (b) configures and builds
# test/core_without_pcl, a project that never finds PCL, which compiles every core
# header (the core sources are compiled without PCL on their include path by the main
# build's visfeat_core target). Either failing fails the test.
cmake_minimum_required(VERSION 3.16)

foreach(var SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: -D${var}=... is required")
  endif()
endforeach()

# (a) No PCL include anywhere under the core folders.
file(GLOB_RECURSE core_files "${SOURCE_DIR}/include/visfeat/core/*"
     "${SOURCE_DIR}/src/core/*")
set(offenders)
foreach(f IN LISTS core_files)
  file(STRINGS "${f}" hits REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]pcl/")
  if(hits)
    list(APPEND offenders "${f}: ${hits}")
  endif()
endforeach()
if(offenders)
  list(JOIN offenders "\n  " text)
  message(FATAL_ERROR "core_without_pcl: PCL included inside the core:\n  ${text}")
endif()
list(LENGTH core_files count)
message(STATUS "core_without_pcl: no PCL include in ${count} core files")

# (b) Build the core without PCL.
file(REMOVE_RECURSE "${WORK_DIR}")
set(args -S "${SOURCE_DIR}/test/core_without_pcl" -B "${WORK_DIR}"
         "-DVISFEAT_SOURCE_DIR=${SOURCE_DIR}")
if(GENERATOR)
  list(APPEND args -G "${GENERATOR}")
endif()
if(CXX_COMPILER)
  list(APPEND args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(LAUNCHER)
  list(APPEND args "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()
foreach(step configure build)
  if(step STREQUAL "configure")
    set(cmd ${CMAKE_COMMAND} ${args})
  else()
    set(cmd ${CMAKE_COMMAND} --build "${WORK_DIR}" --parallel 2)
  endif()
  execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "core_without_pcl: ${step} failed (${rc}):\n${out}")
  endif()
  message(STATUS "core_without_pcl: ${step}: ok")
endforeach()
