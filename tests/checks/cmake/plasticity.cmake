# Scene checks, Thick cylinder against the 1D radial solution, with the direct and the iterative linear solvers.
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

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

# Iterative linear solvers (not used by any other test): the thick cylinder with CG + AMG and with
# GMRES + AMG, u(b) along the load path within the same 0.5 % of the 1D reference as the direct
# solver (their linear tolerance 1e-10 is far below the Newton tolerance). One rank: on 2 ranks
# sharing busy cores the many AMG/Krylov reductions made the CG run take 245 s instead of 6 s.
foreach(_method cg gmres)
  configure_file(${AUSROLL_CHECKS_DIR}/scenes/thick_cylinder_${_method}.prm.in
                 ${CMAKE_CURRENT_BINARY_DIR}/thick_cylinder_${_method}.prm @ONLY)
  ausroll_add_check(NAME thick_cylinder_${_method}_amg
    PRM ${CMAKE_CURRENT_BINARY_DIR}/thick_cylinder_${_method}.prm
    CHECK ${AUSROLL_CHECKS_DIR}/compare_curves.py
    ARGS --result out/history.csv
         --reference ${AUSROLL_CHECKS_DIR}/reference/thick_cylinder_load.csv
         --x-result pressure_0 --y-result outer_ux --x-reference pressure --y-reference u_outer
         --rel-tol 0.005 --x-min 1)
endforeach()

# Generalized plane strain (tests/checks/check_generalized_plane_strain.py): a free section heated
# uniformly is stress-free with lambda = 1 + alpha dT (small strain; finite strain with Q1 F-bar),
# beside plane strain's sigma_zz = -E alpha dT (1e-8); the open-ended elastic Lame cylinder,
# eps_zz = -2 nu p a^2 / (E (b^2 - a^2)), sigma_zz = 0 (1e-5, the mesh's FE error); np = 2 equal
# to np = 1 (1e-10); a resume identical to the uninterrupted run.
ausroll_add_script_check(NAME generalized_plane_strain
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_generalized_plane_strain.py)
set_tests_properties(check/generalized_plane_strain PROPERTIES PROCESSORS 2)
