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
