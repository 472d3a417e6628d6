# Shared by the tools' `cmake -P` test scripts (smoke, png, eval, bad_input,
# end_to_end): the check of their -D arguments, a fresh work directory, and, for the
# scripts that report every failure before stopping, report_failure() and run().

# require_definitions(<script name> <var>...): stops, naming the first -D<var> that is
# missing or empty.
function(require_definitions script)
  foreach(var ${ARGN})
    if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
      message(FATAL_ERROR "${script}: -D${var}=... is required")
    endif()
  endforeach()
endfunction()

# fresh_directory(<dir>): <dir> exists and is empty.
function(fresh_directory dir)
  file(REMOVE_RECURSE "${dir}")
  file(MAKE_DIRECTORY "${dir}")
endfunction()

# report_failure(<text>): the script goes on, and fails at its end.
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

# read_json(<var> <file>): the file's text in <var>; empty when it does not exist.
function(read_json var file)
  set(text "")
  if(EXISTS "${file}")
    file(READ "${file}" text)
  endif()
  set(${var} "${text}" PARENT_SCOPE)
endfunction()

# json_value(<out> <json text> <key or index>...): the member at that path (string(JSON
# GET), CMake 3.19+), or "<missing>" when the text is not JSON or has no such member.
function(json_value out json)
  string(JSON value ERROR_VARIABLE error GET "${json}" ${ARGN})
  if(error)
    set(value "<missing>")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()
