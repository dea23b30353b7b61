/* Sizes from a file header or a generator's options are checked before they are allocated (issue 18, items 2, 6):
   in 64 bits, against the largest PetscInt and against the memory this process can have, with the sizes in the
   message, rather than a signed overflow, a crash or an anonymous "out of memory" later. */
#include "cs_util.h"
#include <stdio.h>
#include <sys/resource.h>
#include <unistd.h>

/* bytes this process may still get: MemAvailable (or the physical memory), bounded by the address-space limit */
static double AvailableBytes(void)
{
  double        avail = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
  struct rlimit rl;
  FILE         *fp = fopen("/proc/meminfo", "r");
  if (fp) {
    char line[256];
    while (fgets(line, sizeof(line), fp)) {
      double kb;
      if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1) avail = kb * 1024.0;
    }
    fclose(fp);
  }
  if (!getrlimit(RLIMIT_AS, &rl) && rl.rlim_cur != RLIM_INFINITY) avail = PetscMin(avail, (double)rl.rlim_cur);
  return avail;
}

PetscErrorCode CSCheckAllocation(const char what[], PetscInt64 n, size_t size)
{
  double bytes = (double)n * (double)size, avail;
  PetscFunctionBeginUser;
  PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: negative size %" PetscInt64_FMT, what, n);
  PetscCheck(n <= PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: %" PetscInt64_FMT " entries exceed the largest index of this PETSc build (%" PetscInt_FMT ")", what, n, (PetscInt)PETSC_MAX_INT);
  avail = AvailableBytes();
  PetscCheck(bytes <= avail, PETSC_COMM_SELF, PETSC_ERR_MEM, "%s: %" PetscInt64_FMT " entries of %zu bytes need %.3g GB, only %.3g GB of memory are available", what, n, size, bytes / 1e9, avail / 1e9);
  PetscFunctionReturn(0);
}
