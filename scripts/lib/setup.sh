# shellcheck shell=bash
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
  libtbb-dev  # oneTBB: verify and report on every core
  chromium
  clang libclang-rt-14-dev  # libFuzzer and the sanitizers' runtimes (scripts/fuzz.sh)
  # The real Direct3D 9/10/11 runtimes (Wine's, over llvmpipe under Xvfb) and
  # the compiler of penumbra_d3d_host.exe, which runs on them.
  wine64 wine xvfb xauth g++-mingw-w64-x86-64
)

install_missing_packages() {
  local missing=()
  for pkg in "${PENUMBRA_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  # npm installs the three.js example's packages (tests/threejs). A machine
  # whose Node.js comes from elsewhere keeps its own npm.
  command -v npm >/dev/null 2>&1 || missing+=(nodejs npm)
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "penumbra: installing missing packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# Where scripts/lib/sid-tools.sh installs vkd3d-compiler (its default when
# XDG_CACHE_HOME is unset); `penumbra build` looks there too.
PENUMBRA_VKD3D_DIR="${PENUMBRA_VKD3D_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/penumbra/vkd3d}"

# install_hlsl_compiler: vkd3d-compiler 2.1 (Wine's HLSL compiler, for the
# Direct3D bytecode), installed once from Debian's unstable archive into
# PENUMBRA_VKD3D_DIR (scripts/lib/sid-tools.sh), exported as
# PENUMBRA_HLSL_COMPILER for CMake, `penumbra build` and the tests. An
# already exported executable is kept. Fails when it cannot be had: the
# bytecode and its tests need it.
install_hlsl_compiler() {
  if [ -n "${PENUMBRA_HLSL_COMPILER:-}" ] && [ -x "$PENUMBRA_HLSL_COMPILER" ]; then
    return 0
  fi
  local wrapper
  if ! wrapper="$(bash "$(dirname "${BASH_SOURCE[0]}")/sid-tools.sh" vkd3d \
    --dir "$PENUMBRA_VKD3D_DIR" | tail -n 1)" || [ ! -x "$wrapper" ]; then
    echo "penumbra: error: vkd3d-compiler could not be installed into $PENUMBRA_VKD3D_DIR" \
      "(above: why); the Direct3D bytecode and its tests need it" >&2
    return 1
  fi
  export PENUMBRA_HLSL_COMPILER="$wrapper"
}

# The two ways the scripts configure. Developers' (scripts/test.sh, bench.sh
# and CI): the tests, warnings as errors. Users' (scripts/run.sh): Release,
# no tests, and a newer compiler's new warning left a warning.
# shellcheck disable=SC2034  # used by the scripts that source this file
PENUMBRA_DEVELOPER_CONFIG=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DPENUMBRA_BUILD_TESTS=ON
  -DPENUMBRA_WERROR=ON)
# shellcheck disable=SC2034
PENUMBRA_USER_CONFIG=(-DCMAKE_BUILD_TYPE=Release -DPENUMBRA_BUILD_TESTS=OFF -DPENUMBRA_WERROR=OFF)

# configure_and_build BUILD_DIR TARGET CMAKE_ARG...: configures with Ninja,
# the HLSL compiler of install_hlsl_compiler when there is one, and the
# CMAKE_ARGs (one of the configurations above, then any more), and builds
# TARGET ("all" for everything).
configure_and_build() {
  local build_dir="$1"
  local target="$2"
  shift 2
  local hlsl=()
  if [ -n "${PENUMBRA_HLSL_COMPILER:-}" ]; then hlsl=("-DPENUMBRA_HLSL_COMPILER=$PENUMBRA_HLSL_COMPILER"); fi
  cmake -S . -B "$build_dir" -G Ninja "${hlsl[@]}" "$@"
  cmake --build "$build_dir" --parallel "$(nproc)" --target "$target"
}

# start_wine_session: one Xvfb display and one private Wine prefix for the
# whole suite, exported as DISPLAY and WINEPREFIX (verify's Direct3D paths
# use them instead of starting their own per process), with a persistent
# wineserver so that each host process starts in about a second. Ended, and
# the prefix removed, when the calling shell exits.
start_wine_session() {
  PENUMBRA_WINE_DIR="$(mktemp -d "${TMPDIR:-/tmp}/penumbra-suite-wine-XXXXXX")"
  Xvfb -displayfd 3 -screen 0 640x480x24 -nolisten tcp 3>"$PENUMBRA_WINE_DIR/display" \
    >/dev/null 2>&1 &
  PENUMBRA_XVFB_PID=$!
  trap end_wine_session EXIT
  local waited=0
  until [ -s "$PENUMBRA_WINE_DIR/display" ] || [ "$waited" -ge 300 ]; do
    sleep 0.1
    waited=$((waited + 1))
  done
  if [ ! -s "$PENUMBRA_WINE_DIR/display" ]; then
    echo "penumbra: error: Xvfb named no display within 30 s" >&2
    return 1
  fi
  export DISPLAY=":$(head -n 1 "$PENUMBRA_WINE_DIR/display")"
  export WINEPREFIX="$PENUMBRA_WINE_DIR/prefix" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
  mkdir -p "$WINEPREFIX"
  wineserver -p  # before anything starts one: it answers 2 when one runs already
  if ! wineboot -i >"$PENUMBRA_WINE_DIR/wineboot.log" 2>&1; then
    echo "penumbra: error: wineboot could not make the Wine prefix $WINEPREFIX:" >&2
    cat "$PENUMBRA_WINE_DIR/wineboot.log" >&2
    return 1
  fi
  echo "penumbra: Wine prefix $WINEPREFIX on display $DISPLAY"
}

end_wine_session() {
  if [ -n "${WINEPREFIX:-}" ]; then wineserver -k >/dev/null 2>&1 || true; fi
  if [ -n "${PENUMBRA_XVFB_PID:-}" ]; then kill "$PENUMBRA_XVFB_PID" 2>/dev/null || true; fi
  if [ -n "${PENUMBRA_WINE_DIR:-}" ]; then rm -rf "$PENUMBRA_WINE_DIR"; fi
}
