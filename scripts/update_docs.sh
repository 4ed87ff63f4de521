#!/usr/bin/env bash
# Usage: scripts/update_docs.sh [path/to/ausroll]
# Regenerates doc/parameters.md from `ausroll --print-parameters=markdown` (builds ausroll first
# when no executable is given). The ctest `check/parameters_doc_current` fails when the committed
# file differs from what the executable prints, so run this after adding or changing a parameter.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
EXE="${1:-}"
if [ -z "$EXE" ]; then
  source "$ROOT/scripts/setup.sh"
  ausroll_build
  EXE="$BUILD_DIR/ausroll"
fi
"$EXE" --print-parameters=markdown > "$ROOT/doc/parameters.md.tmp"
mv "$ROOT/doc/parameters.md.tmp" "$ROOT/doc/parameters.md"
echo "wrote $ROOT/doc/parameters.md"
