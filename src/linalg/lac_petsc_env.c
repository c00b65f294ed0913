/* lac_petsc_env.c -- the processes of the petsc strategy
 *                    (see lac_petsc_env.h)                    [chapter 13]
 */
#include "linalg/lac_petsc_env.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <sys/resource.h>
#include "base/lac_status.h"

/* This process's peak resident memory, MB (Linux: maxrss in kB). */
static double
own_peak_mb (void)
{
  struct rusage u;
  if (getrusage (RUSAGE_SELF, &u) != 0)
    return 0.0;
  return (double) u.ru_maxrss / 1024.0;
}

#ifndef LAC_HAVE_PETSC

/* ---- built without PETSc: one process ----------------------------------- */

int
lac_petsc_available (void)
{
  return 0;
}

int
lac_petsc_initialize (const char *options)
{
  (void) options;
  LAC_ERROR (LAC_EDEP, "lac was built without PETSc (the petsc strategy, "
             "MPI); install it with: %s", LAC_PETSC_INSTALL);
}

int
lac_petsc_initialized (void)
{
  return 0;
}

void
lac_petsc_finalize (void)
{
}

int
lac_petsc_options_unused (char *names, size_t n)
{
  if (n)
    names[0] = 0;
  return 0;
}

void
lac_petsc_rank (int *rank, int *size)
{
  *rank = 0;
  *size = 1;
}

double
lac_petsc_peak_rss_total_mb (int *nproc)
{
  *nproc = 1;
  return own_peak_mb ();
}

int
lac_petsc_option_default (const char *name, const char *value)
{
  (void) name, (void) value;
  return LAC_SUCCESS;
}

int
lac_petsc_option_number (const char *name, const lac_number_spec *spec,
                         const char *expected, double *v)
{
  (void) name, (void) spec, (void) expected, (void) v;
  return LAC_SUCCESS;
}

int
lac_petsc_command_send (const lac_petsc_command *c)
{
  (void) c;
  return LAC_SUCCESS;
}

int
lac_petsc_command_receive (lac_petsc_command *c)
{
  memset (c, 0, sizeof *c);
  c->cmd = LAC_PETSC_CMD_QUIT;
  return LAC_SUCCESS;
}

int
lac_petsc_memory_reply (void)
{
  return LAC_SUCCESS;
}

int
lac_petsc_agree (int status)
{
  return status;
}

int
lac_petsc_bcast (void *buf, size_t bytes)
{
  (void) buf, (void) bytes;
  return LAC_SUCCESS;
}

int
lac_petsc_sum_to_root (double *buf, size_t n)
{
  (void) buf, (void) n;
  return LAC_SUCCESS;
}

int
lac_petsc_fail (int err, const char *func, const char *call)
{
  return lac_error_set (LAC_EDEP, func, "PETSc: %s: error %d", call, err);
}

#else /* LAC_HAVE_PETSC */

#include <petscsys.h>

static char petsc_msg[400];     /* PETSc's first message of an error     */
static int started;             /* 1: lac called PetscInitialize;
                                   2: and the root sent quit              */

static PetscErrorCode
keep_message (MPI_Comm comm, int line, const char *fun, const char *file,
              PetscErrorCode n, PetscErrorType p, const char *mess,
              void *ctx)
{
  (void) comm, (void) file, (void) ctx;
  if (p == PETSC_ERROR_INITIAL)
    snprintf (petsc_msg, sizeof petsc_msg, "%s (in %s, line %d)",
              mess && *mess ? mess : "error", fun, line);
  return n;
}

int
lac_petsc_fail (int err, const char *func, const char *call)
{
  const char *text = NULL;
  int status;
  if (!petsc_msg[0])
    PetscErrorMessage ((PetscErrorCode) err, &text, NULL);
  status = lac_error_set (err == PETSC_ERR_MEM ? LAC_ENOMEM : LAC_EDEP, func,
                          "PETSc: %s: %s", call, petsc_msg[0] ? petsc_msg
                          : text ? text : "error");
  petsc_msg[0] = 0;
  return status;
}

int
lac_petsc_available (void)
{
  return 1;
}

int
lac_petsc_initialized (void)
{
  PetscBool up = PETSC_FALSE;
  PetscInitialized (&up);
  return up == PETSC_TRUE;
}

int
lac_petsc_initialize (const char *options)
{
  PetscErrorCode e;
  if (!lac_petsc_initialized ())
    {
      /* lac's signals are its caller's (and the sanitizers'). */
      PetscOptionsSetValue (NULL, "-no_signal_handler", NULL);
      if (PetscInitializeNoArguments ())
        LAC_ERROR (LAC_EDEP, "PetscInitialize failed (MPI could not start)");
      started = 1;
      PetscPushErrorHandler (keep_message, NULL);
    }
  if (options && *options && (e = PetscOptionsInsertString (NULL, options)))
    return lac_petsc_fail (e, __func__, options);
  return LAC_SUCCESS;
}

int
lac_petsc_options_unused (char *names, size_t n)
{
  PetscInt count = 0;
  char **name = NULL, **value = NULL;
  size_t used = 0;
  if (n)
    names[0] = 0;
  if (!lac_petsc_initialized ()
      || PetscOptionsLeftGet (NULL, &count, &name, &value))
    return 0;
  for (PetscInt i = 0; i < count; i++)
    {
      int w = snprintf (names + used, n - used, "%s-%s", i ? " " : "",
                        name[i]);
      if (w < 0 || (size_t) w >= n - used)
        break;
      used += (size_t) w;
    }
  int unused = (int) count;               /* Restore sets count to 0 */
  PetscOptionsLeftRestore (NULL, &count, &name, &value);
  return unused;
}

int
lac_petsc_option_default (const char *name, const char *value)
{
  PetscBool set = PETSC_FALSE;
  PetscErrorCode e;
  if ((e = PetscOptionsHasName (NULL, NULL, name, &set)))
    return lac_petsc_fail (e, __func__, name);
  if (set)
    return LAC_SUCCESS;
  if ((e = PetscOptionsSetValue (NULL, name, value))
      || (e = PetscOptionsHasName (NULL, NULL, name, &set)))
    return lac_petsc_fail (e, __func__, name);
  return LAC_SUCCESS;
}

int
lac_petsc_option_number (const char *name, const lac_number_spec *spec,
                         const char *expected, double *v)
{
  char text[64] = "", why[160];
  PetscBool set = PETSC_FALSE;
  PetscErrorCode e;
  double x;
  if ((e = PetscOptionsGetString (NULL, NULL, name, text, sizeof text,
                                  &set)))
    return lac_petsc_fail (e, __func__, name);
  if (!set)
    return LAC_SUCCESS;
  if (!text[0])
    LAC_ERROR (LAC_EINVAL, "%s: expected %s, got no value", name,
               expected);
  if (!lac_number_parse (text, spec, &x, why, sizeof why))
    LAC_ERROR (LAC_EINVAL, "%s %s: expected %s; %s", name, text, expected,
               why);
  *v = x;
  return LAC_SUCCESS;
}

void
lac_petsc_rank (int *rank, int *size)
{
  *rank = 0;
  *size = 1;
  if (lac_petsc_initialized ())
    {
      MPI_Comm_rank (PETSC_COMM_WORLD, rank);
      MPI_Comm_size (PETSC_COMM_WORLD, size);
    }
}

void
lac_petsc_finalize (void)
{
  int rank, size;
  if (!started)
    return;
  lac_petsc_rank (&rank, &size);
  if (rank == 0 && size > 1 && started == 1)
    {
      lac_petsc_command c = { .cmd = LAC_PETSC_CMD_QUIT };
      lac_petsc_command_send (&c);
    }
  PetscFinalize ();
  started = 0;
}

int
lac_petsc_command_send (const lac_petsc_command *c)
{
  MPI_Request req;
  int rank, size;
  lac_petsc_rank (&rank, &size);
  if (size == 1)
    return LAC_SUCCESS;
  if (rank != 0)
    LAC_ERROR (LAC_ESANITY, "process %d sends a command: only the root "
               "does", rank);
  if (started == 2)
    LAC_ERROR (LAC_ESANITY, "command %d after quit", c->cmd);
  if (MPI_Ibcast ((void *) c, (int) sizeof *c, MPI_BYTE, 0,
                  PETSC_COMM_WORLD, &req)
      || MPI_Wait (&req, MPI_STATUS_IGNORE))
    LAC_ERROR (LAC_EDEP, "MPI_Ibcast of command %d failed", c->cmd);
  if (c->cmd == LAC_PETSC_CMD_QUIT)
    started = 2;
  return LAC_SUCCESS;
}

/* The wait polls every 0.2 ms and sleeps in between: while the root
 * meshes and assembles alone, the others leave it the cores (MPI's own
 * blocking wait would keep one busy each). */
int
lac_petsc_command_receive (lac_petsc_command *c)
{
  const struct timespec pause = { 0, 200000 };
  MPI_Request req;
  int done = 0;
  if (MPI_Ibcast (c, (int) sizeof *c, MPI_BYTE, 0, PETSC_COMM_WORLD, &req))
    LAC_ERROR (LAC_EDEP, "MPI_Ibcast of a command failed");
  while (!done)
    {
      if (MPI_Test (&req, &done, MPI_STATUS_IGNORE))
        LAC_ERROR (LAC_EDEP, "MPI_Test of a command failed");
      if (!done)
        nanosleep (&pause, NULL);
    }
  return LAC_SUCCESS;
}

int
lac_petsc_memory_reply (void)
{
  double mine = own_peak_mb (), sum = 0;
  if (MPI_Reduce (&mine, &sum, 1, MPI_DOUBLE, MPI_SUM, 0, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Reduce of the peak memory failed");
  return LAC_SUCCESS;
}

int
lac_petsc_agree (int status)
{
  struct { int status; char msg[480]; } e;
  int rank, size, mine, first;
  lac_petsc_rank (&rank, &size);
  if (size == 1)
    return status;
  mine = status ? rank : size;
  if (MPI_Allreduce (&mine, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Allreduce of the processes' statuses failed");
  if (first == size)
    return LAC_SUCCESS;
  memset (&e, 0, sizeof e);
  if (rank == first)
    {
      e.status = status;
      snprintf (e.msg, sizeof e.msg, "%s", lac_error_message ());
    }
  if (MPI_Bcast (&e, (int) sizeof e, MPI_BYTE, first, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Bcast of process %d's error failed", first);
  if (rank == first && first == 0)
    return status;
  if (first == 0)
    return lac_error_restore (e.status, e.msg);
  return lac_error_set (e.status, NULL, "process %d: %s", first, e.msg);
}

/* In pieces of at most 1 GB (MPI's counts are int). */
int
lac_petsc_bcast (void *buf, size_t bytes)
{
  char *p = buf;
  for (size_t done = 0; done < bytes;)
    {
      size_t m = bytes - done < (1u << 30) ? bytes - done : (1u << 30);
      if (MPI_Bcast (p + done, (int) m, MPI_BYTE, 0, PETSC_COMM_WORLD))
        LAC_ERROR (LAC_EDEP, "MPI_Bcast of %zu bytes failed", bytes);
      done += m;
    }
  return LAC_SUCCESS;
}

/* In pieces of at most 2^27 doubles (1 GB). */
int
lac_petsc_sum_to_root (double *buf, size_t n)
{
  int rank, size;
  lac_petsc_rank (&rank, &size);
  for (size_t done = 0; size > 1 && done < n;)
    {
      size_t m = n - done < (1u << 27) ? n - done : (1u << 27);
      if (MPI_Reduce (rank ? buf + done : MPI_IN_PLACE, buf + done, (int) m,
                      MPI_DOUBLE, MPI_SUM, 0, PETSC_COMM_WORLD))
        LAC_ERROR (LAC_EDEP, "MPI_Reduce of %zu numbers failed", n);
      done += m;
    }
  return LAC_SUCCESS;
}

double
lac_petsc_peak_rss_total_mb (int *nproc)
{
  int rank;
  double mine = own_peak_mb (), sum = mine;
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_MEMORY };
  lac_petsc_rank (&rank, nproc);
  if (*nproc > 1 && rank == 0 && lac_petsc_command_send (&c) == LAC_SUCCESS
      && MPI_Reduce (&mine, &sum, 1, MPI_DOUBLE, MPI_SUM, 0,
                     PETSC_COMM_WORLD) != MPI_SUCCESS)
    sum = mine;
  return sum;
}

#endif /* LAC_HAVE_PETSC */
