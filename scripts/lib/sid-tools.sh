#!/usr/bin/env bash
# sid-tools.sh TOOL [--dir DIR] [--force]
#
# Installs a private copy of a tool that Debian 12 lacks, taken from Debian
# unstable ("sid"), and prints the path of its wrapper as the last stdout line.
# Nothing is installed into the system: the .debs are fetched with a private
# apt configuration (own sources.list, empty dpkg status, own lists and cache),
# unpacked with dpkg-deb -x into DIR/root, and run through sid's own loader:
#     DIR/root/usr/lib64/ld-linux-x86-64.so.2 --library-path DIR/root/usr/lib/... PROG
# DIR defaults to ${XDG_CACHE_HOME:-~/.cache}/penumbra/sid/TOOL (vkd3d keeps
# .../penumbra/vkd3d, where the build looks for bin/vkd3d-compiler).
# The archive is the machine's Debian entry in /etc/apt (PENUMBRA_SID_URI overrides).
set -euo pipefail

# ---- the tools: one block each ----------------------------------------------------
# tool NAME FIELD=VALUE ...  (a field left out is empty)
#   packages  the first is the main one; "pkg=" wants the main one's version,
#             "pkg>=V" the archive's candidate if it is at least V
#   pin       the pinned ("tested with") version of the main package
#   min       the minimum version of the main package, taken when the pin is not served
#   wrap      programs of usr/bin to wrap (none: only bin/run)
#   check     more files the loader must resolve
#   assume    packages apt may take as present (they serve only binaries not wrapped here)
TOOLS=()  # "name|packages|pin|min|wrap|check|assume", in the order of the blocks
tool() {
  local name="$1" packages="" pin="" min="" wrap="" check="" assume="" field
  shift
  for field in "$@"; do
    case "${field%%=*}" in
      packages | pin | min | wrap | check | assume)
        printf -v "${field%%=*}" '%s' "${field#*=}"
        ;;
      *)
        echo "sid-tools: error: tool $name has an unknown field '$field'" >&2
        exit 1
        ;;
    esac
  done
  TOOLS+=("$name|$packages|$pin|$min|$wrap|$check|$assume")
}

tool vkd3d \
  packages="vkd3d-compiler libvkd3d-shader1=" \
  pin="2.1+ds-1" \
  min="2.1" \
  wrap="vkd3d-compiler vkd3d-dxbc"

tool tint \
  packages="dawn-tools" \
  pin="0.0~git20260909.1a75cb7f-1" \
  min="0.0~git20260909" \
  wrap="tint" \
  assume="libgbm1 libglfw3 libx11-6"

tool dawn \
  packages="libwebgpu-dawn0 libwebgpu-dawn-dev= mesa-vulkan-drivers>=25" \
  pin="0.0~git20260909.1a75cb7f-1" \
  min="0.0~git20260909" \
  check="usr/lib/*/libwebgpu_dawn.so.0 usr/lib/*/libvulkan_lvp.so usr/lib/*/libvulkan.so.1"

# ---- messages -----------------------------------------------------------------------
note() { echo "sid-tools: $*" >&2; }
die() {
  echo "sid-tools: error: $*" >&2
  exit 1
}
usage() {  # $1 = exit status
  echo "usage: sid-tools.sh TOOL [--dir DIR] [--force]" >&2
  echo "  TOOL: $(printf '%s\n' "${TOOLS[@]}" | cut -d'|' -f1 | tr '\n' ' ')" >&2
  echo "  --dir DIR  install into DIR;  --force  download again even if installed" >&2
  exit "${1:-2}"
}

# ---- per-tool smoke checks: $1 = an install dir; set WHY and fail on error ----------
smoke_vkd3d() {
  local out
  out="$("$1/bin/vkd3d-compiler" --version 2>&1 || true)"
  if ! grep -q 'vkd3d shader compiler version' <<<"$out"; then
    WHY="vkd3d-compiler --version said: ${out:0:300}"
    return 1
  fi
  rm -f "$WORK/t.d3dbc"
  echo 'float4 main() : COLOR { return float4(1, 0, 0, 1); }' > "$WORK/t.hlsl"
  "$1/bin/vkd3d-compiler" -x hlsl -p ps_3_0 -b d3dbc -o "$WORK/t.d3dbc" "$WORK/t.hlsl" \
    > "$WORK/log" 2>&1 || true
  if [[ ! -s "$WORK/t.d3dbc" ]]; then
    WHY="vkd3d-compiler cannot compile a trivial ps_3_0 shader: $(head -c 300 "$WORK/log")"
    return 1
  fi
}
smoke_tint() {
  # tint has no --version, and --help exits 1: look at the text.
  "$1/bin/tint" --help > "$WORK/log" 2>&1 || true
  if ! grep -q 'Usage: tint' "$WORK/log"; then
    WHY="tint --help does not print its usage: $(head -c 300 "$WORK/log")"
    return 1
  fi
  # The SPIR-V comes from glslang (Debian 12: glslang-tools), else from tint itself.
  rm -f "$WORK/t.spv"
  if command -v glslangValidator > /dev/null; then
    printf '%s\n' '#version 450' 'layout(location = 0) out vec4 c;' \
      'void main() { c = vec4(1.0, 0.0, 0.0, 1.0); }' > "$WORK/t.frag"
    glslangValidator -V -o "$WORK/t.spv" "$WORK/t.frag" > "$WORK/log" 2>&1 || true
  else
    echo '@fragment fn main() -> @location(0) vec4f { return vec4f(1, 0, 0, 1); }' \
      > "$WORK/t0.wgsl"
    "$1/bin/tint" -o "$WORK/t.spv" "$WORK/t0.wgsl" > "$WORK/log" 2>&1 || true
  fi
  if [[ ! -s "$WORK/t.spv" ]]; then
    WHY="could not make a test SPIR-V module: $(head -c 300 "$WORK/log")"
    return 1
  fi
  # Debian's tint silently writes SPIR-V asm for unsupported outputs: check the text.
  rm -f "$WORK/t.wgsl"
  "$1/bin/tint" -o "$WORK/t.wgsl" "$WORK/t.spv" > "$WORK/log" 2>&1 || true
  if ! grep -qs '@fragment' "$WORK/t.wgsl"; then
    WHY="tint did not turn SPIR-V into WGSL: $(head -c 300 "$WORK/log")"
    return 1
  fi
}
smoke_dawn() {
  if ! "$1/bin/run" /bin/true; then
    WHY="$1/bin/run cannot run /bin/true"
    return 1
  fi
}
smoke() {  # $1 = an install dir: the tool's smoke check, where it has one
  if declare -F "smoke_$TOOL" > /dev/null; then
    "smoke_$TOOL" "$1"
  fi
}

# ---- arguments ----------------------------------------------------------------------
TOOL="" DIR="" FORCE=0 ROW=""
while (($#)); do
  case "$1" in
    --dir)
      if (($# < 2)); then
        echo "sid-tools: --dir needs a folder" >&2
        usage
      fi
      DIR="$2"
      shift
      ;;
    --force) FORCE=1 ;;
    -h | --help) usage 0 ;;
    -*)
      echo "sid-tools: unknown option '$1'" >&2
      usage
      ;;
    *)
      [[ -z "$TOOL" ]] || usage  # one tool per run
      TOOL="$1"
      ;;
  esac
  shift
done
for r in "${TOOLS[@]}"; do
  if [[ -n "$TOOL" && "${r%%|*}" == "$TOOL" ]]; then
    ROW="$r"
  fi
done
if [[ -z "$ROW" ]]; then
  echo "sid-tools: unknown tool '$TOOL'" >&2
  usage
fi
IFS='|' read -r _ pkgs PIN MIN wrap check assume <<<"$ROW"
read -ra PKGS <<<"$pkgs"
read -ra WRAP <<<"$wrap"
read -ra CHECK <<<"$check"
read -ra ASSUME <<<"$assume"
MAIN="${PKGS[0]}"

CACHE="${XDG_CACHE_HOME:-${HOME:?}/.cache}/penumbra"
if [[ -z "$DIR" ]]; then
  if [[ "$TOOL" == vkd3d ]]; then
    DIR="$CACHE/vkd3d"  # where the build looks for bin/vkd3d-compiler
  else
    DIR="$CACHE/sid/$TOOL"
  fi
fi
mkdir -p "$DIR" || die "cannot create '$DIR'"
DIR="$(cd -P "$DIR" && pwd)"
if ((${#WRAP[@]})); then
  ENTRY="$DIR/bin/${WRAP[0]}"
else
  ENTRY="$DIR/bin/run"
fi
for t in apt-get apt-cache dpkg dpkg-deb flock; do
  command -v "$t" > /dev/null || die "'$t' is needed"
done

# One run per DIR at a time; anything left in DIR/.work.* is from a killed run.
exec 9> "$DIR/.lock"
flock 9
rm -rf "$DIR"/.work.*
WORK="$(mktemp -d "$DIR/.work.XXXXXX")"  # same file system as DIR: renames are atomic
trap 'rm -rf "$WORK"' EXIT

# ---- the unpacked tree: loader, library dirs, and a check that all resolves ---------
layout() {  # $1 = a root; sets LOADER and LIBDIRS (relative to the root)
  local libc l
  libc="$(find "$1/usr/lib" "$1/lib" -name libc.so.6 -path '*-linux-*' 2>/dev/null \
    | head -n1 || true)"
  if [[ -z "$libc" ]]; then
    WHY="no libc.so.6 under $1"
    return 1
  fi
  libc="$(dirname "${libc#"$1"/}")"
  LIBDIRS=("$libc")
  # Without a merged /usr, lib/TRIPLET holds libraries too.
  if [[ -d "$1/lib/${libc##*/}" && ! -L "$1/lib" ]]; then
    LIBDIRS+=("lib/${libc##*/}")
  fi
  LOADER=""
  for l in "$1"/usr/lib64/ld-linux-* "$1"/lib64/ld-linux-* "$1/$libc"/ld-linux-*; do
    if [[ -z "$LOADER" && -x "$l" ]]; then
      LOADER="${l#"$1"/}"
    fi
  done
  if [[ -z "$LOADER" ]]; then
    WHY="no dynamic loader under $1"
    return 1
  fi
}
libpath() {  # $1 = a root: its LIBDIRS as a --library-path
  local d out=""
  for d in "${LIBDIRS[@]}"; do
    out+="${out:+:}$1/$d"
  done
  echo "$out"
}
unresolved() {  # $1 = root, $2 = file: sonames the loader cannot find inside the root
  { "$1/$LOADER" --library-path "$(libpath "$1")" --list "$2" 2>&1 || true; } \
    | awk -v r="$1/" '
      /=> not found/ { print $1 }
      / => \// && index($3, r) != 1 { print $1 }  # found, but on the host system
      /error while loading shared libraries: / {
        sub(/.*shared libraries: /, "")
        sub(/:.*/, "")
        print
      }' \
    | sort -u
}
inspect() {  # $1 = root: every wrapped binary and CHECK file resolves inside it
  local files=() f p so miss grown hit dir
  layout "$1" || return 1
  for p in "${WRAP[@]}"; do
    if [[ ! -x "$1/usr/bin/$p" ]]; then
      WHY="the packages ship no usr/bin/$p"
      return 1
    fi
    files+=("$1/usr/bin/$p")
  done
  for p in "${CHECK[@]}"; do
    hit="$(compgen -G "$1/$p" | head -n1 || true)"
    if [[ -z "$hit" ]]; then
      WHY="the packages ship no $p"
      return 1
    fi
    files+=("$hit")
  done
  # A soname that is in another folder of the root: add that folder, and look again.
  grown=1
  while ((grown)); do
    grown=0
    miss=""
    for f in "${files[@]}"; do
      for so in $(unresolved "$1" "$f"); do
        hit="$(find "$1" -name "$so" -print -quit)"
        dir="$(dirname "${hit#"$1"/}")"
        if [[ -n "$hit" && " ${LIBDIRS[*]} " != *" $dir "* ]]; then
          LIBDIRS+=("$dir")
          grown=1
        else
          miss+=" ${f#"$1"/}: $so;"
        fi
      done
    done
  done
  if [[ -n "$miss" ]]; then
    WHY="sid's loader cannot find, inside the root:$miss"
    return 1
  fi
}
write_wrapper() {  # $1 = install dir, $2 = name, $3 = program ('' for bin/run)
  local w="$1/bin/$2"
  local prog="--argv0 \"\$0\" \"\$R/usr/bin/$3\""
  local usage=""
  if [[ -z "$3" ]]; then
    # bin/run runs the program its first argument names.
    prog=""
    usage='[ $# -ge 1 ] || { echo "usage: run PROGRAM [ARGS...]" >&2; exit 2; }'
  fi
  mkdir -p "$1/bin"
  cat > "$w" <<EOF
#!/bin/sh
# Made by sid-tools.sh: runs ${3:-PROGRAM} with Debian sid's loader and libraries in ../root.
$usage
D="\$(cd "\$(dirname "\$(readlink -f "\$0")")/.." && pwd -P)"
R="\$D/root"
if [ -z "\${VK_DRIVER_FILES:-}" ] && [ -f "\$D/icd/lvp_icd.json" ]; then
  VK_DRIVER_FILES="\$D/icd/lvp_icd.json"; export VK_DRIVER_FILES
fi
exec "\$R/$LOADER" --library-path "$(libpath "\$R")" $prog "\$@"
EOF
  chmod +x "$w"
}
write_icd() {  # $1 = final install dir: lavapipe's manifest, with an absolute library path
  local src lib json
  src="$(compgen -G "$1/root/usr/share/vulkan/icd.d/lvp_icd*.json" | head -n1 || true)"
  lib="$(find "$1/root/usr/lib" -name libvulkan_lvp.so -print -quit 2>/dev/null || true)"
  [[ -n "$src" && -n "$lib" ]] || return 0  # no lavapipe in this tool
  json="$(sed -E "s|(\"library_path\": *)\"[^\"]*\"|\1\"$lib\"|" "$src")"
  # The manifest is written only when it changes.
  if [[ -f "$1/icd/lvp_icd.json" && "$(cat "$1/icd/lvp_icd.json")" == "$json" ]]; then
    return 0
  fi
  mkdir -p "$1/icd"
  echo "$json" > "$1/icd/lvp_icd.json"
}
recorded() {  # $1 = a package: the version DIR/versions.txt records for it
  awk -F= -v p="$1" '$1 == p { print $2 }' "$DIR/versions.txt" 2>/dev/null || true
}
recorded_pin() {  # the pin that DIR/versions.txt was installed for
  awk '$1 == "#" && $2 == "pin" { print $3 }' "$DIR/versions.txt" 2>/dev/null || true
}
wanted() {  # $1 = the recorded version of MAIN, $2 = the recorded pin
  # the pin, or the candidate taken when this same pin was not served
  [[ "$1" == "$PIN" ]] && return 0
  [[ -n "$1" && "$2" == "$PIN" ]] && dpkg --compare-versions "$1" ge "$MIN"
}
headers_note() {
  if [[ -d "$DIR/root/usr/include" ]]; then
    note "headers: $(compgen -G "$DIR/root/usr/include/*" | tr '\n' ' ')"
  fi
}

# ---- reuse a working install of the wanted version, without network ----------------
if ((!FORCE)) && [[ -x "$ENTRY" ]]; then
  have="$(recorded "$MAIN")"
  if wanted "$have" "$(recorded_pin)"; then
    WHY=""
    if inspect "$DIR/root" && smoke "$DIR"; then
      write_icd "$DIR"
      note "already installed: $MAIN $have in $DIR"
      headers_note
      echo "$ENTRY"
      exit 0
    fi
    note "the install in $DIR fails its check ($WHY); installing again"
  fi
fi

# ---- the archive, and a private apt configuration -----------------------------------
debian_uris() {  # Debian entries of a plain release (no -security, -updates, ...)
  local f
  # deb822 files: stanzas split by blank lines
  for f in /etc/apt/sources.list.d/*.sources; do
    [[ -r "$f" ]] || continue
    awk '
      function flush(  n, a, i) {
        if (t ~ /(^|[ \t])deb([ \t]|$)/ && e !~ /^[Nn]o/ && s) {
          n = split(u, a)
          for (i = 1; i <= n; i++) print a[i]
        }
        t = u = e = ""
        s = 0
      }
      /^[ \t]*#/ { next }
      /^[ \t]*$/ { flush(); next }
      { k = tolower($1) }
      k == "types:" { t = $0 }
      k == "uris:" { $1 = ""; u = $0 }
      k == "enabled:" { e = $2 }
      k == "suites:" { for (i = 2; i <= NF; i++) if ($i !~ /[-\/]/) s = 1 }
      END { flush() }' "$f"
  done
  # one-line files: deb [OPTIONS] URI SUITE COMPONENT...
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -r "$f" ]] || continue
    awk '$1 == "deb" {
      i = 2
      if ($i ~ /^\[/) {
        while ($i !~ /\]$/ && i < NF) i++
        i++
      }
      if ($(i + 1) !~ /[-\/]/) print $i
    }' "$f"
  done
  return 0
}
archive_uri() {  # the entry that ends in /debian, else the first one
  debian_uris | sed 's:/*$::' | awk '
    !d && /\/debian$/ { d = $0 }
    NR == 1 { f = $0 }
    END { print (d != "" ? d : f) }'
}
URI="${PENUMBRA_SID_URI:-$(archive_uri)}"
if [[ -z "$URI" ]]; then
  die "no Debian archive in /etc/apt's sources;" \
    "set PENUMBRA_SID_URI to one (e.g. http://HOST/debian)"
fi

APTD="$WORK/apt"
mkdir -p "$APTD/lists/partial" "$APTD/cache/archives/partial" "$APTD/debs" "$APTD/conf.d"
echo "deb $URI sid main" > "$APTD/sources.list"
: > "$APTD/status"  # empty: apt resolves the whole closure from sid alone
# The machine's apt.conf.d is kept (proxies, Check-Valid-Until), but its hooks
# (PackageKit, AppStream refreshes of the system's caches) are cleared.
for f in /etc/apt/apt.conf.d/*; do
  if [[ -f "$f" ]]; then
    ln -s "$f" "$APTD/conf.d/"
  fi
done
printf '#clear %s;\n' \
  APT::Update::Pre-Invoke APT::Update::Post-Invoke APT::Update::Post-Invoke-Success \
  DPkg::Pre-Invoke DPkg::Post-Invoke \
  > "$APTD/conf.d/zzzz-sid-tools"
echo "Dir::Etc::Parts \"$APTD/conf.d\";" > "$APTD/apt.conf"
export APT_CONFIG="$APTD/apt.conf"
APT=(
  -q
  -o "Dir::Etc::SourceList=$APTD/sources.list"
  -o Dir::Etc::SourceParts=/dev/null
  -o Dir::Etc::Preferences=/dev/null
  -o Dir::Etc::PreferencesParts=/dev/null
  -o "Dir::State::Lists=$APTD/lists"
  -o "Dir::State::status=$APTD/status"
  -o "Dir::Cache=$APTD/cache"
  -o "Dir::Cache::Archives=$APTD/cache/archives"
  -o Debug::NoLocking=1
  -o APT::Install-Recommends=false
)
# apt fetches as user _apt, who cannot write root's private folders.
if [[ "$(id -u)" == 0 ]]; then
  APT+=(-o APT::Sandbox::User=root)
fi

T0=$SECONDS
note "reading the sid index of $URI ..."
rc=0
apt-get "${APT[@]}" update > "$WORK/update.log" 2>&1 || rc=$?
# apt-get update can exit 0 with an index missing: look at its messages and lists too.
if ((rc)) || grep -qE '^(Err:|E: |W: Failed to fetch|W: Some index files)' "$WORK/update.log" \
  || ! compgen -G "$APTD/lists/*_Packages*" > /dev/null; then
  grep -E '^(Err|E:|W:|  )' "$WORK/update.log" | head -n 12 >&2 || true
  die "apt-get update failed: no sid archive reachable at '$URI sid main'" \
    "(set PENUMBRA_SID_URI to another)"
fi

# ---- versions: the pin if served, else the candidate if >= the minimum --------------
candidate() {  # $1 = a package: the archive's candidate version, if any
  apt-cache "${APT[@]}" policy "$1" 2>/dev/null \
    | awk '$1 == "Candidate:" && $2 != "(none)" { print $2 }'
}
served() {  # $1 = a package, $2 = a version: whether the archive serves that version
  apt-cache "${APT[@]}" madison "$1" 2>/dev/null \
    | awk -F'|' -v v="$2" '{ gsub(/ /, "", $2) } $2 == v { f = 1 } END { exit !f }'
}
VER="$(candidate "$MAIN")"
[[ -n "$VER" ]] || die "package $MAIN is not served by '$URI sid main'"
if served "$MAIN" "$PIN"; then
  VER="$PIN"
elif dpkg --compare-versions "$VER" ge "$MIN"; then
  note "note: $MAIN $PIN (pinned) is not served; using the archive's $VER (>= $MIN)"
else
  die "'$URI sid' serves $MAIN $VER, below the minimum $MIN (pinned: $PIN)"
fi
SPECS=("$MAIN=$VER")
for p in "${PKGS[@]:1}"; do
  case "$p" in
    *=)  # the main package's version
      name="${p%=}"
      served "$name" "$VER" \
        || die "package $name $VER (the version of $MAIN) is not served by '$URI sid'"
      SPECS+=("$p$VER")
      ;;
    *)  # the candidate, at least the version after any '>='
      name="${p%%>=*}"
      c="$(candidate "$name")"
      [[ -n "$c" ]] || die "package $name is not served by '$URI sid main'"
      if [[ "$p" == *'>='* ]] && ! dpkg --compare-versions "$c" ge "${p#*>=}"; then
        die "'$URI sid' serves $name $c, below the minimum ${p#*>=}"
      fi
      SPECS+=("$name=$c")
      ;;
  esac
done
for p in "${ASSUME[@]}"; do  # taken as installed: apt leaves out their dependencies
  c="$(candidate "$p")"
  [[ -n "$c" ]] || continue
  printf 'Package: %s\nStatus: install ok installed\nVersion: %s\nArchitecture: %s\n\n' \
    "$p" "$c" "$(dpkg --print-architecture)" >> "$APTD/status"
done

# ---- the dependency closure, downloaded and unpacked --------------------------------
note "resolving: ${SPECS[*]}"
if ! apt-get "${APT[@]}" -s install "${SPECS[@]}" > "$WORK/sim.log" 2>&1; then
  grep -E '^(E:| )' "$WORK/sim.log" | head -n 20 >&2
  die "apt cannot resolve ${SPECS[*]} in sid"
fi
# "Inst PKG [OLD] (VERSION ARCHIVE [ARCH])": PKG=VERSION, the version apt chose
mapfile -t CLOSURE < <(awk '$1 == "Inst" {
    for (i = 3; i <= NF; i++) if ($i ~ /^\(/) { print $2 "=" substr($i, 2); break }
  }' "$WORK/sim.log")
note "downloading ${#CLOSURE[@]} packages ..."
if ! (cd "$APTD/debs" && apt-get "${APT[@]}" download "${CLOSURE[@]}") \
  > "$WORK/dl.log" 2>&1; then
  grep -E '^(E:|W:|Err)' "$WORK/dl.log" >&2 || true
  die "apt-get download failed"
fi
STAGE="$WORK/stage"
mkdir -p "$STAGE/root"
for deb in "$APTD"/debs/*.deb; do
  dpkg-deb -x "$deb" "$STAGE/root"
done
rm -rf "$APTD"  # the lists (~25 MB) and .debs are not kept

WHY=""
inspect "$STAGE/root" || die "$WHY"
for p in "${WRAP[@]}"; do
  write_wrapper "$STAGE" "$p" "$p"
done
write_wrapper "$STAGE" run ""
{
  echo "# sid-tools.sh $TOOL from $URI sid, $(date -u +%F)"
  echo "# pin $PIN min $MIN"
  printf '%s\n' "${CLOSURE[@]}" | sort
} > "$STAGE/versions.txt"
if [[ -d "$STAGE/root/usr/include" ]]; then
  echo "# headers $DIR/root/usr/include" >> "$STAGE/versions.txt"
fi
smoke "$STAGE" || die "smoke test of $TOOL failed: $WHY"

# ---- swap in: a failure above has left any previous install as it was --------------
# The old install goes into WORK, which the EXIT trap removes.
mkdir "$WORK/old"
for x in root bin icd versions.txt; do
  if [[ -e "$DIR/$x" ]]; then
    mv "$DIR/$x" "$WORK/old/"
  fi
done
for x in root bin versions.txt; do
  mv "$STAGE/$x" "$DIR/"
done
write_icd "$DIR"
note "installed $MAIN $VER (${#CLOSURE[@]} packages) in $DIR in $((SECONDS - T0)) s"
headers_note
echo "$ENTRY"
