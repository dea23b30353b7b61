# No invalid memory access and no leak of ours under valgrind: a bad file (error path) and a full info run
# with every output; two error paths of issue 18 (a full disk, a damaged checkpoint: ~5 s of CPU each).
# (OpenMPI's own MPI_Init leaks are told apart by tests/valgrind_leaks.py.)
# nprocs: 1
source tests/lib.sh
command -v valgrind >/dev/null || { echo "valgrind not installed: apt-get install valgrind"; exit 1; }
"$CS_BIN" -gen icosphere -gen_level 2 -o "$TMP/ref.obj" >/dev/null
F="-task flow -gen icosphere -gen_level 1 -flow_max_it 2"
"$CS_BIN" $F -checkpoint "$TMP/c.ck" > /dev/null
python3 -c "import sys; d = open(sys.argv[1], 'rb').read(); open(sys.argv[2], 'wb').write(d[:-9] + bytes([d[-9] ^ 1]) + d[-8:])" "$TMP/c.ck" "$TMP/flip.ck"
for args in "-mesh tests/data/pinched_vertex.obj" "-mesh $TMP/ref.obj -o $TMP/out.ply -summary $TMP/s.json -viewer_dir $TMP/vtu -reference $TMP/ref.obj" \
  "-mesh $TMP/ref.obj -summary /dev/full" "$F -resume $TMP/flip.ck"; do
  valgrind --leak-check=full -q "$CS_BIN" $args > "$TMP/vg.log" 2>&1 || true
  if grep -q "Invalid \|uninitialised" "$TMP/vg.log"; then cat "$TMP/vg.log"; echo "BAD: invalid access: $args"; exit 1; fi
  python3 tests/valgrind_leaks.py "$TMP/vg.log" || { echo "BAD: leak: $args"; exit 1; }
  echo "ok  valgrind clean: $args"
done
