/* t043: gmsh's child process is shut in: it cannot start a program or
 * write a file, and a limit it hits (stack, memory) is named  [LAC §2]
 *
 * Readers run in the child of lac_mesh_child_run, as gmsh does, enter the
 * sandbox of lac_mesh_sandbox.h and try what a hostile .geo would: while
 * gmsh starts (LAC_SANDBOX_INIT) a write fails quietly with EACCES; once
 * the script runs (LAC_SANDBOX_SCRIPT) a write, a removal, a directory or
 * a program ends the child with one message naming what was tried, and
 * nothing is made.  A stack that overflows and a reader that fails
 * without a word at its memory limit get messages that name the limit.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "base/lac_status.h"
#include "io/lac_mesh_child.h"
#include "io/lac_mesh_sandbox.h"

static char victim[64];        /* a file a reader must not make */

static int
write_quietly (void *arg, lac_mesh **out)
{
  FILE *f;
  int st = lac_mesh_sandbox_enter (LAC_SANDBOX_INIT);
  (void) arg, (void) out;
  if (st)
    return st;
  if ((f = fopen (victim, "w")))
    {
      fclose (f);
      return lac_error_set (LAC_ESANITY, "t043", "the write went through");
    }
  return lac_error_set (LAC_EINVAL, "t043", "refused: %s", strerror (errno));
}

/* arg: 0 write, 1 append, 2 mkdir, 3 unlink, 4 rename, 5 a program */
static int
script (void *arg, lac_mesh **out)
{
  int what = *(int *) arg, st = lac_mesh_sandbox_enter (LAC_SANDBOX_INIT);
  FILE *f = NULL;
  (void) out;
  if (!st)
    st = lac_mesh_sandbox_enter (LAC_SANDBOX_SCRIPT);
  if (st)
    return st;
  if (what == 0 || what == 1)
    f = fopen (victim, what ? "a" : "w");
  else if (what == 2)
    mkdir (victim, 0777);
  else if (what == 3)
    unlink ("t043-no-such-file");
  else if (what == 4)
    rename ("t043-no-such-file", victim);
  else if (system ("touch t043-touched") == 0)
    return lac_error_set (LAC_ESANITY, "t043", "the program ran");
  if (f)
    fclose (f);
  return lac_error_set (LAC_ESANITY, "t043", "call %d went through", what);
}

static int
deep (int n)
{
  volatile char pad[4096];
  pad[n % 4096] = (char) n;
  return n > 1000000000 ? pad[0] : deep (n + 1) + pad[n % 4096];
}

static int
overflow (void *arg, lac_mesh **out)
{
  (void) arg, (void) out;
  return deep (0);
}

static int
silent (void *arg, lac_mesh **out)
{
  (void) arg, (void) out;
  return lac_error_set (LAC_EDEP, "lac_mesh_read", "'x.geo': meshing "
                        "failed: gmsh gives no details");
}

static void
sandbox (void)
{
  static const char *words[] = {
    "the script tried to write '", "the script tried to write '",
    "tried to create '", "tried to remove 't043-no-such-file' (unlink",
    "tried to rename 't043-no-such-file'", "tried to start a program" };
  lac_mesh *m = NULL;
  struct stat st;
  int status = lac_mesh_child_run ("mesh", "x.geo", write_quietly, NULL, 0,
                                   10, &m);
  check_status (status, LAC_EINVAL, "init: the write fails, quietly");
  check_message ("Permission denied", "init: EACCES");
  for (int k = 0; k < 6; k++)
    {
      status = lac_mesh_child_run ("mesh", "x.geo", script, &k, 0, 10, &m);
      check_status (status, LAC_EIO, "script: call %d refused", k);
      check_message (words[k], "script: call %d", k);
      check_message (k == 5 ? "SystemCall" : "writes outside lac's output "
                     "are not allowed", "script: call %d", k);
      check_true (m == NULL, "script: call %d: no mesh", k);
    }
  check_true (stat (victim, &st) != 0, "nothing made: %s", victim);
  check_true (stat ("t043-touched", &st) != 0, "no program ran");
}

static void
limits (void)
{
  lac_mesh *m = NULL;
  int status = lac_mesh_child_run ("mesh", "x.geo", overflow, NULL, 0, 30,
                                   &m);
  check_status (status, LAC_EIO, "overflow");
  check_message ("killed by signal 11", "overflow");
  check_message ("its stack overflowed", "overflow");
#if !defined(__SANITIZE_ADDRESS__)
  status = lac_mesh_child_run ("mesh", "x.geo", silent, NULL, 1, 10, &m);
  check_status (status, LAC_ENOMEM, "at the memory limit");
  check_message ("out of memory (limit 1 byte, --max-memory)", "limit");
#endif
  status = lac_mesh_child_run ("mesh", "x.geo", silent, NULL, 0, 10, &m);
  check_status (status, LAC_EDEP, "far from the limit");
  check_message ("gmsh gives no details", "far from the limit");
}

int
main (void)
{
  snprintf (victim, sizeof victim, "/tmp/lac-t043-%ld", (long) getpid ());
  sandbox ();
  limits ();
  unlink (victim);
  rmdir (victim);
  return check_summary ();
}
