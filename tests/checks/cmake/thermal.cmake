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

# TRIP and the mixture rule of the yield stress (check_thermal.py cases trip and mixture): a block
# cooled through Ms under a constant uniaxial stress against Leblond's closed form K sigma phi(f)
# (small strain, 1e-6; finite strain: the discrete law, 1e-8), and compressed while it transforms
# against the linear mixture of the yield stress in all four kinematics (1e-8); case carbon_yield:
# pure martensite at 0.2 and 0.8 wt% C with the yield stress and hardening modulus as expressions
# of C and T, compressed: the reaction against the uniaxial closed form (1e-8); case trip_heat:
# an insulated block transforming under a constant stress heated by the TRIP dissipation and the
# latent heat (1e-8 of the rise); case stabilisation: a pre-strained block cooled through the Ms
# lowered by the mechanical stabilisation (KM fraction, 1e-8); case quenched: Phases/Initial state
# = quenched, a 0.2 wt% C block starting at 250 C below its Ms with the KM fraction in its
# stress-free reference, cooled: fractions and free strain from it (1e-8). About 6 s.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/thermal_trip)
add_test(NAME check/thermal_trip
  COMMAND ${Python3_EXECUTABLE} ${AUSROLL_CHECKS_DIR}/check_thermal.py $<TARGET_FILE:ausroll>
          ${CMAKE_SOURCE_DIR} trip mixture carbon_yield trip_heat stabilisation quenched
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/thermal_trip)
set_tests_properties(check/thermal_trip PROPERTIES LABELS check TIMEOUT 900)

# The carburized case: a free bar with a carbon gradient through its thickness (Phases/Carbon
# content in the depth below one face) transforming to martensite on cooling, elastic: curvature,
# mean strain and axial stress against the beam with an eigenstrain, 1 % (measured 0.26 %)
# (tests/checks/check_carburized_bar.py); again on 16 cells through the thickness with
# Adaptivity/Case level = 2 refining the case (1 %, measured 0.26 %). About 7 s wall.
ausroll_add_script_check(NAME carburized_bar SCRIPT ${AUSROLL_CHECKS_DIR}/check_carburized_bar.py)
set_property(TEST check/carburized_bar APPEND PROPERTY LABELS quick)

# Process stages (tests/checks/check_stages.py on scenes/stage_quench.prm: a block quenched into
# a bath, held, cooled in air: the lumped closed form per stage, the stage ends as step ends, the
# history's stage column, one stage against none, a resume in the cooling stage on 1 and 2
# ranks). About 9 s.
ausroll_add_script_check(NAME stages SCRIPT ${AUSROLL_CHECKS_DIR}/check_stages.py)
set_tests_properties(check/stages PROPERTIES PROCESSORS 2)

# The 3D process chain (tests/checks/check_gear_chain_3d.py on scenes/gear_chain_3d_free.prm):
# the extruded gear tooth of prm/gear_ausrolling_chain_3d.prm with stages, the temperature field,
# martensite, TRIP and the mixture yield stress, cooled uniformly from 250 C to 20 C through Ms
# with the inner arc moving with the body's free strain, all austenite (0.5 wt% C) and quenched
# (0.1 wt% C, Phases/Initial state): stress-free (1e-3 MPa) and every node at lambda X,
# lambda = (1 + alpha dT) ((1 + f dV) / (1 + f0 dV))^(1/3) with the Koistinen-Marburger fraction
# (2e-7 mm in the VTU, 1e-9 mm at the monitored tooth tip, f to 1e-8); the quenched case on 2
# ranks: the same history (1e-8). About 5 s.
ausroll_add_script_check(NAME gear_chain_3d SCRIPT ${AUSROLL_CHECKS_DIR}/check_gear_chain_3d.py)
set_tests_properties(check/gear_chain_3d PROPERTIES PROCESSORS 2)
