# Serial and 2 ranks agree up to a rigid motion (here to round-off: the similarity is normalised the same
# way), with rho read from a per-vertex file (file order) on the level-3 icosphere; and with a per-face rho
# file (-rho_location face), which must give nearly the same surface as the per-vertex one.
# nprocs: 2
source tests/lib.sh
P=tests/cases/spin_tools.py
mpirun -n 1 "$CS_BIN" -task info -gen icosphere -gen_level 3 -o "$TMP/in.obj" > /dev/null
python3 $P rho_bump "$TMP/in.obj" "$TMP/rho.txt"
for np in 1 2; do
  timeout 60 mpirun -n $np "$CS_BIN" -task spin -mesh "$TMP/in.obj" -rho "$TMP/rho.txt" -summary "$TMP/s$np.json" -o "$TMP/o$np.obj" > /dev/null
done
check_close "$(json eigenvalue "$TMP/s2.json")" "$(json eigenvalue "$TMP/s1.json")" 1e-8 "gamma np=2 vs np=1"
check_close "$(json q_mean "$TMP/s2.json")" "$(json q_mean "$TMP/s1.json")" 1e-8 "q_mean np=2 vs np=1"
python3 -c "import sys; q=float(sys.argv[1]); sys.exit(0 if q > 1.001 else 1)" "$(json q_mean "$TMP/s1.json")" || { echo "BAD: rho had no effect"; exit 1; }
check_close "$(python3 $P rigid "$TMP/o1.obj" "$TMP/o2.obj")" 0 1e-7 "positions np=2 vs np=1 (after the best rigid motion)"
python3 $P rho_bump_face "$TMP/in.obj" "$TMP/rhof.txt"
for np in 1 2; do
  timeout 60 mpirun -n $np "$CS_BIN" -task spin -mesh "$TMP/in.obj" -rho "$TMP/rhof.txt" -rho_location face -summary "$TMP/f$np.json" -o "$TMP/f$np.obj" > /dev/null
done
check_close "$(python3 $P rigid "$TMP/f1.obj" "$TMP/f2.obj")" 0 1e-7 "per-face rho: positions np=2 vs np=1"
check_close "$(json q_mean "$TMP/f1.json")" "$(json q_mean "$TMP/s1.json")" 0.01 "per-face vs per-vertex rho: q_mean"
d=$(python3 $P rigid "$TMP/f1.obj" "$TMP/o1.obj"); echo "per-face vs per-vertex rho: distance $d"
python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) < 0.05 else 1)" "$d" || { echo "BAD: per-face and per-vertex rho differ by $d"; exit 1; }
