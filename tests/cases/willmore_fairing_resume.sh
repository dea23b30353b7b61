# -checkpoint/-resume of the fairing baselines (impls/fairing/fairing_baselines.c): 6 steps straight give the same W
# and area at step 6 as 3 steps with -checkpoint and 3 more with -resume on the other number of ranks, leak-free.
# The kind built its Laplacian and mass vectors in ops.start, which a resume skips: every resumed run crashed with
# SEGV (found by the kind recipe's walk-through, docs/DESIGN.md "A kind of the Willmore flow").
# nprocs: 1 2
source tests/lib.sh
if [ "$NP" = 1 ]; then OTHER="mpirun -n 2"; else OTHER=""; fi # the resumed half runs on the other rank count
G="-task flow -gen icosphere -gen_level 3 -gen_deform_bump 0.2 -flow_stationary_window 0"
for k in emcf ebilap imcf ibilap cmcf vmcf isobend; do
  timeout 60 $MPIEXEC "$CS_BIN" $G -flow_type $k -flow_max_it 6 > "$TMP/$k-full.log" 2>&1 || { echo "FAIL: $k straight"; tail -3 "$TMP/$k-full.log"; exit 1; }
  timeout 60 $MPIEXEC "$CS_BIN" $G -flow_type $k -flow_max_it 3 -checkpoint "$TMP/$k.ck" -checkpoint_every 3 > "$TMP/$k-a.log" 2>&1 || { echo "FAIL: $k first half"; tail -3 "$TMP/$k-a.log"; exit 1; }
  timeout 60 $OTHER "$CS_BIN" $G -flow_type $k -flow_max_it 6 -resume "$TMP/$k.ck" -malloc_debug -malloc_dump > "$TMP/$k-b.log" 2>&1 || { echo "FAIL: $k -resume (exit $?)"; tail -3 "$TMP/$k-b.log"; exit 1; }
  a=$(awk '$1 == 6 && $2 == "E" {print $3, $5}' "$TMP/$k-full.log")
  b=$(awk '$1 == 6 && $2 == "E" {print $3, $5}' "$TMP/$k-b.log")
  [ -n "$a" ] && [ "$a" = "$b" ] || { echo "BAD  $k: step 6 (W, area) straight '$a', resumed '$b'"; exit 1; }
  ! grep -q "malloc\|\[0\]" "$TMP/$k-b.log" || { echo "BAD  $k: -malloc_dump"; grep "malloc\|\[0\]" "$TMP/$k-b.log" | head -3; exit 1; }
  echo "ok   $k: step 6 W, area $a straight and resumed"
done
