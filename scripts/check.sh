#!/usr/bin/env bash
# The full test suite: set-up and Release build, all Catch2 tests (unit + integration) via CTest,
# then the unit tests again under ASan+UBSan, then 60 s of fuzzing the config loader.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --preset release -j "$(nproc)"
SPHMOL_PRESET=asan scripts/setup.sh
ctest --preset asan -j "$(nproc)"
scripts/fuzz.sh 60
