# configure and build the project in source_dir into work_dir against the prefix
function(configure_and_build source_dir work_dir)
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
endfunction()

# the executable `name` a build in work_dir made (multi-config generators: in CONFIG/)
function(built_executable work_dir name out)
  set(exe "${work_dir}/${name}")
  if(NOT EXISTS "${exe}")
    set(exe "${work_dir}/${CONFIG}/${name}")
  endif()
  set(${out} "${exe}" PARENT_SCOPE)
endfunction()

function(build_and_run source_dir work_dir)
  configure_and_build("${source_dir}" "${work_dir}")
  built_executable("${work_dir}" consumer exe)
  step(run "${exe}")
  message(STATUS "install_consumer: ${step_output}")
endfunction()# Packaging test, run by ctest as:
#   cmake -DBUILD_DIR=<visfeat build> -DPREFIX=<scratch prefix>
#         -DSOURCE_DIR=<this directory> -DWORK_DIR=<consumer build dir>
#         [-DCONFIG=Release] [-DCXX_COMPILER=...] [-DGENERATOR=...]
#         [-DEXTRA_FLAGS="-fsanitize=..."] [-DREADME=<README.md>] -P run.cmake
# (a) installs the visfeat build into PREFIX, (b) configures the consumer project
# with CMAKE_PREFIX_PATH=PREFIX, (c) builds it, (d) runs it; (b)-(d) again for the
# core-only consumer in core_only/ (find_package(visfeat COMPONENTS core), no PCL).
# With README: (b)-(d) for README's own example, as a user would copy it: the first
# ```cmake block of "## Use from CMake" (after a cmake_minimum_required line) and the
# ```cpp block of "## API", run on a generated cube (BUILD_DIR's visfeat_generate),
# which must leave graph.json. Any failing step stops with FATAL_ERROR and shows that
# step's output.
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

# README's example, copied as written.
if(README)
  file(READ "${README}" readme)
  # the section's first fenced block of the given language
  function(readme_block section language out)
    string(FIND "${readme}" "\n## ${section}\n" at)
    if(at LESS 0)
      message(FATAL_ERROR "install_consumer: README has no section '## ${section}'")
    endif()
    string(SUBSTRING "${readme}" ${at} -1 rest)
    string(FIND "${rest}" "\n```${language}\n" begin)
    if(begin LESS 0)
      message(FATAL_ERROR "install_consumer: no ```${language} block in '${section}'")
    endif()
    string(LENGTH "\n```${language}\n" skip)
    math(EXPR begin "${begin} + ${skip}")
    string(SUBSTRING "${rest}" ${begin} -1 rest)
    string(FIND "${rest}" "\n```" end)
    string(SUBSTRING "${rest}" 0 ${end} block)
    set(${out} "${block}\n" PARENT_SCOPE)
  endfunction()
  readme_block("Use from CMake" cmake cmake_block)
  readme_block("API" cpp cpp_block)
  set(readme_src "${WORK_DIR}-readme-src")
  file(REMOVE_RECURSE "${readme_src}" "${WORK_DIR}-readme")
  file(WRITE "${readme_src}/CMakeLists.txt"
       "cmake_minimum_required(VERSION 3.16)\n${cmake_block}")
  file(WRITE "${readme_src}/main.cpp" "${cpp_block}")
  configure_and_build("${readme_src}" "${WORK_DIR}-readme")
  set(generate "${BUILD_DIR}/tools/visfeat_generate")
  if(EXISTS "${generate}")
    set(run_dir "${WORK_DIR}-readme-run")
    file(REMOVE_RECURSE "${run_dir}")
    file(MAKE_DIRECTORY "${run_dir}")
    step(readme_cloud "${generate}" cube "${run_dir}/cloud.pcd" -resolution 64 -seed 3)
    built_executable("${WORK_DIR}-readme" app exe)
    execute_process(COMMAND "${exe}" WORKING_DIRECTORY "${run_dir}"
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT rc EQUAL 0 OR NOT EXISTS "${run_dir}/graph.json")
      message(FATAL_ERROR "install_consumer: README's example failed (${rc}), or "
                          "wrote no graph.json:\n${out}")
    endif()
    message(STATUS "install_consumer: README's example: ok")
  endif()
endif()
