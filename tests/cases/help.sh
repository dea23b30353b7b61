#!/usr/bin/env bash
# -help (src/driver/main.c): alone, the task list (exit 0, no PETSc banner); with -task NAME, only that task's own
# options with their defaults (no other task's, no solver object's); an unknown option still fails naming it.
# nprocs: 1
source tests/lib.sh
"$CS_BIN" -help > "$TMP/h.txt" 2>&1 || { cat "$TMP/h.txt"; echo "BAD: -help exit $?"; exit 1; }
for t in info flow spin spectrum curveflow; do grep -q "^  $t " "$TMP/h.txt" || { echo "BAD: task $t not listed"; exit 1; }; done
! grep -q "Options for all PETSc programs" "$TMP/h.txt" || { echo "BAD: PETSc's banner"; exit 1; }
echo "ok  -help lists the tasks ($(wc -l < "$TMP/h.txt") lines)"
# the flow's kinds in the task list are the registry's (the -flow_type list of the flow's own block), none written by hand
"$CS_BIN" -task flow -help > "$TMP/f.txt" 2>&1 || { cat "$TMP/f.txt"; echo "BAD: -task flow -help failed"; exit 1; }
reg=$(grep -m1 -- "-flow_type <.*Flow kind (one of)" "$TMP/f.txt" | sed 's/.*(one of) //; s/ ((null))//' | tr ' ' '|')
listed=$(grep -m1 "the kinds registered:" "$TMP/h.txt" | sed 's/.*registered: //')
[ -n "$reg" ] && [ "$reg" = "$listed" ] || { echo "BAD: -help's kinds '$listed' are not the registry's '$reg'"; exit 1; }
echo "ok  -help's flow kinds are the registry's: $listed"
check() { # task-args, must-have regex list, must-not regex
  local args=$1 want=$2 not=$3
  $CS_BIN $args -help > "$TMP/t.txt" 2>&1 || { cat "$TMP/t.txt"; echo "BAD: $args -help failed"; exit 1; }
  for w in $want; do grep -qE -- "^  $w " "$TMP/t.txt" || { echo "BAD: $args -help lacks $w"; exit 1; }; done
  grep -E -- "^  -" "$TMP/t.txt" > "$TMP/opts.txt"
  if grep -qE -- "$not" "$TMP/opts.txt"; then echo "BAD: $args -help shows $(grep -E -- "$not" "$TMP/opts.txt" | head -2)"; exit 1; fi
  echo "ok  $args -help: $(grep -c '^  -' "$TMP/t.txt") options, none of /$not/"
}
check "-task flow" "-flow_rtol -flow_type -flow_viewer_every -flow_constraint_area -flow_constraint_add -o -mesh -viewer_dir" "^  -(spin_|bs_)|_ksp_|_pc_"
grep -qE -- "-flow_rtol <5e-07 : 5e-07>" "$TMP/t.txt" || { echo "BAD: -flow_rtol default not shown"; exit 1; }
# an energy's own options (its SetFromOptions under -flow_<energy>_) with that energy
check "-task flow -flow_energy fairing" "-flow_fairing_epsilon -flow_energy" "^  -(spin_|bs_)|_ksp_|_pc_"
check "-task flow -flow_type bs" "-bs_max_it -bs_scheme -o" "^  -(spin_|flow_rtol)|_ksp_|_pc_"
check "-task spin" "-spin_solver -spin_boundary -o" "^  -(flow_|bs_)|_ksp_|_eps_|_st_"
check "-task info" "-mesh -gen -o -mesh_remesh -mesh_remesh_edge_length -mesh_remesh_iterations -o_input" "^  -(flow_|bs_|spin_)"
# the help pass runs on its own options database: PETSc's table of the global one (-options_left, printed at the end)
# holds only what was given, not the pass's -gen, -flow_max_it ... or -help
$CS_BIN -task flow -help -options_left > "$TMP/left.txt" 2>&1 || { cat "$TMP/left.txt"; echo "BAD: -help -options_left failed"; exit 1; }
table=$(sed -n '/Option Table entries/,/End of PETSc Option Table/p' "$TMP/left.txt")
[ -n "$table" ] || { echo "BAD: no options table"; exit 1; }
! grep -qE -- "^-(gen|gen_curve|flow_max_it|bs_max_it|curve_max_it|help)( |$)" <<< "$table" || { echo "BAD: the help pass wrote into the global options database: $table"; exit 1; }
echo "ok  -help leaves the global options database as given"
EXPECT="-flow_rtoll" expect_fail "$CS_BIN" -task flow -gen icosphere -gen_level 1 -flow_max_it 1 -flow_rtoll 1
check "-task curveflow" "-curve_tau -curve -gen_curve -o" "^  -(flow_|bs_|spin_|gen_level)|_ksp_|_pc_"
# -help all: PETSc's own full help of a real run, with the solver objects' blocks the run reaches (PETSc 3.18 reads
# -help's value as a bool: "all" handed on would stop it with "Unknown logical value"), as the task list promises
grep -q -- "-help all" "$TMP/h.txt" || { echo "BAD: the task list no longer names -help all"; exit 1; }
$CS_BIN -task flow -gen icosphere -gen_level 1 -flow_max_it 1 -help all > "$TMP/all.txt" 2>&1 || { tail -20 "$TMP/all.txt"; echo "BAD: -help all failed"; exit 1; }
for w in "Options for all PETSc programs" "-flow_saddle_ksp_type" "-flow_rtol"; do grep -qF -- "$w" "$TMP/all.txt" || { echo "BAD: -help all lacks $w"; exit 1; }; done
echo "ok  -help all: PETSc's full help, $(grep -c -- '-flow_saddle_' "$TMP/all.txt") -flow_saddle_ lines"
# the triangle field's options (its kind's sub-headings inside the flow's block) still listed
check "-task flow -flow_type trianglefield" "-flow_init -flow_integrability_start -flow_spin_weight_decay -flow_type" "^  -(spin_|bs_)|_ksp_|_pc_"
