# Thermal checks (tests/checks/check_thermal.py: conduction against erfc, adiabatic heating,
# free and clamped thermal expansion in 3D and plane strain, np = 2 against np = 1, resume).
ausroll_add_script_check(NAME thermal SCRIPT ${AUSROLL_CHECKS_DIR}/check_thermal.py)
set_tests_properties(check/thermal PROPERTIES PROCESSORS 2)
