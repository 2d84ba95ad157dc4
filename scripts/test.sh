#!/usr/bin/env bash
# Installs what is missing (packages, vkd3d-compiler), builds, and runs the
# whole test suite (ctest), then each fuzzer for a short smoke run
# (scripts/fuzz.sh).
#
#   scripts/test.sh              in build/ (warnings as errors)
#   scripts/test.sh --sanitize   in build-sanitize/, built with ASan + UBSan
#                                (PENUMBRA_SANITIZE); any finding fails
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

sanitize=0
case "${1:-}" in
  "") ;;
  --sanitize) sanitize=1 ;;
  *) echo "scripts/test.sh: unknown argument '$1' (allowed: --sanitize)" >&2; exit 2 ;;
esac

install_missing_packages
install_hlsl_compiler
# Mesa's software rasterizers compile the suite's shaders without LLVM's
# optimizations, as penumbra verify has them do (docs/verification.md, "On
# every core"): the same results, most of the compile time saved. One test
# (cli_jobs_test.cpp) runs verify with the optimizations too.
export GALLIVM_PERF="${GALLIVM_PERF:-nopt}"
if [ "$sanitize" -eq 1 ]; then
  configure_and_build build-sanitize all "${PENUMBRA_DEVELOPER_CONFIG[@]}" -DPENUMBRA_SANITIZE=ON
  start_wine_session  # before LD_PRELOAD: Wine is not ours to sanitize
  # Leaks inside the graphics drivers (Mesa's lavapipe and EGL, LLVM) are
  # theirs, not ours: tests/sanitize/lsan.supp names them.
  # The Vulkan loader and EGL unload the software drivers (lavapipe, and
  # Mesa's swrast for GL) before LeakSanitizer looks at exit, leaving their
  # allocations in an "<unknown module>" no suppression can name; preloaded,
  # they stay. ASan then need not come first in the list.
  lavapipe=$(sed -n 's/.*"library_path": *"\([^"]*\)".*/\1/p' /usr/share/vulkan/icd.d/lvp_icd.*.json | head -n 1)
  swrast="$(dirname "$lavapipe")/dri/swrast_dri.so"
  export LD_PRELOAD="$lavapipe $swrast${LD_PRELOAD:+ $LD_PRELOAD}"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:verify_asan_link_order=0"
  export LSAN_OPTIONS="suppressions=$PWD/tests/sanitize/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)"
  exit 0
fi
configure_and_build build all "${PENUMBRA_DEVELOPER_CONFIG[@]}"
start_wine_session
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
bash scripts/fuzz.sh
