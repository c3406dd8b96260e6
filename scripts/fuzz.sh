#!/usr/bin/env bash
# Fuzzes the config loader (fuzz/config_fuzz.cpp) with libFuzzer + ASan + UBSan for a bounded time
# (default 60 s; first argument overrides). Seeds: every shipped YAML. Fails on any crash, hang
# (> 10 s per input), leak or sanitizer report; the reproducer is left in build/fuzz/artifacts/.
# fuzz/seeds/ adds inputs with the "\0"-separated --set overrides part (see fuzz/config_fuzz.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
cmake --preset fuzz >/tmp/sphmol-fuzz-configure.log 2>&1 || { cat /tmp/sphmol-fuzz-configure.log; exit 1; }
cmake --build --preset fuzz --target sphmol-config-fuzz -j "$(nproc)"
seeds=build/fuzz/seeds corpus=build/fuzz/corpus artifacts=build/fuzz/artifacts
mkdir -p "$seeds" "$corpus" "$artifacts"
cp config/*.yaml verification/*.yaml fuzz/seeds/* "$seeds"/
build/fuzz/fuzz/sphmol-config-fuzz -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -print_final_stats=1 -artifact_prefix="$artifacts"/ "$corpus" "$seeds" 2>&1 | tail -n 15
echo "fuzz: no crash, hang or sanitizer report in ${seconds} s"
