# Fails when doc/parameters.md differs from `ausroll --print-parameters=markdown`.
# Variables: EXE (ausroll), DOC (committed doc/parameters.md), OUT (scratch file).
execute_process(COMMAND ${EXE} --print-parameters=markdown OUTPUT_FILE ${OUT} RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "ausroll --print-parameters=markdown failed (${_rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${DOC} RESULT_VARIABLE _diff)
if(NOT _diff EQUAL 0)
  message(FATAL_ERROR "doc/parameters.md is stale: run scripts/update_docs.sh and commit the result")
endif()
message(STATUS "doc/parameters.md is current")
