#!/usr/bin/env bash
# nprocs: 1 2
# The Willmore flow's ParaView series (src/output/willmore_viewer.c): -flow_viewer_every N writes a step every
# N iterations and the final state into one DIR/series.pvd; without it only the final state (as before the
# redesign); a negative N is refused with an error naming the option.
. tests/lib.sh
B="-task flow -gen icosphere -gen_level 2 -gen_deform_bump 0.2 -flow_max_it 12"
steps() { grep -o 'timestep="[0-9.e+-]*"' "$1/series.pvd" | sed 's/timestep="\(.*\)"/\1/' | tr '\n' ' '; }
timeout 60 $MPIEXEC "$CS_BIN" $B -viewer_dir "$TMP/every" -flow_viewer_every 5 > "$TMP/a.log" 2>&1 || { tail "$TMP/a.log"; exit 1; }
got=$(steps "$TMP/every"); echo "every 5: $got"
[ "$got" = "0 5 10 12 " ] || { echo "BAD: expected steps 0 5 10 12"; exit 1; }
# every step's pieces are written (one .vtu per rank per step, referenced by the .pvtu)
n=$(ls "$TMP/every" | grep -c '\.pvtu$'); [ "$n" = 4 ] || { echo "BAD: $n .pvtu files, expected 4"; exit 1; }
timeout 60 $MPIEXEC "$CS_BIN" $B -viewer_dir "$TMP/final" > "$TMP/b.log" 2>&1 || { tail "$TMP/b.log"; exit 1; }
got=$(steps "$TMP/final"); echo "default: $got"
[ "$got" = "12 " ] || { echo "BAD: expected the final step 12 only"; exit 1; }
# the fields follow the kind (CSWillmoreFlowTriangleFieldGetInfo's flag): a triangle field's omega_0..2 (cell data),
# no el_residual (its residual lives on halfedges); CGD's el_residual and conformal_force, no omega
fields() { grep -o 'Name="[A-Za-z_0-9]*"' "$1"/surface_*.pvtu | sed 's/.*Name="\(.*\)"/\1/' | sort -u | tr '\n' ' '; }
timeout 60 $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_max_it 3 -viewer_dir "$TMP/tf" > "$TMP/tf.log" 2>&1 || { tail "$TMP/tf.log"; exit 1; }
got=$(fields "$TMP/tf"); echo "trianglefield fields: $got"
for f in omega_0 omega_1 omega_2 Q; do [[ " $got" == *" $f "* ]] || { echo "BAD: trianglefield lacks $f"; exit 1; }; done
[[ " $got" != *" el_residual "* ]] || { echo "BAD: trianglefield wrote el_residual"; exit 1; }
got=$(fields "$TMP/final"); echo "cgd fields: $got"
for f in el_residual conformal_force Q; do [[ " $got" == *" $f "* ]] || { echo "BAD: cgd lacks $f"; exit 1; }; done
[[ " $got" != *" omega_0 "* ]] || { echo "BAD: cgd wrote omega_0"; exit 1; }
EXPECT="-flow_viewer_every -1" expect_fail $MPIEXEC "$CS_BIN" $B -viewer_dir "$TMP/bad" -flow_viewer_every -1
echo ok
