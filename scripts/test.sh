#!/usr/bin/env bash
# Installs what is missing (packages, vkd3d-compiler), builds, and runs the
# whole test suite (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

install_missing_packages
install_hlsl_compiler
configure_and_build build
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
