# Scene checks, Disk rolling (ring boundary profile, 2D and 3D).
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- disk rolling (ring, profile)
# Boundary profile on a full ring (Geometry/Type = ring) under internal pressure with the outer
# circle held: every bore node moves radially by Lame's u(a) within 0.2 % (Q2 24 x 4 mesh: 2e-4),
# reference points on the exact circles (1e-9 mm), on 1 rank, with hanging nodes, and np = 2
# writing the same file as np = 1 (1e-9 mm). About 5 s.
ausroll_add_script_check(NAME ring_boundary_profile
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_boundary_profile.py)

# Short disk rolling (coarse ring, feed 0.762 mm + 20 degrees in 1.25 degree steps), run with the
# nested active set and with the load-increment ratio: force sign, Coulomb bound
# |F_t| <= 1.05 mu |F_r|, symmetric indentation (F_x = 0 to 1e-6 |F|), |F| within the slab/Prandtl
# estimate [1990, 10250] N/mm (derivation in check_disk_rolling.py), and the two strategies within
# 5 % at every step, 2 % in the mean (measured 3.0 %, +0.4 %). About 3 s CPU.
ausroll_add_script_check(NAME disk_rolling_short SCRIPT ${AUSROLL_CHECKS_DIR}/check_disk_rolling.py)

# Resolved disk scene (prm/disk_rolling.prm), feed + 20 degrees: its speed settings
# (Status pass tolerance 3e-2, Residual tolerance 1e-7, Interval 8) against the tight defaults,
# |F| within 1 % per step and 0.2 % in the mean (measured 0.37 %, +0.06 %), plus force sign,
# slab/Prandtl bracket and Coulomb bound (check_disk_rolling_resolved.py). About 6 s CPU.
ausroll_add_script_check(NAME disk_rolling_resolved_short
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_disk_rolling_resolved.py)

# Disk rolling (short: feed + 20 degrees, nested active set with Coulomb friction) on 1 and 2
# ranks: every history column within 1e-8 of its largest value.
ausroll_add_parallel_check(NAME disk_rolling_short_np2
  PRM ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_short.prm HISTORY out/history.csv)

# ---------------------------------------------------------------- 3D disk rolling (issue 15)
# check_disk_rolling_3d.py: (1) disk_rolling_short as a 1 mm 3D slice (u_z = 0 on both faces,
# cylinder die, Coulomb 0.3, nested active set) equals the 2D run (1e-6; measured 3e-8) in the same 20 steps
# without cutbacks; (2) the short round-faced (torus) and flat-faced (cylinder) die runs of
# prm/disk_rolling_3d_{round,flat}.prm: force sign, Coulomb cone per node (1e-8), mirror symmetry
# during the feed (1e-6), outward lateral flow of the side face, more for the flat die. About 20 s
# CPU.
ausroll_add_script_check(NAME disk_rolling_3d_short SCRIPT ${AUSROLL_CHECKS_DIR}/check_disk_rolling_3d.py)

# Short 3D round-faced die run on 1 and 2 ranks: every history column within 1e-8 of its largest.
ausroll_add_parallel_check(NAME disk_rolling_3d_round_short_np2
  PRM ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_round_short.prm HISTORY out/history.csv)

# Adaptivity following the die in 3D (issue 15, item 4): the short round-faced die run with the
# contact band refinement (band 6 mm, level 1, re-adapted every step, 10 degrees rolled): mesh
# adapted while rolling, every output sub-cell within 3 mm of a closed contact node at level 1,
# force sign, Coulomb cone per node (1e-8). About 21 s CPU. The np = 2 twin stops after two rolling
# steps (t = 6: refinement at the die and material-point transfer on two ranks) and equals np = 1
# to 1e-8; about 45 s CPU (14.8 s on 1 rank + 29.4 s on 2 ranks, measured on the loaded machine).
ausroll_add_script_check(NAME disk_rolling_3d_round_adaptive_short
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_disk_rolling_3d_adaptive.py)
set(_disk3d_adaptive_np2 ${CMAKE_CURRENT_BINARY_DIR}/disk_rolling_3d_round_adaptive_np2.prm)
execute_process(COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/scripts/prm_variant.py
    ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_round_adaptive_short.prm ${_disk3d_adaptive_np2}
    "Loading/End time = 6" "Loading/Number of steps = 6" "Output/Write VTU = false"
  COMMAND_ERROR_IS_FATAL ANY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_round_adaptive_short.prm)
ausroll_add_parallel_check(NAME disk_rolling_3d_round_adaptive_short_np2
  PRM ${_disk3d_adaptive_np2} HISTORY out/history.csv)

# Coarsening behind the die in 3D (issue 15, item 4): the short adaptive round run with the narrow
# band of prm/disk_rolling_3d_round_adaptive.prm (2 mm, Keep plastic strain above = 0.05), fed at
# 90 degrees, lifted, moved 90 degrees while lifted (one step stands for the rolling past) and fed
# again: the cell count drops, every coarse cell more than 60 degrees from the die is back at level
# 0 or kept at level 1 by its plastic strain (the groove), the new groove is at level 1, force sign,
# no force while lifted, Coulomb cone per node (1e-8). About 11 s CPU. The np = 2 twin (coarsening
# and material-point transfer on two ranks) equals np = 1 to 1e-7 of each column's largest value:
# the tangential force is nominally zero here (die fed normal to the rim), its largest value is
# 1.4e-3 N (1e-7 of the radial force) and its np difference 1.5e-11 N, round-off of the 1.25e4 N
# radial force, i.e. 1.07e-8 of that column (measured); every other column within 8.9e-10.
ausroll_add_script_check(NAME disk_rolling_3d_round_coarsen_short
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_disk_rolling_3d_coarsen.py)
ausroll_add_parallel_check(NAME disk_rolling_3d_round_coarsen_short_np2 TOL 1e-7
  PRM ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_round_coarsen_short.prm HISTORY out/history.csv)

# Coarsening behind the die WHILE ROLLING in 3D (issue 15, item 4): the short adaptive round run
# with the 2 mm band and a short Coarsening distance of 2 mm (level-1 cells coarsen 11.1 mm from the
# die instead of 22 mm), fed at 90 degrees and rolled 17.5 degrees in 2.5 degree steps, re-adapted
# after every step: an adaptation after a rolling step coarsens cells (log line; the cell count
# drops and the next rolling step runs on the coarser mesh), the coarse cells back at level 0 lie
# behind the die (>= 15 degrees), the groove at the die stays at level 1, force_radial < 0 and
# within 2 % of the same position in the 7.5 degree cell pattern after the coarsening, Coulomb cone
# per node (1e-8). About 19 s CPU. The np = 2 twin (coarsening and material-point transfer across two
# ranks while rolling) equals np = 1 to 1e-8 of each column's largest value.
ausroll_add_script_check(NAME disk_rolling_3d_round_coarsen_rolling
  SCRIPT ${AUSROLL_CHECKS_DIR}/check_disk_rolling_3d_coarsen_rolling.py)
ausroll_add_parallel_check(NAME disk_rolling_3d_round_coarsen_rolling_np2
  PRM ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_round_coarsen_rolling.prm HISTORY out/history.csv)

# np = 1 against np = 2 for the other 3D disk checks (issue 39, item 4: every 3D scene's short check
# on 1 and 2 ranks, every history column within 1e-8 of its largest value):
# - the flat-faced die (scenes/disk_rolling_3d_flat_short.prm) cut after the feed and one 1.25
#   degree rolling step (t = 5 of 6): contact across the whole thickness, rounded die edges,
#   Coulomb slip. Measured 2026-12-07 (ctest, load 9-12): 5 steps, 65 Newton solves, np = 1 5.1 s
#   CPU; the 6-step run: np = 2 equal to 5e-14 of each column's largest value.
# - the plane-strain slice (scenes/disk_rolling_3d_slice.prm) cut after the feed and 5 degrees
#   (t = 8 of 20): 8 steps, 53 Newton solves, np = 1 1.8 s CPU; the 20-step run: np = 2 equal.
# On the loaded machine the np = 2 runs take 2-5 times their CPU in wall time (the ranks wait for
# the cores); on an idle machine each check is its np = 1 CPU plus about half of it.
foreach(_case "flat_short|5" "slice|8")
  string(REPLACE "|" ";" _case "${_case}")
  list(GET _case 0 _name)
  list(GET _case 1 _end)
  set(_prm ${CMAKE_CURRENT_BINARY_DIR}/disk_rolling_3d_${_name}_np2.prm)
  execute_process(COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/scripts/prm_variant.py
      ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_${_name}.prm ${_prm}
      "Loading/End time = ${_end}" "Loading/Number of steps = ${_end}"
    COMMAND_ERROR_IS_FATAL ANY)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
    ${AUSROLL_CHECKS_DIR}/scenes/disk_rolling_3d_${_name}.prm)
  ausroll_add_parallel_check(NAME disk_rolling_3d_${_name}_np2 PRM ${_prm} HISTORY out/history.csv)
endforeach()
