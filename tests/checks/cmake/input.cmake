# Scene checks, Malformed input (tests/checks/bad_input/) and the generated parameter documentation.
# Included by tests/checks/CMakeLists.txt (helpers: ausroll_add_check, ausroll_add_parallel_check,
# ausroll_add_script_check, ausroll_add_resume_check there).

# Malformed input files: clear message naming the entry, exit status 2, no output left behind.
# Every case of tests/checks/bad_input/ runs in exactly one of the shards (the K-th takes every
# AUSROLL_BAD_INPUT_SHARDS-th case from the K-th on), so that ctest -j runs them side by side.
set(AUSROLL_BAD_INPUT_SHARDS 4)
foreach(_k RANGE 1 ${AUSROLL_BAD_INPUT_SHARDS})
  set(_name check/bad_input/shard_${_k}_of_${AUSROLL_BAD_INPUT_SHARDS})
  add_test(NAME ${_name}
    COMMAND ${Python3_EXECUTABLE} ${AUSROLL_CHECKS_DIR}/check_bad_inputs.py
            $<TARGET_FILE:ausroll> ${AUSROLL_CHECKS_DIR}/bad_input
            --shard ${_k}/${AUSROLL_BAD_INPUT_SHARDS}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${_name} PROPERTIES LABELS "check;quick" TIMEOUT 600)
endforeach()

# ---------------------------------------------------------------- documentation
# doc/parameters.md must be exactly what `ausroll --print-parameters=markdown` prints (regenerate
# with scripts/update_docs.sh after adding or changing a parameter).
add_test(NAME check/parameters_doc_current
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:ausroll> -DDOC=${CMAKE_SOURCE_DIR}/doc/parameters.md
          -DOUT=${CMAKE_CURRENT_BINARY_DIR}/parameters.md -P ${AUSROLL_CHECKS_DIR}/run_doc_check.cmake)
set_tests_properties(check/parameters_doc_current PROPERTIES LABELS "check;quick")

# `--check-input` on a 2D and a 3D shipped scene: exit 0, the sizes printed, nothing written; a
# refused entry: exit 2, nothing written. A few seconds.
ausroll_add_script_check(NAME check_input_mode SCRIPT ${AUSROLL_CHECKS_DIR}/check_input_mode.py)

# Abaqus mesh import (Geometry/Mesh file = block_5x2.inp, surfaces SS1..SS3 as boundary ids): the
# pressed block agrees with the same mesh built internally (1e-9) and the analytic die force
# (1e-6). A few seconds.
ausroll_add_script_check(NAME abaqus_mesh SCRIPT ${AUSROLL_CHECKS_DIR}/check_abaqus_mesh.py)
