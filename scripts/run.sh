#!/usr/bin/env bash
# Installs what is missing, builds, generates the default shader library
# into out/ (with the Direct3D bytecode: install_hlsl_compiler), verifies
# every variant on lavapipe and writes the HTML report into out/report/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

install_missing_packages
install_hlsl_compiler
configure_and_build build penumbra_cli
./build/penumbra build permutations/default.json -o out -j "$(nproc)"
status=0
./build/penumbra verify out || status=$?
./build/penumbra report out || status=$?
echo
echo "Shader library: out/ (index.json lists every variant; one folder per target)"
echo "Verification:   out/verify.json"
echo "Report:         out/report/index.html (pictures and error figures per variant)"
exit "$status"
