# Test of the tool's pictures, run by ctest as
#   cmake -DVISFEAT=<visfeat> -DGENERATE=<visfeat_generate> -DCHECK=<visfeat_png_check>
#         -DHAVE_PICTURES=ON|OFF -DWORK_DIR=<dir> -P png_test.cmake
# 1. A 96-cell cube rendered with -png and -png_radius (640x480), and with -png alone at
#    the default size: exit code, no .tmp left, the size in the IHDR header, and the
#    content checked by visfeat_png_check (classes / ramp visible, object in frame).
# 2. Failures: no display, an unopenable display, an unwritable picture path, a wrong
#    extension, a bad -png_size: non-zero exit, one error line, no output left.
# Rendering needs an X display (Debian's VTK has no OSMesa/EGL): the tool runs under
# xvfb-run when it exists, else on $DISPLAY; with neither the test is skipped.
# Without PCL visualization (HAVE_PICTURES OFF) only the clear error is checked.

cmake_minimum_required(VERSION 3.16)

include("${CMAKE_CURRENT_LIST_DIR}/script_test_common.cmake")
require_definitions(png_test.cmake VISFEAT GENERATE WORK_DIR)

fresh_directory("${WORK_DIR}")

# expect_failure(<name> <pattern> <outputs> <command...>): non-zero exit, exactly one
# error line matching <pattern>, none of the ;-list <outputs> (nor .tmp) left behind.
function(expect_failure name pattern outputs)
  foreach(o IN LISTS outputs)
    file(REMOVE "${o}" "${o}.tmp")
  endforeach()
  run(${name} ${ARGN})
  # Semicolons would split the matches as a CMake list.
  string(REPLACE ";" "," text "${${name}_out}")
  string(REGEX MATCHALL "error: [^\n]*" errors "${text}")
  list(LENGTH errors n_errors)
  if(${name}_rc EQUAL 0)
    report_failure("${name}: exit code 0\n  ${ARGN}\n${${name}_out}")
    return()
  elseif(NOT n_errors EQUAL 1)
    report_failure("${name}: ${n_errors} error lines, expected 1\n${${name}_out}")
    return()
  elseif(NOT errors MATCHES "${pattern}")
    report_failure("${name}: error does not match '${pattern}': ${errors}")
    return()
  endif()
  foreach(o IN LISTS outputs)
    if(EXISTS "${o}" OR EXISTS "${o}.tmp")
      report_failure("${name}: left '${o}' (or .tmp) behind")
      return()
    endif()
  endforeach()
  message(STATUS "ok: ${name} fails (rc ${${name}_rc}): ${errors}")
endfunction()

# png_size(<file> <w_var> <h_var>): width and height from the IHDR chunk (bytes 16-23,
# after the 8-byte signature, the chunk length and "IHDR").
function(png_size file w_var h_var)
  set(${w_var} "" PARENT_SCOPE)
  set(${h_var} "" PARENT_SCOPE)
  file(READ "${file}" head LIMIT 24 HEX)
  string(SUBSTRING "${head}" 0 16 signature)
  string(SUBSTRING "${head}" 24 8 chunk)
  if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT chunk STREQUAL "49484452")
    report_failure("${file}: not a PNG (first bytes ${head})")
    return()
  endif()
  string(SUBSTRING "${head}" 32 8 w_hex)
  string(SUBSTRING "${head}" 40 8 h_hex)
  math(EXPR w "0x${w_hex}")
  math(EXPR h "0x${h_hex}")
  set(${w_var} "${w}" PARENT_SCOPE)
  set(${h_var} "${h}" PARENT_SCOPE)
endfunction()

# expect_picture(<file> <mode> <w> <h>): written, the IHDR size, the content check.
function(expect_picture file mode w h)
  if(NOT EXISTS "${file}")
    report_failure("${file} was not written")
    return()
  endif()
  if(EXISTS "${file}.tmp")
    report_failure("${file}.tmp left behind")
  endif()
  png_size("${file}" pw ph)
  if(NOT pw STREQUAL "${w}" OR NOT ph STREQUAL "${h}")
    report_failure("${file}: IHDR says ${pw}x${ph}, expected ${w}x${h}")
  else()
    file(SIZE "${file}" bytes)
    message(STATUS "ok: ${file}: PNG ${pw}x${ph}, ${bytes} bytes")
  endif()
  run(check "${CHECK}" "${file}" ${mode} ${w} ${h})
  if(NOT check_rc EQUAL 0)
    report_failure("${file}: content check failed\n${check_out}")
  else()
    message(STATUS "ok: ${file}: content\n${check_out}")
  endif()
endfunction()

set(cube "${WORK_DIR}/cube.pcd")
set(out "${WORK_DIR}/cube_out.pcd")
set(png "${WORK_DIR}/cube.png")
set(radius_png "${WORK_DIR}/cube_radius.png")
run(generate "${GENERATE}" cube "${cube}" -resolution 96 -seed 3)
if(NOT generate_rc EQUAL 0)
  message(FATAL_ERROR "visfeat_generate failed:\n${generate_out}")
endif()

if(NOT HAVE_PICTURES)
  expect_failure(no_pictures_built "without PCL's visualization" "${out};${png}"
    "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${png}")
  message(STATUS "tools_png: this build has no pictures; checked the error only")
  return()
endif()
if("${CHECK}" STREQUAL "")
  message(FATAL_ERROR "png_test.cmake: -DCHECK=... is required with pictures")
endif()

# Failures that need no display, and the display checks themselves.
expect_failure(no_display "xvfb-run" "${out};${png}"
  ${CMAKE_COMMAND} -E env --unset=DISPLAY
  "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${png}")
expect_failure(bad_display "cannot open the X display.*xvfb-run" "${out};${png}"
  ${CMAKE_COMMAND} -E env DISPLAY=:4711
  "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${png}")
expect_failure(png_missing_dir "does not exist" "${out}"
  "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${WORK_DIR}/no/such/dir/x.png")
file(MAKE_DIRECTORY "${WORK_DIR}/dir.png")
expect_failure(png_is_directory "is a directory" "${out}"
  "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png_radius "${WORK_DIR}/dir.png")
expect_failure(png_extension "extension .png" "${out};${WORK_DIR}/x.jpg"
  "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${WORK_DIR}/x.jpg")
expect_failure(png_same_file "must differ" "${out};${png}"
  "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${png}" -png_radius "${png}")
foreach(bad 640 640x 0x480 640x48000 axb -640x480 "640x480 ")
  string(MAKE_C_IDENTIFIER "png_size_${bad}" name)
  expect_failure(${name} "-png_size" "${out};${png}"
    "${VISFEAT}" "${cube}" "${out}" -resolution 96 -png "${png}" -png_size "${bad}")
endforeach()

# A display: xvfb-run (a private X server per run), else the caller's.
find_program(XVFB_RUN xvfb-run)
set(launcher "")
if(XVFB_RUN)
  set(launcher "${XVFB_RUN}" -a)
  message(STATUS "rendering under ${XVFB_RUN} -a")
elseif(NOT "$ENV{DISPLAY}" STREQUAL "")
  message(STATUS "rendering on DISPLAY=$ENV{DISPLAY} (no xvfb-run)")
else()
  message(STATUS "tools_png: SKIPPED the rendering checks: no xvfb-run and no DISPLAY "
                 "(install xvfb: scripts/install_deps.sh)")
  return()
endif()

run(render ${launcher} "${VISFEAT}" "${cube}" "${out}" -resolution 96
  -png "${png}" -png_radius "${radius_png}" -png_size 640x480)
if(NOT render_rc EQUAL 0)
  report_failure("render: exit code ${render_rc}\n${render_out}")
else()
  message(STATUS "ok: render")
  expect_picture("${png}" classes 640 480)
  expect_picture("${radius_png}" radius 640 480)
  # The checker must tell the two apart (it is not satisfied by any picture).
  run(cross "${CHECK}" "${radius_png}" classes 640 480)
  if(cross_rc EQUAL 0)
    report_failure("the radius picture passes the classes check:\n${cross_out}")
  else()
    message(STATUS "ok: the radius picture fails the classes check")
  endif()
endif()

set(default_png "${WORK_DIR}/cube_default.png")
run(render_default ${launcher} "${VISFEAT}" "${cube}" "${out}" -resolution 96 -q
  -png "${default_png}")
if(NOT render_default_rc EQUAL 0)
  report_failure("render_default: exit code ${render_default_rc}\n${render_default_out}")
else()
  expect_picture("${default_png}" classes 1024 768)
endif()
