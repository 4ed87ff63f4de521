# Scene checks, 3D verification (issue 14, 6b-e).
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- 3D verification (issue 14, 6b-e)
# doc/scenes/verification_3d.md. Together about 75 s of CPU (measured on the shared 2-core machine).
foreach(_scene upsetting_3d_short upsetting_3d_np2 thick_cylinder_3d_np2 block3d_oblique_slide_np2
               block3d_oblique_slide_checkpoint block3d_hardening_checkpoint)
  configure_file(${AUSROLL_CHECKS_DIR}/scenes/${_scene}.prm.in ${CMAKE_CURRENT_BINARY_DIR}/${_scene}.prm @ONLY)
endforeach()
# (b) Upsetting, quarter cylinder (3D) against the axisymmetric run of the same scene at matched
# resolution (4 Q2 cells along the radius and the half height): platen force within 1 % at every
# step to 10 % (measured 0.17 %; each mesh's own error is ~1.4 %, reasons in the script). The full
# 30 % comparison is the benchmark benchmark_upsetting_3d. About 10 s.
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/scene3d_upsetting_axisymmetric)
file(MAKE_DIRECTORY ${_dir})
add_test(NAME check/scene3d_upsetting_axisymmetric
  COMMAND ${Python3_EXECUTABLE} ${AUSROLL_CHECKS_DIR}/check_upsetting_3d.py $<TARGET_FILE:ausroll>
          ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/upsetting_3d_short.prm
  WORKING_DIRECTORY ${_dir})
set_tests_properties(check/scene3d_upsetting_axisymmetric PROPERTIES LABELS check TIMEOUT 900)
# (c) Plane-strain thick cylinder as a 3D slice (thick ring sector, u_z = 0): u(b) within 0.5 % of
# the 1D reference along the load path (measured 3e-4) and the 2D history to 1e-8 (same discrete
# problem; measured 5e-11). About 18 s.
ausroll_add_script_check(NAME scene3d_thick_cylinder SCRIPT ${AUSROLL_CHECKS_DIR}/check_thick_cylinder_3d.py)
# (d) Oblique slide under a plane die (Coulomb, isotropic cone): partial slip, then the tangential
# force vector mu F_n e_s to 1e-9 (exact cone; measured 9e-11), balanced by the top reaction,
# nothing left after the release. About 2 s.
ausroll_add_check(NAME scene3d_oblique_slide
  PRM ${AUSROLL_CHECKS_DIR}/scenes/block3d_oblique_slide.prm
  CHECK ${AUSROLL_CHECKS_DIR}/check_oblique_slide_3d.py ARGS out/history.csv)
# (e) Scene<3> on 2 ranks gives the 1-rank history to 1e-8 (relative to each column's largest
# value): the checks above (shortened: upsetting to 5 %, thick cylinder to 180 MPa in 10 steps,
# oblique slide to t = 3) and the earlier 3D checks. About 45 s of CPU together.
ausroll_add_parallel_check(NAME scene3d_upsetting_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/upsetting_3d_np2.prm HISTORY out/history.csv)
ausroll_add_parallel_check(NAME scene3d_thick_cylinder_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/thick_cylinder_3d_np2.prm HISTORY out/history.csv)
ausroll_add_parallel_check(NAME scene3d_oblique_slide_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block3d_oblique_slide_np2.prm HISTORY out/history.csv)
ausroll_add_parallel_check(NAME scene3d_block_hardening_np2
  PRM ${AUSROLL_CHECKS_DIR}/scenes/block3d_hardening.prm HISTORY out/history.csv)
ausroll_add_parallel_check(NAME scene3d_block_plane_die_np2
  PRM ${AUSROLL_CHECKS_DIR}/scenes/block3d_plane_die.prm HISTORY out/history.csv)
# the 3D half of check/scene3d_plane_strain_cylinder
ausroll_add_parallel_check(NAME scene3d_plane_strain_cylinder_np2
  PRM ${AUSROLL_CHECKS_DIR}/scenes/cylinder_block_3d.prm HISTORY out/history.csv)
# 3D checkpoint/restart: the oblique slide killed after step 9 (in the stick-to-slip transition;
# checkpoints every 2 steps: resumes from step 8 with the contact statuses and slip directions)
# and resumed ends identical (1e-10) to the uninterrupted run.
ausroll_add_resume_check(NAME checkpoint_3d_contact
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block3d_oblique_slide_checkpoint.prm ABORT 9)
# The same for the 3D plastic block (8 steps, killed after step 5 on the hardening branch), on 1
# and 2 ranks (one cell per rank: the distributed 3D checkpoint with its material points).
ausroll_add_resume_check(NAME checkpoint_3d_plastic
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block3d_hardening_checkpoint.prm ABORT 5)
ausroll_add_resume_check(NAME checkpoint_3d_plastic_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block3d_hardening_checkpoint.prm ABORT 5 NP 2)
