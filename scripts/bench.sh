#!/usr/bin/env bash
# Installs what is missing, builds the benchmarks and runs penumbra_bench_minmax
# (minmax_pcf's min-max traversal against brute force on the Vulkan device).
# Arguments go to the benchmark, e.g. scripts/bench.sh --repeats 9.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

install_missing_packages
configure_and_build build penumbra_bench_minmax
build/bench/penumbra_bench_minmax "$@"
