# Restart and output-directory safety (see cmake/checkpoint.cmake, check/restart_safety). RUN: ausroll,
# PRM: a scene with Checkpoint/Interval = 2 and Output/Directory = out.
foreach(_v RUN PRM)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "run_restart_safety_check.cmake: ${_v} not set")
  endif()
endforeach()
file(REMOVE_RECURSE ${CMAKE_CURRENT_BINARY_DIR}/out)

# expect(<name> <exit status> <text the output must contain> <arguments...>)
function(expect name status text)
  execute_process(COMMAND ${RUN} ${PRM} ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
                  ERROR_VARIABLE _out)
  if(NOT _rc STREQUAL "${status}")
    message(FATAL_ERROR "${name}: exit ${_rc}, expected ${status}:\n${_out}")
  endif()
  string(FIND "${_out}" "${text}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "${name}: output lacks '${text}':\n${_out}")
  endif()
  message(STATUS "${name}: exit ${_rc}, '${text}' found")
endfunction()

expect("interrupted run" 99 "aborting after step 5" --set "Checkpoint/Abort after step=5"
       --set "Output/Verbosity=normal")
expect("resume with another mesh" 2 "Geometry/Rectangle/Cells (checkpoint: '4, 2', now: '8, 4')"
       --resume --set "Geometry/Rectangle/Cells=8, 4")
expect("resume with another degree" 2 "Model/Polynomial degree (checkpoint: '2', now: '1')"
       --resume --set "Model/Polynomial degree=1")
expect("new run into the results" 2 "holds results of an earlier run")
expect("resume with another output interval" 0
       "warning: --resume: Output/Interval (checkpoint: '1', now: '3') changed" --resume
       --set "Output/Interval=3")
expect("new run with --overwrite" 0 "" --overwrite)
