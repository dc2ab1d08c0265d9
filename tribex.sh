#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The two README commands (and a few more for developers):
#   ./tribex.sh demo        install missing Debian packages, build Release into build/, run the demo
#   ./tribex.sh test        same set-up, then the CTest suite (everything but the `slow` label)
#   ./tribex.sh test-slow   the `slow` verification variants as well
#   ./tribex.sh sanitize    ASan+UBSan build of the unit and bad-input tests in build-asan/, run them
#   ./tribex.sh build       set-up and build only
#   ./tribex.sh python SCRIPT [ARGS]  /usr/bin/python3 with tools/python on the path (`import tribex`),
#                           in the caller's working directory
set -euo pipefail
CALLER_PWD=$PWD
cd "$(dirname "$0")"
ROOT=$PWD

# Debian 12 packages (names and traps: docs/dependencies.md).
PACKAGES=(
  cmake make g++ git
  libeigen3-dev libmetis-dev libptscotch-dev libhdf5-openmpi-dev libopenmpi-dev openmpi-bin
  libgmsh-dev gmsh libcgal-dev libgtest-dev libexodusii-dev libnetcdf-dev
  python3 python3-matplotlib python3-numpy python3-scipy python3-h5py python3-netcdf4
  paraview python3-paraview xvfb xauth
)

log() { printf '[tribex.sh] %s\n' "$*"; }

ensure_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    log "installing Debian packages: ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get -o DPkg::Lock::Timeout=600 update -q
    $sudo apt-get -o DPkg::Lock::Timeout=600 install -y -q --no-install-recommends "${missing[@]}"
  fi
}

# Open MPI as root in a container, with np > cores (docs/dependencies.md section 4).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1
export OMPI_MCA_hwloc_base_binding_policy=none

build() {  # build DIR [cmake args...]
  local dir=$1; shift
  mkdir -p "$dir"
  cmake -S "$ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" > "$dir/configure.log" 2>&1 \
    || { cat "$dir/configure.log"; exit 1; }
  cmake --build "$dir" -j2
}

cmd=${1:-}
case "$cmd" in
  build)
    ensure_packages; build build ;;
  demo)
    # The adhesive indentation (W = 0.05 J/m^2) and its W = 0 twin run side by side, one per core
    # (quarter models, about 15 s on an idle 2-core machine), from about 120 nN down past pull-off; then the
    # a-versus-P plot of both against DMT and Hertz (verification/dmt/compare.py). The W = 0 run is
    # quiet so that the terminal shows one progress line.
    ensure_packages; build build
    out="$ROOT/demo_output"
    rm -rf "$out/dmt" "$out/hertz"; mkdir -p "$out"
    log "running the adhesive indentation (W = 0.05 J/m^2) and the one without adhesion (W = 0) side by side, under a minute"
    build/bin/tribex run inputs/examples/demo_hertz.i -o "$out/hertz" --quiet & hertz_pid=$!
    build/bin/tribex run inputs/examples/demo.i -o "$out/dmt" || { kill "$hertz_pid" 2>/dev/null; exit 1; }
    wait "$hertz_pid"
    /usr/bin/python3 verification/dmt/compare.py "$out/dmt" --element-size 0.4 --hertz-output "$out/hertz" \
      --plot "$out/demo.png" || log "the comparison above did not pass (see its FAIL line)"
    for run in dmt hertz; do
      log "results ($run): $out/$run/results.xdmf (open in ParaView), history.csv, summary.json, log.txt"
    done
    log "plot:    $out/demo.png (contact radius a versus load P, W = 0.05 and W = 0, against DMT and Hertz, with the pull-off)" ;;
  test)
    ensure_packages; build build
    ctest --test-dir build -j2 --output-on-failure -LE slow ;;
  test-slow)
    ensure_packages; build build
    ctest --test-dir build -j2 --output-on-failure -L slow ;;
  sanitize)
    ensure_packages
    mkdir -p build-asan
    cmake -S "$ROOT" -B build-asan -DCMAKE_BUILD_TYPE=Debug -DTRIBEX_SANITIZE=ON > build-asan/configure.log 2>&1 \
      || { cat build-asan/configure.log; exit 1; }
    cmake --build build-asan -j2
    ASAN_OPTIONS=detect_leaks=1 ctest --test-dir build-asan -j2 --output-on-failure -L "unit|bad_input" ;;
  python)
    # The Python package (tools/python/tribex) for the user's own scripts; the binary it drives is
    # build/bin/tribex (./tribex.sh build first).
    shift
    cd "$CALLER_PWD"
    PYTHONPATH="$ROOT/tools/python${PYTHONPATH:+:$PYTHONPATH}" exec /usr/bin/python3 "$@" ;;
  *)
    echo "usage: ./tribex.sh demo|test|test-slow|sanitize|build|python SCRIPT" >&2; exit 2 ;;
esac
