#!/usr/bin/env bash
# Packs a build's penumbra executables to run on an x86-64 Linux machine
# that has a GPU driver but none of Debian 12's packages (docs/verification.md,
# "On real GPUs"):
#
#   scripts/pack-portable.sh BUILD_DIR [DEST]     DEST defaults to .portable/
#
# DEST holds stripped copies of BUILD_DIR's penumbra* executables (the
# benchmarks included), the shared libraries they need beyond the C and C++
# runtimes (libpng, zlib, ...), the Vulkan, EGL and OpenGL loaders as Debian
# 12 packages (unpacked there: they must match the machine's driver), the
# installed vkd3d-compiler (scripts/lib/sid-tools.sh; it carries its own C
# library) and env.sh. DEST is replaced whole and kept out of git (a line in
# .git/info/exclude). On the other machine, from the checkout's root:
#
#   source .portable/env.sh
#   penumbra verify LIB --device NVIDIA
set -euo pipefail

die() {
  echo "pack-portable: $1" >&2
  exit "${2:-1}"
}

if [ $# -lt 1 ] || [ $# -gt 2 ]; then die "usage: scripts/pack-portable.sh BUILD_DIR [DEST]" 2; fi
build=$1
[ -d "$build" ] || die "$build: no such build folder; allowed: a CMake build folder of penumbra" 2
top=$(git -C "$(dirname "$0")" rev-parse --show-toplevel 2>/dev/null || pwd)
dest=${2:-$top/.portable}
case "$dest" in /*) ;; *) dest="$PWD/$dest" ;; esac

# Linux executables only: the Direct3D host is a Windows program, for Wine.
mapfile -t exes < <(find "$build" -maxdepth 4 -type f -perm -u+x -name 'penumbra*' \
  ! -name '*.so*' ! -name '*_tests' ! -name '*.exe' | sort)
elves=()
for exe in "${exes[@]}"; do
  if file -b "$exe" | grep -q '^ELF'; then elves+=("$exe"); fi
done
[ ${#elves[@]} -gt 0 ] || die "no penumbra executable under $build; build it first" 2

# Packed beside DEST and swapped in at the end: a failed pack leaves the
# previous one as it was.
staging="$dest.new"
rm -rf "$staging"
trap 'rm -rf "$staging"' EXIT
mkdir -p "$staging/bin" "$staging/lib" "$staging/debs"
for exe in "${elves[@]}"; do
  cp "$exe" "$staging/bin/"
  strip "$staging/bin/$(basename "$exe")"
done

# The loaders come from the machine's own Debian (the .debs below); the C
# and C++ runtimes are the other machine's.
system='linux-vdso|ld-linux|libc\.so|libm\.so|libstdc\+\+|libgcc_s|libpthread|libdl\.so|librt\.so'
loaders='libvulkan|libEGL|libOpenGL|libGL|libGLdispatch|libGLX'
for exe in "$staging"/bin/*; do
  ldd "$exe" | awk '$3 ~ /^\// { print $3 }'
done | sort -u | grep -Ev "$system|$loaders" | while read -r so; do
  cp -L "$so" "$staging/lib/"
done

if ! (cd "$staging/debs" &&
  apt-get download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2) \
  >"$staging/apt.log" 2>&1; then
  cat "$staging/apt.log" >&2
  die "apt-get download of the Vulkan, EGL and OpenGL loaders failed (above: apt's words)"
fi
rm "$staging/apt.log"

vkd3d="${PENUMBRA_HLSL_COMPILER:-${XDG_CACHE_HOME:-$HOME/.cache}/penumbra/vkd3d/bin/vkd3d-compiler}"
if [ -x "$vkd3d" ]; then
  cp -a "$(cd "$(dirname "$(readlink -f "$vkd3d")")/.." && pwd)" "$staging/vkd3d"
else
  echo "pack-portable: note: no vkd3d-compiler at $vkd3d: the pack builds no bytecode" >&2
fi

cat >"$staging/env.sh" <<'ENV'
# Sourced on the machine that runs the pack (scripts/pack-portable.sh):
# unpacks the loaders there when the system has none (as root), and points
# Vulkan and EGL at NVIDIA's driver files where they are.
_pp=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ "$(id -u)" -eq 0 ] && ! ldconfig -p | grep -q 'libvulkan.so.1 '; then
  for _deb in "$_pp"/debs/*.deb; do dpkg -x "$_deb" /; done
  ldconfig
fi
export LD_LIBRARY_PATH="$_pp/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$_pp/bin:$PATH"
_nv=/usr/local/nvidia/share
[ -f "$_nv/vulkan/icd.d/nvidia_icd.json" ] && export VK_DRIVER_FILES="$_nv/vulkan/icd.d/nvidia_icd.json"
[ -f "$_nv/glvnd/egl_vendor.d/10_nvidia.json" ] &&
  export __EGL_VENDOR_LIBRARY_FILENAMES="$_nv/glvnd/egl_vendor.d/10_nvidia.json"
[ -x "$_pp/vkd3d/bin/vkd3d-compiler" ] && export PENUMBRA_HLSL_COMPILER="$_pp/vkd3d/bin/vkd3d-compiler"
unset _pp _deb _nv
ENV

rm -rf "$dest"
mv "$staging" "$dest"
trap - EXIT
if [ -d "$top/.git" ] && [[ $dest == "$top"/* ]]; then
  line="/${dest#"$top"/}/"
  grep -qxF "$line" "$top/.git/info/exclude" 2>/dev/null || echo "$line" >>"$top/.git/info/exclude"
fi
echo "packed ${#elves[@]} executables and $(find "$dest/lib" -type f | wc -l) libraries into" \
  "$dest ($(du -sh "$dest" | cut -f1))"
