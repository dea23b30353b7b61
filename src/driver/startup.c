/* What bin/confsurf does before MPI starts: the start-up defaults of a serial run (an MPI singleton) and the
   private folder Open MPI's session tree goes into (issue 36, item 2). */
#define _XOPEN_SOURCE 700
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cs_driver.h"

static char SessionBase[4096]; /* the private folder, removed at exit; "" when none */

static int RemoveEntry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
  (void)st;
  (void)flag;
  (void)ftw;
  (void)remove(path);
  return 0;
}

/* atexit: after MPI_Finalize (which empties its own tree) and on every exit() path, also MPI_Abort's */
static void SessionBaseRemove(void)
{
  if (!SessionBase[0]) return;
  (void)nftw(SessionBase, RemoveEntry, 16, FTW_DEPTH | FTW_PHYS);
  SessionBase[0] = 0;
}

/* Open MPI 4.1's isolated singleton (ess_singleton_isolated, opal/mca/pmix/isolated) names every process [[0,1],0],
   so all serial runs of a user share one session tree, $TMPDIR/ompi.<host>.<uid>/jf.0/1/0 (orte/util/session_dir.c).
   A run that finalizes removes that tree (proc, job, job-family and top folders) while another one that starts is
   creating it one folder at a time (opal_os_dirpath_create): its mkdir fails with ENOENT and MPI_Init aborts
   (3 of 400 runs of 8 concurrent `-task info`, runs/startup_race.sh). Each run gets its own tree instead: Open MPI's
   orte_tmpdir_base points at a fresh mkdtemp folder under $TMPDIR (or /tmp), removed at exit. Not when the user
   chose a tmpdir base (any of Open MPI's three parameters), and not when the folder cannot be made (then the shared
   tree, as before). A run killed by a signal Open MPI does not catch (SIGKILL) leaves its folder behind: a few empty
   folders, /tmp/confsurf-mpi.XXXXXX/ompi.<host>.<uid>/jf.0/1/0, as Open MPI itself leaves its tree then. */
static void PrivateSessionTree(void)
{
  const char *tmp = getenv("TMPDIR");
  if (getenv("OMPI_MCA_orte_tmpdir_base") || getenv("OMPI_MCA_orte_local_tmpdir_base") || getenv("OMPI_MCA_orte_remote_tmpdir_base")) return;
  if (!tmp || !tmp[0]) tmp = "/tmp";
  if (snprintf(SessionBase, sizeof(SessionBase), "%s/confsurf-mpi.XXXXXX", tmp) >= (int)sizeof(SessionBase) || !mkdtemp(SessionBase)) {
    SessionBase[0] = 0;
    return;
  }
  if (atexit(SessionBaseRemove)) {
    (void)rmdir(SessionBase);
    SessionBase[0] = 0;
    return;
  }
  setenv("OMPI_MCA_orte_tmpdir_base", SessionBase, 1);
}

/* Start-up of a serial run (an MPI singleton, not started by mpirun): Open MPI's defaults spawn a helper daemon
   (ess singleton), open UCX and every transport (pml, btl) and let hwloc load its GL/OpenCL/PCI/libxml plugins (X11,
   libicu) and opens nine collective components; for one process none of that is used. Measured (docs/output.md):
   MPI_Init 384 ms -> 46 ms, the tiny -task info run 0.60 s -> 0.14 s wall. Set only
   what the user did not set; CS_MPI_DEFAULTS=0 turns it off (and the private session tree with it). */
void CSSingletonDefaults(void)
{
  const char *off = getenv("CS_MPI_DEFAULTS");
  if (off && !strcmp(off, "0")) return;
  if (getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMIX_RANK") || getenv("PMI_RANK")) return; /* under a launcher */
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_btl", "self", 0);
  setenv("OMPI_MCA_coll", "self,basic,libnbc", 0);
  setenv("HWLOC_PLUGINS_BLACKLIST", "hwloc_gl,hwloc_opencl,hwloc_pci,hwloc_xml_libxml", 0);
  PrivateSessionTree();
}
