/* lac_petsc_serve.c -- the petsc strategy on the processes other than
 *                      the root: the root's commands followed with the
 *                      same steps and none of its data (see lac_petsc.h)
 *                                                          [chapter 13]
 *
 * Each command ends with the agreement of every process on its status
 * (lac_petsc_agree), but free and memory, which cannot fail.  A build
 * with LAC_TEST_FAULTS fails a process on purpose (the Makefile's
 * lac_faults, tests/cases-petsc.sh).
 */
#ifdef LAC_HAVE_PETSC

#include <stdlib.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_post_dist.h"
#include "solve/lac_petsc_internal.h"

/* ---- the other processes ------------------------------------------------ */

#ifdef LAC_TEST_FAULTS
/* A failure on purpose (test builds): LAC_TEST_FAIL_AFTER=R:NAME fails
 * process R once its step of the command NAME (build, update, solve,
 * kmul, post) is done, after its last collective call, where only the
 * agreement that ends the command carries it to the root. */
static int
injected (const lac_petsc *s, int cmd)
{
  static const char *name[] = { "", "build", "update", "solve", "free",
                                "memory", "kmul", "post", "quit" };
  const char *v = getenv ("LAC_TEST_FAIL_AFTER"), *colon;
  if (!v || !(colon = strchr (v, ':')) || atoi (v) != s->rank || cmd < 1
      || cmd > LAC_PETSC_CMD_QUIT || strcmp (colon + 1, name[cmd]) != 0)
    return LAC_SUCCESS;
  LAC_ERROR (LAC_EDEP, "failure injected by LAC_TEST_FAIL_AFTER after the "
             "%s", name[cmd]);
}
#else
#define injected(s, cmd) LAC_SUCCESS
#endif

/* The others: the root's command, the same steps as the root's with
 * none of its data. */
static int
follow (lac_petsc *s, const lac_petsc_command *c)
{
  int status;
  switch (c->cmd)
    {
    case LAC_PETSC_CMD_BUILD:
      status = lac_petsc_build (s, c, NULL);
      break;
    case LAC_PETSC_CMD_UPDATE:
      status = lac_petsc_update_values (s, c, NULL);
      break;
    case LAC_PETSC_CMD_SOLVE:
      status = lac_petsc_step_solve (s, c, NULL, NULL, NULL, NULL);
      break;
    case LAC_PETSC_CMD_FREE:
      lac_petsc_free_petsc (s);
      lac_petsc_free_arrays (s);
      return LAC_SUCCESS;
    case LAC_PETSC_CMD_MEMORY:
      return lac_petsc_memory_reply ();
    case LAC_PETSC_CMD_KMUL:
      status = lac_petsc_step_kmul (s, NULL, NULL);
      break;
    case LAC_PETSC_CMD_POST:
      status = lac_dist_post (s->dist, NULL);
      break;
    default:
      LAC_ERROR (LAC_ESANITY, "unknown command %d", c->cmd);
    }
  return status ? status : injected (s, c->cmd);
}

/* 1 for the commands that end with an agreement on their status (the
 * others cannot fail on a process: free, memory). */
static int
agreed (int cmd)
{
  return cmd == LAC_PETSC_CMD_BUILD || cmd == LAC_PETSC_CMD_UPDATE
         || cmd == LAC_PETSC_CMD_SOLVE || cmd == LAC_PETSC_CMD_KMUL
         || cmd == LAC_PETSC_CMD_POST;
}

/* Each command ends with the agreement of every process on its status,
 * as the root's side ends it: a failure on this process (after the
 * steps' own agreements too) reaches the root with this process's
 * message, and the root ends the run. */
int
lac_petsc_serve (void)
{
  lac_petsc *s;
  lac_petsc_command c;
  int status;
  if (!lac_petsc_initialized ())
    LAC_ERROR (LAC_EINVAL, "lac_petsc_initialize was not called");
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR (LAC_ENOMEM, "petsc worker");
  lac_petsc_rank (&s->rank, &s->size);
  if (s->rank == 0)
    {
      lac_free (s);
      LAC_ERROR (LAC_EINVAL, "the root runs the scene; the others serve");
    }
  while (!(status = lac_petsc_command_receive (&c))
         && c.cmd != LAC_PETSC_CMD_QUIT)
    {
      status = follow (s, &c);
      if (agreed (c.cmd))
        lac_petsc_agree (status);
      lac_error_clear ();
    }
  lac_petsc_free_petsc (s);
  lac_petsc_free_arrays (s);
  lac_free (s);
  return status;
}

#else

typedef int lac_petsc_serve_unused;     /* lac_petsc.c: without PETSc */

#endif /* LAC_HAVE_PETSC */
