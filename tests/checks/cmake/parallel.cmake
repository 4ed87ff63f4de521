# Scene checks, Parallel consistency of the short forming scenes (1 and 2 ranks).
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- parallel consistency
# Short versions of the forming scenes on 1 and 2 ranks: every history column agrees to 1e-8
# relative to its largest value (the partition must not change the answer beyond round-off).
foreach(_scene head_forming_short flat_punch_short cantilever_short)
  configure_file(${AUSROLL_CHECKS_DIR}/scenes/${_scene}.prm.in ${CMAKE_CURRENT_BINARY_DIR}/${_scene}.prm @ONLY)
  ausroll_add_parallel_check(NAME ${_scene}_np2 PRM ${CMAKE_CURRENT_BINARY_DIR}/${_scene}.prm
    HISTORY out/history.csv)
endforeach()
ausroll_add_parallel_check(NAME upsetting_short_np2 PRM ${CMAKE_SOURCE_DIR}/tests/upsetting_short.prm
  HISTORY out/history.csv)

# An error that only rank 0 finds (a directory named history.csv in the output directory) ends
# both ranks within seconds with exit 2 and the message (before: rank 1 waited forever).
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/rank_error_np2)
file(MAKE_DIRECTORY ${_dir})
add_test(NAME check/rank_error_np2
  COMMAND ${Python3_EXECUTABLE} ${AUSROLL_CHECKS_DIR}/check_rank_error.py $<TARGET_FILE:ausroll>
          ${CMAKE_SOURCE_DIR} ${DEAL_II_MPIEXEC}
  WORKING_DIRECTORY ${_dir})
set_tests_properties(check/rank_error_np2 PROPERTIES LABELS check TIMEOUT 120 PROCESSORS 2)
