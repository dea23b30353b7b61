#!/usr/bin/env bash
# Installs what confsurf needs on a fresh Debian machine (we run as root; sudo is used when we are not).
# --test: also what the test suite needs beyond that: ParaView (paraview python3-paraview, ~540 MB installed,
# measured 3 min 17 s to download and install here) for tests/cases/viewer_paraview.sh.
set -euo pipefail
pkgs="petsc-dev slepc-dev libsuitesparse-dev openmpi-bin libopenblas0 pkg-config zlib1g-dev python3 python3-numpy python3-matplotlib make bc valgrind"  # libsuitesparse-dev: CHOLMOD headers (a dependency of petsc-dev anyway); zlib1g-dev: the compressed ParaView output; python3-matplotlib: the pictures (scripts/pictures.py)
# CGAL for -mesh_remesh (header-only; GMP/MPFR; the C++ compiler for its one translation unit): part of the set
# --check requires, so `make` installs it before it builds (a build that finds no CGAL still succeeds, and then
# -mesh_remesh refuses with one line naming `make deps`)
pkgs="$pkgs libcgal-dev libgmp-dev libmpfr-dev g++"
[ "${1:-}" = "--test" ] && pkgs="$pkgs paraview python3-paraview xvfb"
missing=""
for p in $pkgs; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -z "$missing" ]; then exit 0; fi
if [ "${1:-}" = "--check" ]; then exit 1; fi   # used by the Makefile: are we complete?
SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
echo "install-deps: installing$missing (apt-get)"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends $missing
