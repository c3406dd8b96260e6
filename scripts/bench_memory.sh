#!/bin/sh
# Peak resident memory per particle of a short Taylor-Green run, one process per size (getrusage's
# peak covers the whole process, so sizes must not share one). Usage: scripts/bench_memory.sh [build dir]
set -e
BUILD=${1:-build/release}
for n in 10000 100000 1000000; do
  for fused in 0 1; do
    "$BUILD/sph-bench" --benchmark_filter="^Memory/n:$n/fused:$fused/" | grep '^Memory'
  done
done
