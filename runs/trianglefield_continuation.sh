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
set -euo pipefail
cd "$(dirname "$0")/.."
out=runs/results; mkdir -p "$out"
bin/confsurf -options_file options/trianglefield_fig1_top1.opts -flow_spin_weight_decay 0.1 -flow_max_it 3000 \
  -summary $out/tf_continuation_A.json -o $out/tf_continuation_A.obj | tee $out/tf_continuation_A.log | grep "spin stage\|flow trianglefield"
bin/confsurf -options_file options/trianglefield_fig1_top1.opts -flow_spin_weight_decay 1e-4 -flow_spin_stage_rtol 1e-2 \
  -flow_max_it 3000 -summary $out/tf_continuation_B.json -o $out/tf_continuation_B.obj | tee $out/tf_continuation_B.log | grep "spin stage\|flow trianglefield"
