# Scene checks, Output: ParaView/VTK files and the field plot script.
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# ---------------------------------------------------------------- ParaView / VTK
configure_file(${AUSROLL_CHECKS_DIR}/scenes/block_press_vtu.prm.in ${CMAKE_CURRENT_BINARY_DIR}/block_press_vtu.prm @ONLY)
# solution.pvd and the .pvtu/.vtu files open with VTK's readers, carry the documented fields, and
# hold the exact uniform state of the pressed block: sigma_yy = -E/(1-nu^2) * 0.002 = -461.538 MPa
# in every cell (1e-6: float32 output), u_y between -0.010 mm (top) and 0 (base).
# Skipped (exit 77) when python3-vtk9 is not installed; scripts/test.sh installs it.
ausroll_add_check(NAME paraview_vtu_block_press
  PRM ${CMAKE_CURRENT_BINARY_DIR}/block_press_vtu.prm
  CHECK ${AUSROLL_CHECKS_DIR}/check_vtu.py
  ARGS out --expect-cell stress_yy -461.5384615 1e-6 --expect-cell stress_xx 0 1e30
       --expect-point-range displacement 1 -0.0100001 1e-9)
set_tests_properties(check/paraview_vtu_block_press PROPERTIES SKIP_REGULAR_EXPRESSION "SKIPPED: VTK")
# scripts/plot_field.py draws a field of that output (reads the .pvd, writes a PNG); runs after
# the check above, on its output directory.
add_test(NAME check/plot_field_script
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/scripts/plot_field.py
          paraview_vtu_block_press/out/solution.pvd stress_yy --warp 10 --edges --mirror x -o plot_field.png
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(check/plot_field_script PROPERTIES LABELS check
  DEPENDS check/paraview_vtu_block_press REQUIRED_FILES ${CMAKE_CURRENT_BINARY_DIR}/paraview_vtu_block_press/out/solution.pvd
  PASS_REGULAR_EXPRESSION "wrote plot_field.png")
# ---------------------------------------------------------------- output files (issues 39, 40)
# check_output_files.py: the dies as geometry (dies.pvd, points on the analytic cylinder at their
# time to 1e-10 R, 2D and 3D, np = 2, after a resume), the units files of history.csv and the VTU
# arrays, parameters.prm (its run repeats history.csv exactly; --print-parameters FILE.prm), the
# summary at Verbosity = quiet (peak die force = max |F| of history.csv), and in 3D all six
# stress and strain components obeying Hooke's law cell by cell (VTK for Python; 77 = skipped).
# scenes/cylinder_block_{2d,3d}.prm, 4 steps each. About 10 s CPU.
ausroll_add_script_check(NAME output_files SCRIPT ${AUSROLL_CHECKS_DIR}/check_output_files.py)
set_tests_properties(check/output_files PROPERTIES SKIP_RETURN_CODE 77)

# Depth probes (Postprocess/Depth probes) on Lame's thick cylinder: each starts on the exact
# circle at its angle (1e-9 mm), runs along the normal for its depth, and gives stress_nn,
# stress_tt, stress_nt = sigma_rr, sigma_tt, 0 of the closed form within 0.5 % of p. About 1 s.
ausroll_add_script_check(NAME depth_probe SCRIPT ${AUSROLL_CHECKS_DIR}/check_depth_probe.py)
