#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/setup.sh

install_missing_packages
configure_and_build build
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
