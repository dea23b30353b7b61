# tests/README.md maps every case script, unit program and golden case (tests/tools/check_readme.py): each appears
# in its table, no name there is stale, a unit program sits in the row of a case that runs it, and the (np=...)
# marks agree with the scripts' "# nprocs:" lines. A new or renamed test fails here until the map has it.
# nprocs: 1
source tests/lib.sh
python3 tests/tools/check_readme.py
