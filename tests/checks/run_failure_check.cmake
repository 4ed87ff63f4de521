# Runs a scene that is expected to fail and hands its exit status and log to a checker.
execute_process(COMMAND ${RUN} ${PRM} --overwrite RESULT_VARIABLE _rc OUTPUT_FILE run.log ERROR_FILE run.log)
execute_process(COMMAND ${CHECK} run.log ${_rc} ${ARGS} RESULT_VARIABLE _check)
if(NOT _check EQUAL 0)
  message(FATAL_ERROR "failure check failed")
endif()
