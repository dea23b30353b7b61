#!/usr/bin/env bash
# Installs what confsurf needs on a fresh Debian machine (we run as root; sudo is used when we are not).
set -euo pipefail
pkgs="petsc-dev slepc-dev libsuitesparse-dev openmpi-bin libopenblas0 pkg-config python3 python3-numpy python3-matplotlib make bc valgrind"  # libsuitesparse-dev: CHOLMOD headers (a dependency of petsc-dev anyway); python3-matplotlib: the pictures (scripts/pictures.py)
missing=""
for p in $pkgs; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -z "$missing" ]; then exit 0; fi
if [ "${1:-}" = "--check" ]; then exit 1; fi   # used by the Makefile: are we complete?
SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
echo "install-deps: installing$missing (apt-get)"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends $missing
