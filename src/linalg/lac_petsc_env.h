/* lac_petsc_env.h -- the MPI processes of PETSc: MPI and PETSc started
 *                    and stopped, the root's commands, memory
 *                                                          [chapter 13]
 *
 * lac on N MPI processes (mpirun -n N lac run ...): process 0, the root,
 * runs the scene; the others follow its commands (solve/lac_petsc.h,
 * lac_petsc_serve).  This module starts MPI and PETSc with the options of
 * the command line and of PETSC_OPTIONS, broadcasts the root's commands,
 * turns PETSc's errors into lac's (PETSc prints nothing: its messages are
 * kept and become lac's message), and sums the peak memory of the
 * processes.  Built without PETSc (no LAC_HAVE_PETSC) the same functions
 * exist: one process, and lac_petsc_initialize fails with the apt-get line
 * (LAC_PETSC_INSTALL).
 *
 * PETSc and MPI are process-wide: whether lac started them, and PETSc's
 * last message, are the module's two static variables.
 */
#ifndef LAC_PETSC_ENV_H
#define LAC_PETSC_ENV_H

#include <stddef.h>
#include "base/lac_number.h"

#define LAC_PETSC_INSTALL "apt-get install -y --no-install-recommends " \
  "libpetsc-real-dev openmpi-bin, then make clean && make"

/* 1 if lac was built with PETSc. */
int lac_petsc_available (void);
/* Initialize MPI (if nobody did) and PETSc (if nobody did): PETSc reads
 * PETSC_OPTIONS; then add `options` ("-key value ...", NULL or "": none),
 * which win.  Every process, with the same options. */
int lac_petsc_initialize (const char *options);
/* 1 once lac_petsc_initialize succeeded (or PETSc was started by the
 * caller). */
int lac_petsc_initialized (void);
/* The root: release the other processes (quit).  Then finalize PETSc and
 * MPI if lac_petsc_initialize started them.  Last call of main() on
 * every process; nothing without PETSc or before initialize. */
void lac_petsc_finalize (void);
/* The options given to PETSc (command line, PETSC_OPTIONS) that nothing
 * read: their names joined by spaces into names[n] (cut if longer); the
 * count.  0 without PETSc or before initialize.  Called by the root after
 * the run, so that an option with a wrong prefix, or one given to a run
 * that solved nothing with PETSc, is not ignored silently. */
int lac_petsc_options_unused (char *names, size_t n);
/* PETSc's option `name` ("-prefix_key") set to `value` unless the user
 * set it (the user's options win, as in PETSc); marked read, so that
 * the warning about the options nothing read does not name lac's own
 * when another preconditioner than the one it configures was chosen.
 * Nothing without PETSc. */
int lac_petsc_option_default (const char *name, const char *value);
/* One of lac's own options (-lac_omega ...) as a number: *v (left as it
 * is when the option is not given) from its text, which must be a
 * number within spec (base/lac_number.h: NULL, any finite one); a value
 * missing, not a number or out of range is an error naming the option,
 * the limit it broke and what is `expected` (PETSc's own reading keeps
 * *v for a missing value and wraps an integer beyond 32 bits).  Nothing
 * without PETSc. */
int lac_petsc_option_number (const char *name, const lac_number_spec *spec,
                             const char *expected, double *v);
/* This process and the number of processes: 0 and 1 without MPI or
 * before lac_petsc_initialize. */
void lac_petsc_rank (int *rank, int *size);
/* The peak resident memory (MB, getrusage's maxrss) summed over the
 * processes, and their number: the root asks the others (they answer in
 * lac_petsc_serve).  One process: its own. */
double lac_petsc_peak_rss_total_mb (int *nproc);

/* ---- the root's commands (for the petsc strategy, solve/lac_petsc.c) ---- */

typedef enum
{
  LAC_PETSC_CMD_BUILD = 1,  /* new layout and patterns                    */
  LAC_PETSC_CMD_UPDATE,     /* new values of the matrices                 */
  LAC_PETSC_CMD_SOLVE,      /* one solve of (*W) (of K when k = 0)        */
  LAC_PETSC_CMD_FREE,       /* destroy the strategy's objects             */
  LAC_PETSC_CMD_MEMORY,     /* add the peak memory to the root's          */
  LAC_PETSC_CMD_KMUL,       /* K_W x for the root's residuals             */
  LAC_PETSC_CMD_POST,       /* stresses and errors of the own cells       */
  LAC_PETSC_CMD_QUIT        /* the root is done                           */
} lac_petsc_cmd;

typedef struct lac_petsc_command
{
  int cmd;                  /* lac_petsc_cmd                              */
  int mode, bs, coords;     /* build: the contact solver (-lac_contact),
                               block size, coordinates given              */
  int all;                  /* update: every row (new numbers)            */
  int cells;                /* build: K from the cells (fem/lac_assembly_dist.h) */
  int warm;                 /* solve: the start is the last solution      */
  long long n, k;           /* build: displacements, multipliers          */
  double rtol;              /* solve: relative residual                   */
  double omega;             /* build: W_i = omega / s_i, which every
                               process computes                          */
  double threshold;         /* build: the contact multigrid's threshold
                               (-lac_contact_threshold, read by the root) */
} lac_petsc_command;

/* The root: c to every other process (nothing with one process). */
int lac_petsc_command_send (const lac_petsc_command *c);
/* The others: the root's next command. */
int lac_petsc_command_receive (lac_petsc_command *c);
/* The others, on LAC_PETSC_CMD_MEMORY: their share of the sum. */
int lac_petsc_memory_reply (void);
/* Every process, after a step that may fail on some of them and before
 * the next collective call: status on every process is the status of
 * the first process that failed (LAC_SUCCESS if none), with its message
 * ("process 1: ..." when it is not the root).  One process: status. */
int lac_petsc_agree (int status);
/* The root's `bytes` bytes at buf to every process (MPI_Bcast). */
int lac_petsc_bcast (void *buf, size_t bytes);
/* buf[n] of the root becomes the sum of every process's buf[n]
 * (MPI_Reduce; the others' buf unchanged). */
int lac_petsc_sum_to_root (double *buf, size_t n);
/* LAC_EDEP (LAC_ENOMEM) with PETSc's message for the failed call `call`
 * of `func` (err: its PetscErrorCode). */
int lac_petsc_fail (int err, const char *func, const char *call);

#endif /* LAC_PETSC_ENV_H */
