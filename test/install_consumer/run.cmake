# Packaging test, run by ctest as:
#   cmake -DBUILD_DIR=<visfeat build> -DPREFIX=<scratch prefix>
#         -DSOURCE_DIR=<this directory> -DWORK_DIR=<consumer build dir>
#         [-DCONFIG=Release] [-DCXX_COMPILER=...] [-DGENERATOR=...]
#         [-DEXTRA_FLAGS="-fsanitize=..."] -P run.cmake
# (a) installs the visfeat build into PREFIX, (b) configures the consumer project
# with CMAKE_PREFIX_PATH=PREFIX, (c) builds it, (d) runs it. Any failing step
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

file(REMOVE_RECURSE "${PREFIX}" "${WORK_DIR}")

# (a) install
step(install ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}" --config "${CONFIG}")

# (b) configure
set(args -S "${SOURCE_DIR}" -B "${WORK_DIR}"
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

# (c) build
step(build ${CMAKE_COMMAND} --build "${WORK_DIR}" --config "${CONFIG}")

# (d) run
set(exe "${WORK_DIR}/consumer")
if(NOT EXISTS "${exe}")
  set(exe "${WORK_DIR}/${CONFIG}/consumer") # multi-config generators
endif()
step(run "${exe}")
message(STATUS "install_consumer: ${step_output}")
