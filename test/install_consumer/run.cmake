# Packaging test, run by ctest as:
#   cmake -DBUILD_DIR=<visfeat build> -DPREFIX=<scratch prefix>
#         -DSOURCE_DIR=<this directory> -DWORK_DIR=<consumer build dir>
#         [-DCONFIG=Release] [-DCXX_COMPILER=...] [-DGENERATOR=...]
#         [-DEXTRA_FLAGS="-fsanitize=..."] -P run.cmake
# (a) installs the visfeat build into PREFIX, (b) configures the consumer project
# with CMAKE_PREFIX_PATH=PREFIX, (c) builds it, (d) runs it; (b)-(d) again for the
# core-only consumer in core_only/ (find_package(visfeat COMPONENTS core), no PCL). Any failing step
# stops with FATAL_ERROR and shows that step's output.
#
# EXTRA_FLAGS: when visfeat is built with VISFEAT_SANITIZE, the consumer is
# compiled and linked with the same -fsanitize flags (an ASan-instrumented
# libvisfeat cannot be loaded by an uninstrumented executable without
# LD_PRELOAD), and it is run normally.

cmake_minimum_required(VERSION 3.16) # script mode: set policies

foreach(var BUILD_DIR PREFIX SOURCE_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT WORK_DIR)
  set(WORK_DIR "${PREFIX}-consumer-build")
endif()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

function(step name)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    list(JOIN ARGN " " cmd)
    message(FATAL_ERROR "install_consumer: step '${name}' failed (${rc}):\n"
                        "  ${cmd}\n${out}")
  endif()
  message(STATUS "install_consumer: ${name}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${PREFIX}" "${WORK_DIR}" "${WORK_DIR}-core")

# (a) install
step(install ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}" --config "${CONFIG}")

# (b)-(d) for each consumer: the PCL front (SOURCE_DIR) and the PCL-free core alone
# (SOURCE_DIR/core_only, which refuses to find PCL).
function(build_and_run source_dir work_dir)
  set(args -S "${source_dir}" -B "${work_dir}"
           "-DCMAKE_PREFIX_PATH=${PREFIX}"
           "-DCMAKE_BUILD_TYPE=${CONFIG}")
  if(GENERATOR)
    list(APPEND args -G "${GENERATOR}")
  endif()
  if(CXX_COMPILER)
    list(APPEND args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
  endif()
  if(EXTRA_FLAGS)
    list(APPEND args "-DCMAKE_CXX_FLAGS=${EXTRA_FLAGS}"
                     "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_FLAGS}")
  endif()
  step(configure ${CMAKE_COMMAND} ${args})
  step(build ${CMAKE_COMMAND} --build "${work_dir}" --config "${CONFIG}")
  set(exe "${work_dir}/consumer")
  if(NOT EXISTS "${exe}")
    set(exe "${work_dir}/${CONFIG}/consumer") # multi-config generators
  endif()
  step(run "${exe}")
  message(STATUS "install_consumer: ${step_output}")
endfunction()

build_and_run("${SOURCE_DIR}" "${WORK_DIR}")
build_and_run("${SOURCE_DIR}/core_only" "${WORK_DIR}-core")
