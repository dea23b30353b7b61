# Reads a valgrind log; fails when a definitely-lost block was allocated directly by our code (src/).
# OpenMPI leaks a few blocks in MPI_Init/MPI_Finalize in every program: those are not ours.
import sys, re, os
ours = set(p for d, _, fs in os.walk(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'src')) for p in fs)

txt = open(sys.argv[1]).read()
blocks = re.split(r'==\d+== \n', txt)
bad = 0
for b in blocks:
    if 'definitely lost' not in b: continue
    frames = re.findall(r'(?:at|by) 0x[0-9A-F]+: (\S+) \(([^)]*)\)', b)
    # first frame after the allocator
    inner = [f for f in frames if f[0] not in ('malloc', 'calloc', 'realloc', 'strdup', 'PetscMallocAlign', 'PetscMallocA')]
    if inner and inner[0][1].split(':')[0] in ours:
        bad += 1; print(b[:1500])
print("leaks allocated directly by our code:", bad)
sys.exit(1 if bad else 0)
