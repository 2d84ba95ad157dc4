#!/usr/bin/env bash
# Installs what is missing, builds the benchmarks and runs one:
#   scripts/bench.sh [minmax] [ARGS]  minmax_pcf's traversal against brute force
#                                     on the Vulkan device (penumbra_bench_minmax)
#   scripts/bench.sh bytecode [ARGS]  vkd3d-compiler's time and Shader Model 3
#                                     slots per Direct3D file, slowest first
#                                     (penumbra_bench_bytecode)
#   scripts/bench.sh build [--baseline REV] [ARGS]
#                                     penumbra build's cold, warm and no-op times,
#                                     memory and index size, against a chain of
#                                     separate tools (penumbra_bench_build); with
#                                     --cold-only, cold builds alone: every form,
#                                     each --form F, and commit REV's penumbra
#                                     (built in build-baseline/), side by side
#   scripts/bench.sh accuracy [ARGS]  every variant's error against the exact
#                                     area light on the accuracy suite, with its
#                                     texel reads and time (penumbra_bench_accuracy)
#   scripts/bench.sh capped           backprojection where hlsl_dx9's step cap
#                                     binds, against the uncapped walk, on busy
#                                     maps and the report's stage
#                                     (penumbra_bench_capped, CPU only)
#   scripts/bench.sh cascades [ARGS]  cascaded variants' reference on the cascaded
#                                     stage: error per cascade against the exact
#                                     directional light, the jump at each boundary
#                                     (penumbra_bench_cascades, CPU only)
#   scripts/bench.sh jobs [ARGS]      verify and report with --jobs 1 against
#                                     --jobs N (every core), side by side, and
#                                     their results compared (penumbra_bench_jobs)
#   scripts/bench.sh gpu [ARGS]       every variant's GPU time on the report's
#                                     stage (timestamp queries) beside its error,
#                                     against the device's fetch-only texel rate
#                                     (penumbra_bench_gpu; --device D, --size WxH,
#                                     --variant V...)
#   scripts/bench.sh verify [--baseline REV] [ARGS]
#                                     verify of the default library by commit REV's
#                                     penumbra (built in build-baseline/; default:
#                                     this one run with --baseline-arg=ARG's) against
#                                     this one's, side by side, verify.json
#                                     compared (penumbra_bench_verify; --cold,
#                                     --repeats R, --variant V..., --manifest F)
# ARGS go to the benchmark, e.g. scripts/bench.sh --repeats 9.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

bench=minmax
if [[ $# -gt 0 && ($1 == minmax || $1 == bytecode || $1 == build || $1 == accuracy ||
  $1 == capped || $1 == cascades || $1 == jobs || $1 == gpu || $1 == verify) ]]; then
  bench=$1
  shift
fi
install_missing_packages
if [[ $bench == bytecode || $bench == jobs || $bench == verify ||
  ($bench == build && " $* " == *" --bytecode "*) ]]; then
  install_hlsl_compiler
fi

# build_baseline REV: commit REV's penumbra, built as build/ is (the
# benchmark compares like with like) in build-baseline/ from a worktree of
# it there; prints the executable's path.
build_baseline() {
  local rev
  if ! rev="$(git rev-parse --verify --quiet "$1^{commit}")"; then
    echo "bench.sh: error: --baseline $1: no such commit in this checkout" >&2
    exit 2
  fi
  local dir=build-baseline
  if [ ! -e "$dir/source/.git" ]; then
    rm -rf "$dir/source"
    git worktree add --force --detach "$dir/source" "$rev" >&2
  fi
  git -C "$dir/source" checkout --quiet --detach "$rev"
  (cd "$dir/source" && configure_and_build ../build penumbra_cli "${PENUMBRA_DEVELOPER_CONFIG[@]}" >&2)
  # verify's Wine paths need the Direct3D host, a target of its own.
  if cmake --build "$dir/build" --target help | grep -q '^[^ ]*penumbra_d3d_host'; then
    cmake --build "$dir/build" --target penumbra_d3d_host >&2
  fi
  echo "$PWD/$dir/build/penumbra"
}

args=("$@")
if [[ $bench == verify || $bench == build ]]; then
  args=()
  while [[ $# -gt 0 ]]; do
    if [[ $1 == --baseline && $# -gt 1 ]]; then
      baseline="$(build_baseline "$2")" # exits here when it fails (set -e)
      args+=(--baseline "$baseline")
      shift 2
    else
      args+=("$1")
      shift
    fi
  done
fi
configure_and_build build "penumbra_bench_$bench" "${PENUMBRA_DEVELOPER_CONFIG[@]}"
# One Xvfb and Wine prefix for every verify and report the benchmark runs.
if [[ $bench == jobs || $bench == verify ]]; then start_wine_session; fi
"build/bench/penumbra_bench_$bench" "${args[@]}"
