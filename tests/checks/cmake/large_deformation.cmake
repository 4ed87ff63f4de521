# Scene checks, Large deformation: follower pressure, 3D against 2D, locking, cantilever, upsetting.
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- large deformation
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


# 3D against 2D: a block extruded along z with u_z = 0 on both z faces, pressed by a frictionless
# cylinder, reproduces the plane-strain 2D scene with a circle die (same x-y mesh): histories
# within 1e-8 (the discrete problems are the same; measured equal to 10 digits). A few seconds.
ausroll_add_script_check(NAME scene3d_plane_strain_cylinder SCRIPT ${AUSROLL_CHECKS_DIR}/check_plane_strain_3d.py)

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
