#!/usr/bin/env bash
# A user's main job: installs what is missing, builds penumbra in Release
# into build-release/ (no tests, warnings left as warnings; the Direct3D
# runtimes' host comes with it), generates the default shader library into
# out/ (with the Direct3D bytecode: install_hlsl_compiler), verifies every
# variant on every path (lavapipe, Mesa's OpenGL, Wine's Direct3D 9, 10 and
# 11) and writes the HTML report into out/report/.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

install_missing_packages
install_hlsl_compiler
configure_and_build build-release penumbra_cli "${PENUMBRA_USER_CONFIG[@]}"
./build-release/penumbra build permutations/default.json -o out -j "$(nproc)"
start_wine_session  # one Xvfb and Wine prefix for verify's and the report's d3d paths
status=0
./build-release/penumbra verify out || status=$?
./build-release/penumbra report out || status=$?
echo
echo "Shader library: out/ (index.json lists every variant; one folder per target)"
echo "Verification:   out/verify.json"
echo "Report:         out/report/index.html (pictures and error figures per variant)"
exit "$status"
