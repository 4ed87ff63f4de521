# Runs one scene (RUN PRM) in the current directory, then the checker (CHECK ARGS).
# Fails if either exits non-zero.
execute_process(COMMAND ${RUN} ${PRM} --overwrite RESULT_VARIABLE _rc OUTPUT_FILE run.log ERROR_FILE run.log)
if(NOT _rc EQUAL 0)
  file(READ run.log _log)
  message(FATAL_ERROR "scene ${PRM} failed (exit ${_rc}):\n${_log}")
endif()
execute_process(COMMAND ${CHECK} ${ARGS} RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "check failed (exit ${_rc})")
endif()
