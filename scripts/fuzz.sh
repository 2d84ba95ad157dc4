#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/: clang, ASan + UBSan) in build-fuzz and
# runs each on its seed corpus, tests/fuzz/NAME. New inputs go to
# build-fuzz/corpus/NAME, crashing ones to build-fuzz/artifacts/.
#
#   scripts/fuzz.sh              each fuzzer for 20 seconds (the CI smoke run)
#   scripts/fuzz.sh --time S     each fuzzer for S seconds
#   scripts/fuzz.sh --runs N     each fuzzer for N executions
#   scripts/fuzz.sh ... NAME...  only these fuzzers (manifest, pfm, index)
#
# Prints each fuzzer's executions; exits 1 on the first crash, leak or
# sanitizer finding.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

limit=(-max_total_time=20)
fuzzers=()
while [ $# -gt 0 ]; do
  case "$1" in
    --time) limit=(-max_total_time="$2"); shift 2 ;;
    --runs) limit=(-runs="$2"); shift 2 ;;
    manifest|pfm|index) fuzzers+=("$1"); shift ;;
    *) echo "scripts/fuzz.sh: unknown argument '$1' (allowed: --time S, --runs N, manifest, pfm, index)" >&2; exit 2 ;;
  esac
done
[ ${#fuzzers[@]} -gt 0 ] || fuzzers=(manifest pfm index)

install_missing_packages
targets=()
for name in "${fuzzers[@]}"; do targets+=("penumbra_fuzz_$name"); done
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPENUMBRA_FUZZ=ON -DPENUMBRA_WERROR=ON -DPENUMBRA_BUILD_TESTS=OFF -DPENUMBRA_BUILD_RUNTIME=OFF \
  -DPENUMBRA_BUILD_GL=OFF -DPENUMBRA_BUILD_BENCH=OFF > /dev/null
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]}"

mkdir -p build-fuzz/artifacts
for name in "${fuzzers[@]}"; do
  mkdir -p "build-fuzz/corpus/$name"
  log="build-fuzz/$name.log"
  status=0
  "build-fuzz/fuzz/penumbra_fuzz_$name" "build-fuzz/corpus/$name" "tests/fuzz/$name" \
    -dict=tests/fuzz/"$name".dict -seed=1 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -artifact_prefix=build-fuzz/artifacts/"$name"- "${limit[@]}" > "$log" 2>&1 || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  if [ "$status" -ne 0 ]; then
    tail -n 40 "$log" >&2
    echo "fuzz $name: FAILED after ${runs:-?} executions (log: $log; input under build-fuzz/artifacts/)" >&2
    exit 1
  fi
  echo "fuzz $name: ${runs} executions, no crash"
done
