# Scene checks, Checkpoint / restart: resumed runs give the uninterrupted history; restart and output safety.
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- checkpoint / restart

foreach(_scene thick_cylinder_adapt_checkpoint block_slide_checkpoint)
  configure_file(${AUSROLL_CHECKS_DIR}/scenes/${_scene}.prm.in ${CMAKE_CURRENT_BINARY_DIR}/${_scene}.prm @ONLY)
endforeach()
# A run killed after step 5 (checkpoints every 2 steps: resumes from step 4) and resumed ends
# identical (1e-10) to an uninterrupted one: plasticity + mesh adaptation, contact with friction,
# and in parallel.
ausroll_add_resume_check(NAME checkpoint_plastic_adaptive
  PRM ${CMAKE_CURRENT_BINARY_DIR}/thick_cylinder_adapt_checkpoint.prm ABORT 5)
ausroll_add_resume_check(NAME checkpoint_contact
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block_slide_checkpoint.prm ABORT 7)
ausroll_add_resume_check(NAME checkpoint_contact_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block_slide_checkpoint.prm ABORT 7 NP 2)
# With the linear-extrapolation predictor (the shipped disk scene's): the checkpoint carries the
# previous converged solution and step size, so the first step after the resume predicts as the
# uninterrupted run does (before, the force differed by 0.8 % after one resume).
ausroll_add_resume_check(NAME checkpoint_predictor
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block_slide_checkpoint.prm ABORT 7
  ARGS --set "Loading/Predictor=linear extrapolation")
ausroll_add_resume_check(NAME checkpoint_predictor_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block_slide_checkpoint.prm ABORT 7 NP 2
  ARGS --set "Loading/Predictor=linear extrapolation")

# Restart and output safety (block slide, checkpoint after step 4 of 12): a resume with a changed
# mesh or polynomial degree is refused naming the entries (it crashed); a legitimate change
# (Output/Interval) is resumed with a warning naming it; a new run into the directory with these
# results is refused without --overwrite and runs with it.
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/restart_safety)
file(MAKE_DIRECTORY ${_dir})
add_test(NAME check/restart_safety
  COMMAND ${CMAKE_COMMAND} -DRUN=$<TARGET_FILE:ausroll>
    -DPRM=${CMAKE_CURRENT_BINARY_DIR}/block_slide_checkpoint.prm
    -P ${AUSROLL_CHECKS_DIR}/run_restart_safety_check.cmake
  WORKING_DIRECTORY ${_dir})
set_tests_properties(check/restart_safety PROPERTIES LABELS check TIMEOUT 600)

# Damaged checkpoints (emptied, truncated, bit-flipped or missing p4est and data files, edited or
# emptied metadata), an edited history.csv and resumes that change Candidate boundaries or add a
# monitor point: each ends with exit 2 and a message naming the file or entry (before: p4est
# abort, segfault, NaN later, a corrupted history.csv); an undamaged copy resumes. About 15 s.
ausroll_add_script_check(NAME damaged_restarts SCRIPT ${AUSROLL_CHECKS_DIR}/check_damaged_restarts.py)

# A full disk (imitated by the file-size limit) while writing a checkpoint or a VTU file: exit 3
# naming the step and file, the previous checkpoint, history.csv and solution.pvd intact, and a
# resume without the limit gives the uninterrupted history. About 10 s CPU.
ausroll_add_script_check(NAME full_disk SCRIPT ${AUSROLL_CHECKS_DIR}/check_full_disk.py)
