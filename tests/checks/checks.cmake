# The scene checks. Each states its reference and tolerance.

# Thick cylinder (plane strain, perfectly plastic): outer radial displacement u(b) along the whole
# load path within 0.5 % of the independent 1D radial solution (issue tolerance; the mesh of
# prm/thick_cylinder.prm reaches ~0.1 %). Points below 1 MPa are skipped (u ~ 0).
ausroll_add_check(NAME thick_cylinder_load_path
  PRM ${CMAKE_SOURCE_DIR}/prm/thick_cylinder.prm
  CHECK ${AUSROLL_CHECKS_DIR}/compare_curves.py
  ARGS --result output/thick_cylinder/history.csv
       --reference ${AUSROLL_CHECKS_DIR}/reference/thick_cylinder_load.csv
       --x-result pressure_0 --y-result outer_ux --x-reference pressure --y-reference u_outer
       --rel-tol 0.005 --x-min 1)

# Thick cylinder: hoop stress along the radial line at p = 180 MPa (output 4) against the 1D
# reference. Error relative to max(|sigma_ref|, sigma_y): 1.5 % -- the stresses are interpolated
# from the Gauss points, which smooths the kink at the plastic front (c = 161 mm) and extrapolates
# to r = a; the mesh of the scene gives 0.6 %.
ausroll_add_check(NAME thick_cylinder_hoop_profile
  PRM ${CMAKE_SOURCE_DIR}/prm/thick_cylinder.prm
  CHECK ${AUSROLL_CHECKS_DIR}/compare_curves.py
  ARGS --result output/thick_cylinder/probe_radial_0004.csv
       --reference ${AUSROLL_CHECKS_DIR}/reference/thick_cylinder_profile.csv
       --x-result x --y-result stress_yy --x-reference r --y-reference sigma_theta
       --rel-tol 0.015 --abs-floor 240)

# The same scene on 1 and 2 MPI ranks gives the same history to 1e-8 (relative to each column's
# largest value): the distributed assembly and solver must not change the answer.
ausroll_add_parallel_check(NAME thick_cylinder_np2
  PRM ${CMAKE_SOURCE_DIR}/prm/thick_cylinder.prm
  HISTORY output/thick_cylinder/history.csv)

# Malformed input files: clear message naming the entry, exit status 2, no output left behind.
add_test(NAME check/bad_input
  COMMAND ${Python3_EXECUTABLE} ${AUSROLL_CHECKS_DIR}/check_bad_inputs.py
          $<TARGET_FILE:ausroll> ${AUSROLL_CHECKS_DIR}/bad_input
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(check/bad_input PROPERTIES LABELS check TIMEOUT 600)

# Follower pressure (finite strain): plane-strain thick ring A = 100, B = 200, Hencky elastic,
# E = 1000 MPa, internal pressure 0..100 MPa on the deformed surface (u(A) = 29 %): u(A) and u(B)
# within 0.1 % of the independent 1D shooting solution (benchmarks/reference/
# thick_shell_hencky.py); the scene reaches 6e-6. (A dead load of the same nominal pressure gives
# u(A) = 21.6 mm instead of 29.2 mm.)
ausroll_add_check(NAME thick_ring_follower_pressure
  PRM ${AUSROLL_CHECKS_DIR}/scenes/thick_ring_follower.prm
  CHECK ${AUSROLL_CHECKS_DIR}/compare_curves.py
  ARGS --result out/history.csv
       --reference ${AUSROLL_CHECKS_DIR}/reference/thick_ring_hencky.csv
       --x-result pressure_0 --y-result inner_ux --x-reference pressure --y-reference u_inner
       --rel-tol 0.001 --x-min 1)

# Follower pressure, axisymmetric (hoop stretch in the deformed area): thick sphere A = 100,
# B = 200, 0..200 MPa (u(A) = 25 %): u(A) within 0.1 % of the 1D solution (scene: 5e-6).
ausroll_add_check(NAME thick_sphere_follower_pressure
  PRM ${AUSROLL_CHECKS_DIR}/scenes/thick_sphere_follower.prm
  CHECK ${AUSROLL_CHECKS_DIR}/compare_curves.py
  ARGS --result out/history.csv
       --reference ${AUSROLL_CHECKS_DIR}/reference/thick_sphere_hencky.csv
       --x-result pressure_0 --y-result inner_ux --x-reference pressure --y-reference u_inner
       --rel-tol 0.001 --x-min 1)

# Scene checks that run several variants of a shipped scene (a Python driver calls ausroll).
# ausroll_add_script_check(NAME <name> SCRIPT <script.py>): python3 SCRIPT AUSROLL SOURCE_DIR.
function(ausroll_add_script_check)
  cmake_parse_arguments(C "" "NAME;SCRIPT" "" ${ARGN})
  set(_dir ${CMAKE_CURRENT_BINARY_DIR}/${C_NAME})
  file(MAKE_DIRECTORY ${_dir})
  add_test(NAME check/${C_NAME}
    COMMAND ${Python3_EXECUTABLE} ${C_SCRIPT} $<TARGET_FILE:ausroll> ${CMAKE_SOURCE_DIR}
    WORKING_DIRECTORY ${_dir})
  set_tests_properties(check/${C_NAME} PROPERTIES LABELS check TIMEOUT 900)
endfunction()

# Volumetric locking (prm/flat_punch.prm, rough flat punch, plane strain, small strain): Q1 F-bar
# limit pressure within 3 % of Prandtl's (2 + pi) k (measured +1.7 %), Q1 with full integration
# locks (+13.6 % at the end and still rising). About 15 s.
ausroll_add_script_check(NAME flat_punch_locking SCRIPT ${AUSROLL_CHECKS_DIR}/check_flat_punch.py)

# Cantilever (prm/cantilever.prm): total vs updated Lagrangian, elastica and Reissner beam
# references, 5 vs 100 increments, full roll-up by a follower end couple. About 25 s.
ausroll_add_script_check(NAME cantilever_large_deflection
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_cantilever.py)

# Upsetting (prm/upsetting.prm, coarse: Q2 8x6, 0.5 % and 1 % steps): step-size independence
# outside fold-over events (0.5 %), force and bulge at 30 % vs the Q2 16x12 reference (2 %, 1 %),
# small strain underestimates the load (> 20 %). About 25 s.
ausroll_add_script_check(NAME upsetting SCRIPT ${AUSROLL_CHECKS_DIR}/check_upsetting.py)
