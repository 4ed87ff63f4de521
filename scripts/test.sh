#!/usr/bin/env bash
# Usage: scripts/test.sh [ctest arguments]
# Installs what is missing (Debian 12), builds ausroll (Release, build/) and runs the test suite
# (serial and mpirun -np 2 tests; benchmarks excluded).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

ausroll_install_missing python3-vtk9
ausroll_build

cd "$BUILD_DIR"
ctest -LE benchmark -j "$JOBS" --output-on-failure --timeout 900 "$@"
