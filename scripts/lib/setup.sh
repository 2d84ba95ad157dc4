# Sourced by scripts/run.sh, test.sh and bench.sh: installs the Debian 12
# packages that are missing and the HLSL compiler, then configures and
# builds with CMake + Ninja.

PENUMBRA_PACKAGES=(
  cmake ninja-build g++
  glslang-dev glslang-tools spirv-tools spirv-cross libspirv-cross-c-shared-dev spirv-headers
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  nlohmann-json3-dev libcli11-dev libpugixml-dev googletest libgtest-dev libxxhash-dev
  libpng-dev
  chromium
  clang libclang-rt-14-dev  # libFuzzer and the sanitizers' runtimes (scripts/fuzz.sh)
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

# Where ../shared/tools/fetch-vkd3d installs vkd3d-compiler (its own default
# when XDG_CACHE_HOME is unset); `penumbra build` looks there too.
PENUMBRA_VKD3D_DIR="${PENUMBRA_VKD3D_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/penumbra/vkd3d}"

# install_hlsl_compiler: vkd3d-compiler 2.1 (Wine's HLSL compiler, for the
# Direct3D bytecode), installed once into PENUMBRA_VKD3D_DIR, exported as
# PENUMBRA_HLSL_COMPILER for CMake, `penumbra build` and the tests. An
# already exported executable is kept. Fails when it cannot be had: the
# bytecode tests need it.
install_hlsl_compiler() {
  if [ -n "${PENUMBRA_HLSL_COMPILER:-}" ] && [ -x "$PENUMBRA_HLSL_COMPILER" ]; then
    return 0
  fi
  local fetch="../shared/tools/fetch-vkd3d"
  if [ ! -f "$fetch" ]; then
    echo "penumbra: error: $fetch is missing; it installs vkd3d-compiler, which the build's bytecode and its tests need" >&2
    return 1
  fi
  local wrapper
  wrapper="$(bash "$fetch" "$PENUMBRA_VKD3D_DIR" | tail -n 1)"
  if [ ! -x "$wrapper" ]; then
    echo "penumbra: error: fetch-vkd3d did not install vkd3d-compiler into $PENUMBRA_VKD3D_DIR" >&2
    return 1
  fi
  export PENUMBRA_HLSL_COMPILER="$wrapper"
}

# configure_and_build BUILD_DIR [TARGET [CMAKE_ARG...]]: configures (tests
# on, warnings as errors, with the HLSL compiler of install_hlsl_compiler
# when there is one, then CMAKE_ARGs) and builds TARGET, or everything.
configure_and_build() {
  local build_dir="$1"
  local target="${2:-all}"
  shift $(($# < 2 ? $# : 2))
  local hlsl=()
  if [ -n "${PENUMBRA_HLSL_COMPILER:-}" ]; then hlsl=("-DPENUMBRA_HLSL_COMPILER=$PENUMBRA_HLSL_COMPILER"); fi
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPENUMBRA_BUILD_TESTS=ON \
    -DPENUMBRA_WERROR=ON "${hlsl[@]}" "$@"
  cmake --build "$build_dir" --parallel "$(nproc)" --target "$target"
}
