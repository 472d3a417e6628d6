# Runs a libFuzzer target once on every file of a corpus (files given as arguments:
# no fuzzing, no file written). Fails when the corpus is empty or the target does not
# exit 0 (a crash, a sanitizer report or a timeout of one input).
#   cmake -DFUZZER=fuzz_x -DCORPUS=dir -P replay_corpus.cmake
if(NOT FUZZER OR NOT CORPUS)
  message(FATAL_ERROR "usage: cmake -DFUZZER=... -DCORPUS=... -P replay_corpus.cmake")
endif()
file(GLOB _inputs LIST_DIRECTORIES false "${CORPUS}/*")
list(LENGTH _inputs _count)
if(_count EQUAL 0)
  message(FATAL_ERROR "replay: no file in ${CORPUS}")
endif()
execute_process(
  COMMAND ${FUZZER} -timeout=30 -rss_limit_mb=2048 ${_inputs}
  RESULT_VARIABLE _rc
  OUTPUT_VARIABLE _out
  ERROR_VARIABLE _out)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "replay: ${FUZZER} failed (${_rc}) on ${CORPUS}:\n${_out}")
endif()
string(REGEX MATCHALL "Executed [^\n]*" _executed "${_out}")
list(LENGTH _executed _ran)
if(NOT _ran EQUAL _count)
  message(FATAL_ERROR "replay: ${_ran} of ${_count} inputs executed:\n${_out}")
endif()
message(STATUS "replay: ${_count} inputs of ${CORPUS} ran cleanly")
