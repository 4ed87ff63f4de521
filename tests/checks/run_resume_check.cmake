# Checkpoint/restart check: run a scene without interruption (in full/), run it again with an
# abrupt stop after step ABORT (in resumed/; Checkpoint/Abort after step, exit status 99) and
# continue it with --resume, then compare the two histories (TOL, relative). ARGS (optional): more
# arguments for all three runs (e.g. --set "Loading/Predictor=linear extrapolation").
foreach(_v RUN PRM ABORT COMPARE TOL)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "run_resume_check.cmake: ${_v} not set")
  endif()
endforeach()
set(_here ${CMAKE_CURRENT_BINARY_DIR})
file(REMOVE_RECURSE ${_here}/full ${_here}/resumed)
file(MAKE_DIRECTORY ${_here}/full ${_here}/resumed)
file(WRITE ${_here}/abort.prm "include ${PRM}\nsubsection Checkpoint\n  set Abort after step = ${ABORT}\nend\n")

execute_process(COMMAND ${RUN} ${PRM} ${ARGS} WORKING_DIRECTORY ${_here}/full RESULT_VARIABLE _rc
                OUTPUT_FILE ${_here}/full/run.log ERROR_FILE ${_here}/full/run.log)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "uninterrupted run failed (exit ${_rc})")
endif()
execute_process(COMMAND ${RUN} ${_here}/abort.prm ${ARGS} WORKING_DIRECTORY ${_here}/resumed RESULT_VARIABLE _rc
                OUTPUT_FILE ${_here}/resumed/run1.log ERROR_FILE ${_here}/resumed/run1.log)
if(_rc EQUAL 0)
  message(FATAL_ERROR "the interrupted run did not stop")
endif()
execute_process(COMMAND ${RUN} ${_here}/abort.prm --resume ${ARGS} WORKING_DIRECTORY ${_here}/resumed
                RESULT_VARIABLE _rc OUTPUT_FILE ${_here}/resumed/run2.log ERROR_FILE ${_here}/resumed/run2.log)
if(NOT _rc EQUAL 0)
  file(READ ${_here}/resumed/run2.log _log)
  message(FATAL_ERROR "resumed run failed (exit ${_rc}):\n${_log}")
endif()
execute_process(COMMAND ${COMPARE} ${_here}/full/out/history.csv ${_here}/resumed/out/history.csv
                        --rel-tol ${TOL} RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "resumed run differs from the uninterrupted one")
endif()
