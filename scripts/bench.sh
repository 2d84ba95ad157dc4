#!/usr/bin/env bash
# Installs what is missing, builds the benchmarks and runs one:
#   scripts/bench.sh [minmax] [ARGS]  minmax_pcf's traversal against brute force
#                                     on the Vulkan device (penumbra_bench_minmax)
#   scripts/bench.sh bytecode [ARGS]  vkd3d-compiler's time and Shader Model 3
#                                     slots per Direct3D file, slowest first
#                                     (penumbra_bench_bytecode)
#   scripts/bench.sh build [ARGS]     penumbra build's cold, warm and no-op times,
#                                     memory and index size, against a chain of
#                                     separate tools (penumbra_bench_build)
#   scripts/bench.sh accuracy [ARGS]  every variant's error against the exact
#                                     area light on the accuracy suite, with its
#                                     texel reads and time (penumbra_bench_accuracy)
#   scripts/bench.sh capped           backprojection where hlsl_dx9's step cap
#                                     binds, against the uncapped walk, on busy
#                                     maps and the report's stage
#                                     (penumbra_bench_capped, CPU only)
#   scripts/bench.sh jobs [ARGS]      verify and report with --jobs 1 against
#                                     --jobs N (every core), side by side, and
#                                     their results compared (penumbra_bench_jobs)
#   scripts/bench.sh gpu [ARGS]       every variant's GPU time on the report's
#                                     stage (timestamp queries) beside its error,
#                                     against the device's fetch-only texel rate
#                                     (penumbra_bench_gpu; --device D, --size WxH,
#                                     --variant V...)
# ARGS go to the benchmark, e.g. scripts/bench.sh --repeats 9.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

bench=minmax
if [[ $# -gt 0 && ($1 == minmax || $1 == bytecode || $1 == build || $1 == accuracy ||
  $1 == capped || $1 == jobs || $1 == gpu) ]]; then
  bench=$1
  shift
fi
install_missing_packages
if [[ $bench == bytecode || $bench == jobs || ($bench == build && " $* " == *" --bytecode "*) ]]; then
  install_hlsl_compiler
fi
configure_and_build build "penumbra_bench_$bench" "${PENUMBRA_DEVELOPER_CONFIG[@]}"
# One Xvfb and Wine prefix for every verify and report the benchmark runs.
if [[ $bench == jobs ]]; then start_wine_session; fi
"build/bench/penumbra_bench_$bench" "$@"
