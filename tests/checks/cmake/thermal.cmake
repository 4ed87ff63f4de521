# Thermal checks (tests/checks/check_thermal.py: conduction against erfc, adiabatic heating,
# free and clamped thermal expansion in 3D and plane strain, np = 2 against np = 1, resume).
ausroll_add_script_check(NAME thermal SCRIPT ${AUSROLL_CHECKS_DIR}/check_thermal.py)
set_tests_properties(check/thermal PROPERTIES PROCESSORS 2)

# The thermal gear on 1 and 2 ranks (contact heat on one rank only, adaptivity): every history
# column to 1e-8 of its largest magnitude. About 40 s CPU.
configure_file(${AUSROLL_CHECKS_DIR}/scenes/gear_ausrolling_np2.prm.in
  ${CMAKE_CURRENT_BINARY_DIR}/gear_ausrolling_np2.prm @ONLY)
ausroll_add_parallel_check(NAME gear_ausrolling_np2
  PRM ${CMAKE_CURRENT_BINARY_DIR}/gear_ausrolling_np2.prm HISTORY out/history.csv)

# Process stages (tests/checks/check_stages.py on scenes/stage_quench.prm: a block quenched into
# a bath, held, cooled in air: the lumped closed form per stage, the stage ends as step ends, the
# history's stage column, one stage against none, a resume in the cooling stage on 1 and 2
# ranks). About 9 s.
ausroll_add_script_check(NAME stages SCRIPT ${AUSROLL_CHECKS_DIR}/check_stages.py)
set_tests_properties(check/stages PROPERTIES PROCESSORS 2)
