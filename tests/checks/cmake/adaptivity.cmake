# Scene checks, Adaptivity: transfer of the state at constant load, Hertz on an adaptive mesh, in parallel.
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- adaptivity
foreach(_scene thick_cylinder_adapt hertz_adaptive)
  configure_file(${AUSROLL_CHECKS_DIR}/scenes/${_scene}.prm.in ${CMAKE_CURRENT_BINARY_DIR}/${_scene}.prm @ONLY)
endforeach()
# Refinement and coarsening at constant load (t = 1 ... 3): reactions equal p a = 15000 N by
# equilibrium (1e-6: solver tolerance), yield excess at round-off (1e-8 sigma_y), u(b) within
# 0.5 % of the 1D reference at 150 MPa at every step.
ausroll_add_check(NAME adaptivity_transfer_thick_cylinder
  PRM ${CMAKE_CURRENT_BINARY_DIR}/thick_cylinder_adapt.prm
  CHECK ${AUSROLL_CHECKS_DIR}/check_history.py
  ARGS out/history.csv
       --value reaction_2_y 1 -15000 1e-6 --value reaction_2_y 2 -15000 1e-6 --value reaction_2_y 3 -15000 1e-6
       --value reaction_3_x 2 -15000 1e-6
       --range yield_excess 1 0 1e-8 --range yield_excess 1.5 0 1e-8 --range yield_excess 2 0 1e-8
       --range yield_excess 2.5 0 1e-8 --range yield_excess 3 0 1e-8
       --range outer_ux 1 0.097701 0.098683 --range outer_ux 2 0.097701 0.098683 --range outer_ux 3 0.097701 0.098683)

# Hertz on an adaptive mesh (contact band + Kelly): a and p0 within 1 % at the thesis loads.
ausroll_add_check(NAME adaptivity_hertz
  PRM ${CMAKE_CURRENT_BINARY_DIR}/hertz_adaptive.prm
  CHECK ${AUSROLL_CHECKS_DIR}/check_hertz.py ARGS ${_hertz_args})
# Adaptation in parallel (flags, repartitioning, transfer): np = 2 gives the np = 1 history.
ausroll_add_parallel_check(NAME adaptivity_hertz_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/hertz_adaptive.prm HISTORY out/history.csv)
ausroll_add_parallel_check(NAME adaptivity_transfer_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/thick_cylinder_adapt.prm HISTORY out/history.csv)
