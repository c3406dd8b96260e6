#!/usr/bin/env bash
# Fuzzes with libFuzzer + ASan + UBSan for a bounded total time (default 90 s; first argument
# overrides), split over four targets: the config loader (fuzz/config_fuzz.cpp, 40 %), the run
# command line with --set (fuzz/cli_fuzz.cpp), the checkpoint reader (fuzz/checkpoint_fuzz.cpp) and
# the triangle-mesh reader (fuzz/mesh_fuzz.cpp), 20 % each.
# Fails on any crash, hang (> 10 s per input), leak or sanitizer report; the
# reproducer is left in build/fuzz/artifacts/<target>/.
# Seeds: every shipped YAML (config, and the YAML part of the CLI inputs), fuzz/seeds/ (config with
# "\0"-separated --set overrides), fuzz/seeds-cli/ (argument lists) and fuzz/seeds-checkpoint/ (a
# checkpoint.json written by a short run) and fuzz/seeds-mesh/ (a cube in each mesh format).
set -euo pipefail
cd "$(dirname "$0")/.."
total="${1:-90}"
cmake --preset fuzz >/tmp/sphmol-fuzz-configure.log 2>&1 || { cat /tmp/sphmol-fuzz-configure.log; exit 1; }
cmake --build --preset fuzz --target sphmol-config-fuzz sphmol-cli-fuzz sphmol-checkpoint-fuzz sphmol-mesh-fuzz -j "$(nproc)"
# The CLI and checkpoint targets write their inputs to scratch files: keep them in the build tree.
export TMPDIR="$PWD/build/fuzz/tmp"
rm -rf "$TMPDIR"
mkdir -p "$TMPDIR"

fuzz() {  # target seconds max_len seed-dirs...
  local target="$1" seconds="$2" max_len="$3"
  shift 3
  local seeds="build/fuzz/seeds/$target" corpus="build/fuzz/corpus/$target" artifacts="build/fuzz/artifacts/$target"
  mkdir -p "$seeds" "$corpus" "$artifacts"
  cp "$@" "$seeds"/
  echo "fuzz: $target for ${seconds} s"
  build/fuzz/fuzz/"$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
    -print_final_stats=1 -artifact_prefix="$artifacts"/ "$corpus" "$seeds" 2>&1 | tail -n 15
}

big=$((total * 2 / 5)) small=$((total / 5))
fuzz sphmol-config-fuzz "$big" 4096 config/*.yaml verification/*.yaml fuzz/seeds/*
# CLI inputs: "YAML\0arguments"; the shipped YAML alone is a seed too (no arguments).
fuzz sphmol-cli-fuzz "$small" 4096 fuzz/seeds-cli/* verification/couette.yaml
fuzz sphmol-checkpoint-fuzz "$small" 65536 fuzz/seeds-checkpoint/*
fuzz sphmol-mesh-fuzz "$small" 16384 fuzz/seeds-mesh/*
rm -rf "$TMPDIR"
echo "fuzz: no crash, hang or sanitizer report in ${total} s"
