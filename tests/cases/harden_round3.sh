# Issue 36 (third hardening round), items 1, 2, 4, 9, 10, 11, 13, 14, 15, 19: each hostile input is refused before
# any work with one line naming the option or file (refuse: non-zero exit below 128, no signal, no hang, the line
# printed once, no PETSc error block), and nothing is half-written or lost.
# nprocs: 1 2
source tests/lib.sh
T="timeout 30"
G="-task info -gen icosphere -gen_level 1"
F="-task flow -gen icosphere -gen_level 1 -flow_max_it 2"
serial() { [ "$NP" = 1 ]; } # what does not depend on the ranks runs serially only
mkdir "$TMP/w" && cd "$TMP/w" # $TMP/log is the runner's
# refuse CMD...: fails cleanly with $EXPECT in exactly one line
refuse() {
  local out rc=0
  out=$($T $MPIEXEC "$CS_BIN" "$@" 2>&1) || rc=$?
  local n; n=$(grep -cE -- "$EXPECT" <<< "$out" || true)
  if [ "$rc" = 0 ] || [ "$rc" -ge 124 ] || [ "$n" != 1 ] || grep -qE "PETSC ERROR|Caught signal|Sanitizer|runtime error:" <<< "$out"; then
    echo "$out" | head -20; echo "BAD (exit $rc, $n lines /$EXPECT/): $*"; exit 1
  fi
  echo "ok  refused (exit $rc): $(cut -c1-150 <<< "$*")"
}
mkdir d d.obj; touch plain; mkfifo fifo fifo.obj fifo.opts
# item 1: PETSc's -history at a folder, from the command line, PETSC_OPTIONS and an options file (was SIGSEGV)
EXPECT="^confsurf: error: -history d: cannot write there \(is a folder" refuse $G -history d
serial && EXPECT="^confsurf: error: -history d: cannot write there" PETSC_OPTIONS="-history d" refuse $G
printf -- '-history d\n' > h.opts
EXPECT="^confsurf: error: -history d: cannot write there" refuse $G -options_file h.opts
serial && EXPECT="^confsurf: error: -history plain/h.txt: cannot write there" refuse $G -history plain/h.txt
# item 4: FIFOs nobody reads or writes, as outputs and as an options file, are refused without blocking
EXPECT="-o fifo.obj: a FIFO nobody reads" refuse $F -o fifo.obj
serial && EXPECT="-summary fifo: a FIFO nobody reads" refuse $G -summary fifo
EXPECT="-history_csv fifo: a FIFO nobody reads" refuse $F -history_csv fifo
serial && EXPECT="-history fifo: cannot write there \(a FIFO nobody reads" refuse $G -history fifo
serial && EXPECT="^confsurf: error: -options_file fifo.opts: cannot read it \(is not a regular file" refuse $G -options_file fifo.opts
# item 19: an options file that is a folder, or names itself, is one line
EXPECT="^confsurf: error: -options_file d: cannot read it \(is a folder" refuse $G -options_file d
printf -- '-options_file self.opts\n' > self.opts
serial && EXPECT="^confsurf: error: -options_file self.opts: options files nested more than 8" refuse $G -options_file self.opts
# item 13: every output checked before the first iteration (the flow prints its first line only after the checks)
EXPECT="-o d.obj: is a folder" refuse $F -o d.obj
serial && EXPECT="-summary d: is a folder" refuse $F -summary d
serial && EXPECT="-history_csv d: is a folder" refuse $F -history_csv d
EXPECT="-o plain/x.obj: cannot write there \(Not a directory" refuse $F -o plain/x.obj
serial && EXPECT="-summary /proc/s.json: cannot create" refuse $F -summary /proc/s.json
out=$($T $MPIEXEC "$CS_BIN" $F -o d.obj 2>&1 || true)
grep -q "^flow " <<< "$out" && { echo "BAD: the flow started before -o was checked"; exit 1; }
EXPECT="-checkpoint: needs a value" refuse $F -checkpoint ''
# item 14: two outputs to one file (also through ./ and a link)
ln -s plain link.obj
EXPECT="-summary s.obj: the same file as -o" refuse $G -o s.obj -summary s.obj
serial && EXPECT="-o ./x.obj: the same file as -checkpoint|-checkpoint x.obj: the same file as -o" refuse $F -checkpoint x.obj -o ./x.obj
serial && EXPECT="-summary plain: the same file as -o" refuse $G -o link.obj -summary plain
EXPECT="-history h.csv: the same file as -history_csv" refuse $F -history_csv h.csv -history h.csv
if [ -e s.obj ] || [ -e x.obj ]; then echo "BAD: a refused run left a file"; exit 1; fi
# h.csv is PETSc's own -history log (opened in PetscInitialize, before the outputs are read), complete, not ours
if [ -e h.csv ]; then head -1 h.csv | grep -q "^-----" || { echo "BAD: h.csv is not PETSc's log"; exit 1; }; rm h.csv; fi
# items 9-11: integers that wrap, values that would be cut, empty values
EXPECT="-flow_max_it 4294967298: out of range" refuse $F -flow_max_it 4294967298
serial && EXPECT="-gen_level 4294967298: out of range" refuse $G -gen_level 4294967298
EXPECT="-flow_max_it 99999999999999999999: out of range" refuse $F -flow_max_it 99999999999999999999
# an integer option given a fraction or one of PETSc's words is refused naming the option (PETSc's reader named
# only the string, and turned DEFAULT into -2)
serial && EXPECT="-gen_level 1.5: not an integer" refuse $G -gen_level 1.5
serial && EXPECT="-flow_max_it DEFAULT: not an integer" refuse $F -flow_max_it DEFAULT
serial && EXPECT="-flow_rtol abc: not a number" refuse $F -flow_rtol abc
long=$(printf 'a%.0s' $(seq 4100))
EXPECT="-summary: the value is 4105 characters long, at most 4095" refuse $G -summary "$long.json"
serial && EXPECT="-mesh: the value is 4104 characters long" refuse -task info -mesh "$long.obj"
EXPECT="-flow_t: needs a number" refuse $F -flow_t ''
serial && EXPECT="-gen: needs a value" refuse -task info -gen '' -gen_level 1
serial && EXPECT="-gen_level: needs an integer value" refuse -task info -gen icosphere -gen_level ''
serial && EXPECT="-mesh_lengths: needs a value" refuse $F -mesh_lengths ''
[ -z "$(ls | grep -v -e '^d$' -e '^d.obj$' -e '^plain$' -e fifo -e opts -e link.obj -e '^log$')" ] || { ls; echo "BAD: files left behind"; exit 1; }
# item 19: a 250-character checkpoint name (its temporary name must stay within 255); output into a closed pipe
ck=$(printf 'c%.0s' $(seq 250))
$T $MPIEXEC "$CS_BIN" $F -checkpoint "$ck" > log 2>&1 || { cat log; echo "BAD: 250-character checkpoint"; exit 1; }
[ -s "$ck" ] && [ "$(ls | grep -c '^ccc')" = 1 ] || { ls; echo "BAD: checkpoint or its temporary"; exit 1; }
echo "ok  250-character -checkpoint written"
rc=0; { $T $MPIEXEC "$CS_BIN" $F -o piped.obj 2> err | head -1 > /dev/null; } || true
rc=${PIPESTATUS[0]:-0}
grep -qE "PETSC ERROR|Broken Pipe|MPI_ABORT" err && { cat err; echo "BAD: crash dump on a closed pipe"; exit 1; }
[ -s piped.obj ] || { cat err; echo "BAD: the run into a closed pipe did not finish"; exit 1; }
echo "ok  a closed stdout pipe: no crash dump, the run finished"
rm -f piped.obj err log "$ck"
# item 15: a full disk (a 1 KB file size limit, SIGXFSZ ignored) keeps the complete rows of -history_csv
# (the limit is set inside each rank: mpirun's own shared-memory files must not hit it)
out=$($T $MPIEXEC bash -c "trap '' XFSZ; ulimit -f 1; exec \"$CS_BIN\" -task flow -gen icosphere -gen_level 2 -flow_max_it 50 -history_csv h.csv" 2>&1) && { echo "BAD: exit 0 on a full disk"; exit 1; }
grep -qE -- "-history_csv h.csv: write error \(File too large\); kept the [1-9][0-9]* complete rows" <<< "$out" || { echo "$out" | tail -5; echo "BAD: message"; exit 1; }
kept=$(sed -n 's/.*kept the \([0-9]*\) complete rows.*/\1/p' <<< "$out" | head -1)
python3 - h.csv "$kept" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
assert len(rows) == int(sys.argv[2]) + 1, (len(rows), sys.argv[2])
assert all(len(r) == len(rows[0]) for r in rows), "a half-written row"
print(f"ok  full disk: header and {len(rows) - 1} complete rows kept, as the message says")
PY
# item 2: a serial run puts Open MPI's session tree in a private folder under TMPDIR, removed at exit
serial || exit 0
mkdir tmpdir
for i in 1 2; do TMPDIR=$TMP/w/tmpdir OMPI_MCA_orte_debug=1 $T "$CS_BIN" $G 2>&1 >/dev/null | sed -n 's/.*procdir: //p' > proc$i; done
grep -q "^$TMP/w/tmpdir/confsurf-mpi\.[A-Za-z0-9]*/ompi\." proc1 || { cat proc1; echo "BAD: session tree not private"; exit 1; }
cmp -s proc1 proc2 && { echo "BAD: two runs share a session tree"; exit 1; }
[ -z "$(ls -A tmpdir)" ] || { ls -R tmpdir; echo "BAD: the private session tree was left behind"; exit 1; }
EXPECT="" OMPI_MCA_orte_tmpdir_base=$TMP/w/tmpdir $T "$CS_BIN" $G > /dev/null
[ -z "$(ls -A tmpdir | grep confsurf-mpi)" ] || { echo "BAD: a private tree despite the user's orte_tmpdir_base"; exit 1; }
echo "ok  private session trees: $(cat proc1) and another, both removed"
