#!/usr/bin/env bash
# Issue 15, soliman2021 App. C.3: the twisted class tau = 0.3 + 1.2i (12 x 12 lattice, the deformed start of
# options/trianglefield_fig1_top1.opts) with the spin-weight continuation (trianglefield_continuation.c): w = 1, each
# stage ends at el_residual < -flow_spin_stage_rtol and rows < 1e-8, then w <- w * decay (0 below 1e-3), the last
# stage is W alone. Too long for a test (hundreds of iterations, tens of minutes under load); the measured output is
# quoted in docs/triangle_fields.md ("Continuation in the spin weight").
#   A: decay 0.1, stage rtol 1e-3 (stages w = 1, 0.1, 0.01, 0.001, then 0)
#   B: decay 1e-4, stage rtol 1e-2 (w = 1 until el < 1e-2, then W alone)
# Each run prints a "flow: spin stage ..." line per stage (W~ + w E_tau, E_tau, el, pinch edges) and the summary has
# pinch_edges, spin_energy, energy (= W once w = 0).
# Measured (serially, load 25-30 on 2 cores; A stopped by max_it 1500 then, B by -flow_max_seconds 2300):
#   A: flow: spin stage 1 converged at iteration 154 (w = 1.): W~ + w E_tau = 44.55025986, E_tau = 15.1469, el_residual 9.957e-04, violation 1.967e-10, pinch edges 0; w -> 0.1
#      flow: spin stage 2 converged at iteration 622 (w = 0.1): W~ + w E_tau = 29.76488043, E_tau = 18.424, el_residual 9.917e-04, violation 7.841e-10, pinch edges 0; w -> 0.01
#      flow: spin stage 3 converged at iteration 1028 (w = 0.01): W~ + w E_tau = 28.07246997, E_tau = 19.1803, el_residual 9.904e-04, violation 8.589e-10, pinch edges 0; w -> 0.001
#      flow: spin stage 4 converged at iteration 1238 (w = 0.001): W~ + w E_tau = 27.89945983, E_tau = 19.2571, el_residual 9.976e-04, violation 8.734e-10, pinch edges 0; w -> 0.
#      flow trianglefield: NOT converged after 1500 iterations (max_it; ...), 3414.445 s; conformal violation 1.03e-10, constraint violation 3.58e-15, EL residual 1.17e-04
#      summary: energy (W) 27.880191451, pinch_edges 0, q_max 7.04; reconstructed mesh: largest normal angle 134.9 deg, no folds
#   B: flow: spin stage 1 converged at iteration 100 (w = 1.): W~ + w E_tau = 44.55047125, E_tau = 15.1368, el_residual 9.850e-03, violation 1.954e-09, pinch edges 0; w -> 0.
#      flow trianglefield: NOT converged after 1230 iterations (max_it; ...), 2300.247 s; conformal violation 1.57e-12, constraint violation 1.78e-15, EL residual 1.82e-06
#      summary: energy (W) 27.880191418, pinch_edges 0
#   B rerun to the end on the quieter machine (2026-12-02, lead, serial, 224 s):
#      flow: spin stage 1 converged at iteration 100 (w = 1.): ..., pinch edges 0; w -> 0.
#      flow trianglefield: converged after 1286 iterations (converged; 0 rejected steps, 183087 KSP iterations, ...),
#      224.235 s; conformal violation 5.70e-12, constraint violation 8.88e-16, EL residual 9.97e-07
#      summary: energy (W) 27.880191418 (> 2 pi^2 = 19.739), pinch_edges 0, q_max 7.04
set -euo pipefail
cd "$(dirname "$0")/.."
out=runs/results; mkdir -p "$out"
bin/confsurf -options_file options/trianglefield_fig1_top1.opts -flow_spin_weight_decay 0.1 -flow_max_it 3000 \
  -summary $out/tf_continuation_A.json -o $out/tf_continuation_A.obj | tee $out/tf_continuation_A.log | grep "spin stage\|flow trianglefield"
bin/confsurf -options_file options/trianglefield_fig1_top1.opts -flow_spin_weight_decay 1e-4 -flow_spin_stage_rtol 1e-2 \
  -flow_max_it 3000 -summary $out/tf_continuation_B.json -o $out/tf_continuation_B.obj | tee $out/tf_continuation_B.log | grep "spin stage\|flow trianglefield"
