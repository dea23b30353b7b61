#!/usr/bin/env bash
# `make run` on a fresh machine (issue #17): a new Debian bookworm root (debootstrap, minbase) with only what a new
# machine of this kind has (gcc, g++, gfortran, make, git), a clone of this checkout's HEAD in it, then the stages
# of `make run` timed apart: the Debian packages (scripts/install-deps.sh), the build, the run with its pictures.
# Root only (debootstrap, chroot, mounts). ROOT=dir (default /tmp/confsurf-fresh, removed first). Several runs:
# REPS=n. Results: runs/results/bench_make_run_fresh.md (one row per run, and the load average at the start).
set -euo pipefail
cd "$(dirname "$0")/.."
[ "$(id -u)" = 0 ] || { echo "bench_make_run_fresh: needs root (debootstrap, chroot)"; exit 1; }
command -v debootstrap > /dev/null || { apt-get update -q && apt-get install -y -q debootstrap; }
ROOT=${ROOT:-/tmp/confsurf-fresh}; REPS=${REPS:-1}; repo=$PWD
mkdir -p runs/results; out=runs/results/bench_make_run_fresh.md
echo "| run | load at start | packages s | build s | run + pictures s | make run total s |" > "$out"
echo "|---|---|---|---|---|---|" >> "$out"
cleanup() { umount -R "$ROOT/proc" "$ROOT/dev" "$ROOT/sys" 2> /dev/null || true; }
for k in $(seq "$REPS"); do
  cleanup; rm -rf "$ROOT"
  debootstrap --variant=minbase bookworm "$ROOT" http://deb.debian.org/debian > /dev/null
  cp /etc/resolv.conf "$ROOT/etc/"
  mount -t proc proc "$ROOT/proc"; mount --rbind /dev "$ROOT/dev"; mount --rbind /sys "$ROOT/sys"
  chroot "$ROOT" bash -c "apt-get update -q > /dev/null && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends gcc g++ gfortran make git ca-certificates > /dev/null 2>&1"
  git clone -q "$repo" "$ROOT/src/confsurf"
  load=$(cut -d' ' -f1 /proc/loadavg)
  times=$(chroot "$ROOT" bash -c 'cd /src/confsurf && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    t0=$(date +%s.%N); bash scripts/install-deps.sh > /tmp/deps.log 2>&1; t1=$(date +%s.%N)
    make -j"$(nproc)" bin/confsurf > /tmp/build.log 2>&1; t2=$(date +%s.%N)
    bash scripts/run-default.sh > /tmp/run.log 2>&1; t3=$(date +%s.%N)
    ls out/run/pictures/*.png > /dev/null
    echo "$(echo "$t1-$t0"|bc) $(echo "$t2-$t1"|bc) $(echo "$t3-$t2"|bc) $(echo "$t3-$t0"|bc)"')
  set -- $times
  printf "| %s | %s | %.0f | %.0f | %.0f | **%.0f** |\n" "$k" "$load" "$1" "$2" "$3" "$4" | tee -a "$out"
done
cleanup
cat "$out"
