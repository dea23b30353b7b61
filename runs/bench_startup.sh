#!/usr/bin/env bash
# Start-up cost of a tiny serial run (issue 17, item 5): `bin/confsurf -task info -gen icosphere -gen_level 1`,
# 10 runs per configuration, median/min/max wall seconds, for the singleton defaults of src/driver/main.c
# (CSSingletonDefaults, src/driver/startup.c) and without them (CS_MPI_DEFAULTS=0), with Open MPI's ess_singleton_isolated alone, and with
# one OpenBLAS thread (OPENBLAS_NUM_THREADS=1: must be in the environment before the program starts).
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
C="bin/confsurf -task info -gen icosphere -gen_level 1"
python3 - "$C" <<'PY'
import os, statistics, subprocess, sys, time
cmd = sys.argv[1].split()
cfgs = [("CS_MPI_DEFAULTS=0 (Open MPI defaults)", {"CS_MPI_DEFAULTS": "0"}),
        ("CS_MPI_DEFAULTS=0 OMPI_MCA_ess_singleton_isolated=1", {"CS_MPI_DEFAULTS": "0", "OMPI_MCA_ess_singleton_isolated": "1"}),
        ("singleton defaults, shared session tree (OMPI_MCA_orte_tmpdir_base=/tmp: as before issue 36 item 2)", {"OMPI_MCA_orte_tmpdir_base": "/tmp"}),
        ("singleton defaults (the default: a private session tree)", {}),
        ("singleton defaults + OPENBLAS_NUM_THREADS=1", {"OPENBLAS_NUM_THREADS": "1"})]
print("| configuration | median s | min | max |\n|---|---|---|---|")
for name, extra in cfgs:
    env = dict(os.environ, **extra); ts = []
    for i in range(10):
        t = time.perf_counter(); subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, check=True); ts.append(time.perf_counter() - t)
    print(f"| {name} | {statistics.median(ts):.3f} | {min(ts):.3f} | {max(ts):.3f} |")
PY
