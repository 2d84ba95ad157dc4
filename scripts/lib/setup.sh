# Sourced by scripts/run.sh, test.sh and bench.sh: installs the Debian 12
# packages that are missing, then configures and builds with CMake + Ninja.

PENUMBRA_PACKAGES=(
  cmake ninja-build g++
  glslang-dev glslang-tools spirv-tools spirv-cross libspirv-cross-c-shared-dev spirv-headers
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  nlohmann-json3-dev libcli11-dev googletest libgtest-dev
  chromium
)

install_missing_packages() {
  local missing=()
  for pkg in "${PENUMBRA_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "penumbra: installing missing packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# configure_and_build BUILD_DIR [TARGET]: configures (tests on) and builds
# TARGET, or everything.
configure_and_build() {
  local build_dir="$1"
  local target="${2:-all}"
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPENUMBRA_BUILD_TESTS=ON
  cmake --build "$build_dir" --parallel "$(nproc)" --target "$target"
}
