#!/usr/bin/env bash
# The full test suite: set-up and Release build (with the MPI decomposition library, SPHMOL_MPI, so
# that its tests run under mpirun on 1-4 ranks), all Catch2 tests (unit, integration, parallel) via CTest,
# then the unit tests again under ASan+UBSan (only that target is built in the sanitizer tree),
# then 90 s of fuzzing (config loader, run command line, checkpoint reader, mesh reader).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh -DSPHMOL_MPI=ON
ctest --preset release -j "$(nproc)"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$(nproc)" --target sphmol-unit-tests
ctest --preset asan -j "$(nproc)"
scripts/fuzz.sh 90
