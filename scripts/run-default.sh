#!/usr/bin/env bash
# `make run`: the default experiment on a bundled mesh, then where the results went.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p out
np=${NP:-2}
echo "+ mpirun -n $np bin/confsurf -options_file options/info_bunny.opts"
mpirun -n "$np" bin/confsurf -options_file options/info_bunny.opts
echo
echo "Results:"
echo "  out/bunny_info.json        summary (counts, genus, area, volume, willmore, seconds)"
echo "  out/bunny.ply              the mesh as written back"
echo "  out/bunny_vtu/series.pvd   ParaView series (mean curvature, vertex and face areas)"
