#!/usr/bin/env bash
# Study (not a test), issue 35: is the homogeneous torus of class b a stable minimum, a saddle, or degenerate?
# On structured -gen torus grids (R/r = 1.8, 2, 2.2: b = 1.50, sqrt 3, 1.96) a cos 2phi perturbation
# (-gen_deform_nfold 2,1e-3) is flowed with -flow_rtol 1e-14 (so the run does not stop at EL 1e-6) and the growth
# rate of EL is printed (runs/el_growth_rate.py): negative = stable, positive = the mode grows; a rate that falls
# like h^2 under refinement = a mode at which the smooth second variation vanishes (docs/real_meshes.md
# "Issue 35" section 4). Measured 2026-12-06: R/r 1.8 -0.0077 (32x16) -0.020 (64x32); 2: +0.0148 +0.0038
# +0.00096 (128x64); 2.2: +0.033 +0.023. The 128 x 64 run takes ~15 min under load; MAXN=64 skips it.
# Knobs: MAXIT=250, MAXN=128.
set -u
cd "$(dirname "$0")/.."
MAXIT=${MAXIT:-250}; MAXN=${MAXN:-128}
BIN=$PWD/bin/confsurf
PY=$(bash scripts/find-python.sh) || exit 1
dir=runs/results/fat_class_modes; mkdir -p "$dir"
for R in 1.8 2 2.2; do
  for n in 32 64 128; do
    [ "$n" -le "$MAXN" ] || continue
    [ "$n" = 128 ] && [ "$R" != 2 ] && continue
    h=$dir/R${R}_n$n.csv
    "$BIN" -task flow -gen torus -gen_torus_R "$R" -gen_tube_r 1 -gen_n "$n" -gen_m $((n / 2)) \
      -gen_deform_nfold 2,1e-3 -flow_max_it "$MAXIT" -flow_rtol 1e-14 -flow_t_mu_final 4e9 \
      -history_csv "$h" > "${h%.csv}.log" 2>&1
    "$PY" runs/el_growth_rate.py "$h"
  done
done
