# The packaging_manifest test, run by ctest as:
#   cmake -DSOURCE_DIR=<checkout> -DBUILD_DIR=<build> -DVERSION=<PROJECT_VERSION>
#         -P packaging_manifest.cmake
# One version everywhere, and package.xml's dependencies installed by the scripts:
#  - package.xml's <version> = the project's version = the version file CMake writes
#    for find_package(visfeat X.Y) = the version README's status line gives;
#  - every dependency key of package.xml (rosdep names) maps to a Debian package that
#    scripts/install_deps.sh installs (libomp-dev excepted: GCC brings libgomp).
cmake_minimum_required(VERSION 3.16)

foreach(var SOURCE_DIR BUILD_DIR VERSION)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "packaging_manifest: -D${var}=... is required")
  endif()
endforeach()

set(failures)
file(READ "${SOURCE_DIR}/package.xml" manifest)
if(NOT manifest MATCHES "<version>([^<]*)</version>")
  list(APPEND failures "package.xml has no <version>")
elseif(NOT CMAKE_MATCH_1 STREQUAL VERSION)
  list(APPEND failures "package.xml says ${CMAKE_MATCH_1}, the build ${VERSION}")
endif()

set(version_file "${BUILD_DIR}/visfeat-config-version.cmake")
if(NOT EXISTS "${version_file}")
  list(APPEND failures "${version_file} was not written")
else()
  file(READ "${version_file}" text)
  if(NOT text MATCHES "set\\(PACKAGE_VERSION \"([^\"]*)\"\\)" OR
     NOT CMAKE_MATCH_1 STREQUAL VERSION)
    list(APPEND failures "${version_file}: PACKAGE_VERSION '${CMAKE_MATCH_1}', expected ${VERSION}")
  endif()
endif()

file(READ "${SOURCE_DIR}/README.md" readme)
if(NOT readme MATCHES "\\*\\*Status:\\*\\* ([0-9]+\\.[0-9]+\\.[0-9]+)")
  list(APPEND failures "README.md: no '**Status:** X.Y.Z' line")
elseif(NOT CMAKE_MATCH_1 STREQUAL VERSION)
  list(APPEND failures "README.md says ${CMAKE_MATCH_1}, the build ${VERSION}")
endif()

# rosdep key -> Debian package (Debian 12 names).
set(debian_libpcl-all-dev libpcl-dev)
set(debian_eigen libeigen3-dev)
set(debian_boost libboost-graph-dev)
set(debian_nlohmann-json-dev nlohmann-json3-dev)
set(debian_gtest libgtest-dev)
set(debian_xvfb xvfb)
set(debian_pcl-tools pcl-tools)
set(debian_libcgal-dev libcgal-dev)
file(READ "${SOURCE_DIR}/scripts/install_deps.sh" installer)
string(REGEX MATCHALL "<[a-z_]*depend[^>]*>[^<]+</" entries "${manifest}")
set(checked 0)
foreach(entry IN LISTS entries)
  string(REGEX REPLACE "^<[^>]*>([^<]+)</$" "\\1" key "${entry}")
  if(key STREQUAL "cmake" OR key STREQUAL "libomp-dev")
    continue()
  endif()
  if(NOT DEFINED debian_${key})
    list(APPEND failures "package.xml: no Debian package known for the key '${key}' (add it here)")
    continue()
  endif()
  string(REGEX MATCH "[ \t\n(]${debian_${key}}[ \t\n)]" found "${installer}")
  if(NOT found)
    list(APPEND failures "package.xml needs '${key}', but scripts/install_deps.sh does not install ${debian_${key}}")
  endif()
  math(EXPR checked "${checked} + 1")
endforeach()

if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "packaging_manifest:\n  ${text}")
endif()
message(STATUS "packaging_manifest: version ${VERSION} everywhere; ${checked} dependencies installed by scripts/install_deps.sh")
