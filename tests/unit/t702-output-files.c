/* t702: output files -- VTU and CSV contents, batches that appear together
 *
 * A 2 x 1 box of quad8 cells (lac_mesh_box) with a linear displacement is
 * written through a batch: the files appear only on commit, all at once;
 * a batch freed without commit or interrupted leaves the earlier files and
 * no temporaries; a new run's files replace the earlier run's (no mixed
 * set), files a run never writes are kept, and what a killed run left
 * beside the directory is cleaned up by the next batch.  A file, a link
 * to a file, a path under a file are refused with the path and the reason;
 * a link to a directory stands for it, which keeps its permissions.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "base/lac_mem.h"
#include <signal.h>
#include <sys/stat.h>
#include "io/lac_output.h"
#include "io/lac_output_batch.h"
#include "base/lac_status.h"

static char dir[64], base[32];

static char *
slurp (const char *name)
{
  char path[128], *buf = calloc (1, 1 << 20);
  FILE *f;
  snprintf (path, sizeof path, "%s/%s", dir, name);
  if (!(f = fopen (path, "r")))
    {
      free (buf);
      return NULL;
    }
  if (fread (buf, 1, (1 << 20) - 1, f) == 0)
    buf[0] = '\0';
  fclose (f);
  return buf;
}

/* Entries of path (but . and ..); -1 if it is no directory. */
static int
count_in (const char *path)
{
  DIR *d = opendir (path);
  struct dirent *e;
  int n = 0;
  while (d && (e = readdir (d)) != NULL)
    n += e->d_name[0] != '.' || (strcmp (e->d_name, ".")
                                 && strcmp (e->d_name, ".."));
  if (d)
    closedir (d);
  return d ? n : -1;
}

static int
count_files (void)
{
  return count_in (dir);
}

/* Write a small file in dir. */
static void
put (const char *d, const char *name, const char *text)
{
  char path[160];
  FILE *f;
  snprintf (path, sizeof path, "%s/%s", d, name);
  if ((f = fopen (path, "w")))
    {
      fputs (text, f);
      fclose (f);
    }
}

static size_t
count (const char *s, const char *needle)
{
  size_t n = 0;
  for (; (s = strstr (s, needle)) != NULL; s++)
    n++;
  return n;
}

static void
test_files (const lac_mesh *m)
{
  double *u = lac_malloc (m->nnodes * 2 * sizeof *u);
  double *sig = lac_calloc (m->nnodes * 4, sizeof *sig);
  double *vm = lac_calloc (m->nnodes, sizeof *vm);
  lac_output_fields f = { m, LAC_PLANE_STRAIN, u, NULL, sig, vm, 1 };
  lac_output_batch *b = lac_output_batch_alloc (dir, NULL);
  const char *key[] = { "nodes", "title" }, *val[] = { "21", "a box" };
  const char *p1, *p2, *p3;
  char *vtu, *csv, *sum;
  for (size_t a = 0; a < m->nnodes; a++)
    u[2 * a] = 0.5 * m->x[2 * a], u[2 * a + 1] = 0;
  check_true (b != NULL, "batch in a new directory: %s", lac_error_message ());
  if (!b)
    goto done;
  p1 = lac_output_batch_add (b, "solution.vtu");
  p2 = lac_output_batch_add (b, "nodes.csv");
  p3 = lac_output_batch_add (b, "summary.txt");
  check_status (lac_output_vtu (p1, &f), LAC_SUCCESS, "vtu");
  check_status (lac_output_csv (p2, &f), LAC_SUCCESS, "csv");
  check_status (lac_output_summary (p3, 2, key, val), LAC_SUCCESS, "summary");
  check_int (count_files (), -1, "no directory before commit");
  check_int (count_in (base), 1, "the temporary directory beside it");
  check_true (!(vtu = slurp ("solution.vtu")), "no solution.vtu yet");
  free (vtu);
  check_status (lac_output_commit (b), LAC_SUCCESS, "commit");
  lac_output_batch_free (b);
  check_int (count_files (), 3, "three files after commit");
  check_int (count_in (base), 1, "no temporary left beside");

  vtu = slurp ("solution.vtu");
  csv = slurp ("nodes.csv");
  sum = slurp ("summary.txt");
  check_true (vtu && csv && sum, "files readable");
  if (vtu && csv && sum)
    {
      char want[64];
      snprintf (want, sizeof want, "NumberOfPoints=\"%zu\" NumberOfCells="
                "\"%zu\"", m->nnodes, m->ncells);
      check_true (strstr (vtu, want) != NULL, "vtu counts");
      check_int ((long) count (vtu, "\n          23\n"), (long) m->ncells,
                 "vtu types: quad8 is VTK 23");
      check_true (strstr (vtu, "Name=\"stress_xy\"") && strstr
                  (vtu, "Name=\"von_mises\"") && strstr (vtu, "Name=\"body\""),
                  "vtu arrays");
      check_true (strstr (vtu, "</VTKFile>\n") != NULL, "vtu closed");
      check_int ((long) count (csv, "\n"), (long) m->nnodes + 1, "csv rows");
      check_true (strncmp (csv, "node,x,y,z,u_x,u_y,s_xx,s_yy,s_zz,s_xy,"
                           "von_mises\n", 45) == 0, "csv header");
      check_true (strcmp (sum, "nodes = 21\ntitle = a box\n") == 0, "summary");
    }
  free (vtu), free (csv), free (sum);

  /* A batch that fails (freed without commit) changes nothing. */
  b = lac_output_batch_alloc (dir, NULL);
  if (b)
    {
      p3 = lac_output_batch_add (b, "summary.txt");
      lac_output_summary (p3, 1, key, val);
      lac_output_batch_free (b);
    }
  sum = slurp ("summary.txt");
  check_true (sum && strcmp (sum, "nodes = 21\ntitle = a box\n") == 0,
              "earlier summary kept");
  check_int (count_files (), 3, "no temporary left");
  check_int (count_in (base), 1, "no temporary left beside");
  free (sum);
done:
  lac_free (u), lac_free (sig), lac_free (vm);
}

/* A pid that is not running (for temporaries a killed run left). */
static long
dead_pid (void)
{
  for (long pid = 4000000; pid > 1000; pid--)
    if (kill ((pid_t) pid, 0) != 0)
      return pid;
  return 0;
}

static void
test_batches (void)
{
  static volatile sig_atomic_t stop;
  const char *key[] = { "run" }, *v2[] = { "2" };
  char path[160], *sum;
  long pid = dead_pid ();
  lac_output_batch *b;

  /* A new run: its files replace the earlier run's, all of them; a file
   * a run never writes stays. */
  put (dir, "notes.txt", "mine\n");
  put (dir, "step_003.vtu", "old step\n");
  b = lac_output_batch_alloc (dir, NULL);
  if (b)
    {
      lac_output_summary (lac_output_batch_add (b, "summary.txt"), 1, key,
                          v2);
      check_status (lac_output_commit (b), LAC_SUCCESS, "second run");
      lac_output_batch_free (b);
    }
  sum = slurp ("summary.txt");
  check_true (sum && strcmp (sum, "run = 2\n") == 0, "the new summary");
  free (sum);
  check_int (count_files (), 2, "summary.txt and notes.txt, nothing of the "
             "earlier run");
  check_true ((sum = slurp ("notes.txt")) != NULL, "notes.txt kept");
  free (sum);
  check_int (count_in (base), 1, "no temporary beside");

  /* Interrupted: nothing can be added or committed, nothing changes. */
  b = lac_output_batch_alloc (dir, &stop);
  if (b)
    {
      check_true (lac_output_batch_add (b, "summary.txt") != NULL, "before");
      stop = SIGINT;
      check_true (lac_output_batch_add (b, "nodes.csv") == NULL, "stopped");
      check_message ("interrupted by signal 2", "stopped");
      check_status (lac_output_commit (b), LAC_EIO, "no commit");
      lac_output_batch_free (b);
      stop = 0;
    }
  check_int (count_files (), 2, "interrupted: the earlier files");
  check_int (count_in (base), 1, "interrupted: no temporary");

  /* What a killed run left: its new directory (killed after the exchange:
   * it holds the earlier files, a picture of the user's too), its old
   * directory (with a picture of the user's), a file of the former scheme
   * in DIR. */
  snprintf (path, sizeof path, "%s/.sub.lac-new-%ld", base, pid);
  mkdir (path, 0777);
  put (path, "solution.vtu", "half\n");
  put (path, "ex.png", "earlier picture\n");
  snprintf (path, sizeof path, "%s/.sub.lac-old-%ld", base, pid);
  mkdir (path, 0777);
  put (path, "u.png", "picture\n");
  put (path, "summary.txt", "run = 0\n");
  snprintf (path, sizeof path, ".solution.vtu.tmp%ld", pid);
  put (dir, path, "former\n");
  b = lac_output_batch_alloc (dir, NULL);
  lac_output_batch_free (b);
  check_int (count_in (base), 1, "stale temporaries removed");
  check_int (count_files (), 4, "summary.txt, notes.txt, u.png, ex.png");
  sum = slurp ("summary.txt");
  check_true (sum && strcmp (sum, "run = 2\n") == 0, "summary kept");
  free (sum);
  check_true ((sum = slurp ("u.png")) != NULL, "the user's picture back");
  free (sum);
  check_true ((sum = slurp ("ex.png")) != NULL, "from new: picture back");
  free (sum);

  /* DIR lost between the two renames of a killed run: put back. */
  snprintf (path, sizeof path, "%s/.sub.lac-old-%ld", base, pid);
  check_int (rename (dir, path), 0, "lose DIR");
  b = lac_output_batch_alloc (dir, NULL);
  lac_output_batch_free (b);
  check_int (count_files (), 4, "DIR put back");
  check_int (count_in (base), 1, "nothing else beside");
}

/* What is not a writable directory is refused before anything is
 * written, with the path and the reason; a link to a directory stands for
 * it; the new directory keeps the earlier one's permission bits. */
static void
test_refusals (void)
{
  char file[96], link[96], sub[128], real[96];
  const char *key[] = { "run" }, *v3[] = { "3" };
  struct stat st;
  lac_output_batch *b;
  snprintf (file, sizeof file, "%s/afile", base);
  snprintf (link, sizeof link, "%s/link", base);
  snprintf (real, sizeof real, "%s/real", base);
  put (base, "afile", "x\n");
  check_true (lac_output_batch_alloc (file, NULL) == NULL, "a file");
  check_message ("afile' exists and is a regular file, not a directory",
                 "a file");
  check_int (lac_output_batch_check (file), LAC_EIO, "check: a file");
  snprintf (sub, sizeof sub, "%s/x", file);
  check_int (lac_output_batch_check (sub), LAC_EIO, "check: under a file");
  check_message ("afile' is not a directory", "under a file");
  check_int (symlink ("afile", link), 0, "link to a file");
  check_true (lac_output_batch_alloc (link, NULL) == NULL, "link to a file");
  check_message ("is a symbolic link to 'afile', which is a regular file",
                 "link to a file");
  unlink (link);

  mkdir (real, 0750);
  check_int (symlink ("real", link), 0, "link to a directory");
  if ((b = lac_output_batch_alloc (link, NULL)))
    {
      lac_output_summary (lac_output_batch_add (b, "summary.txt"), 1, key,
                          v3);
      check_status (lac_output_commit (b), LAC_SUCCESS, "through a link");
      lac_output_batch_free (b);
    }
  check_int (lstat (link, &st) == 0 && S_ISLNK (st.st_mode), 1,
             "the link stays a link");
  check_int (stat (real, &st) == 0 ? (int) (st.st_mode & 0777) : -1, 0750,
             "the directory keeps its permissions");
  check_int (count_in (real), 1, "the files in the linked directory");
  snprintf (sub, sizeof sub, "%s/summary.txt", real);
  unlink (sub);
  rmdir (real);
  unlink (link);
  unlink (file);
}

static void
cleanup (void)
{
  const char *names[] = { "solution.vtu", "nodes.csv", "summary.txt",
                          "notes.txt", "u.png", "ex.png" };
  char path[128];
  for (int k = 0; k < 6; k++)
    {
      snprintf (path, sizeof path, "%s/%s", dir, names[k]);
      unlink (path);
    }
  snprintf (path, sizeof path, "%s/sub", dir);
  rmdir (path);
  rmdir (dir);
}

int
main (void)
{
  lac_mesh *m = NULL;
  size_t n[2] = { 2, 1 };
  double L[2] = { 2, 1 };
  snprintf (base, sizeof base, "/tmp/lac-t702-XXXXXX");
  if (!mkdtemp (base))
    {
      check_true (0, "mkdtemp");
      return check_summary ();
    }
  snprintf (dir, sizeof dir, "%s/sub", base);    /* created by the batch */
  check_status (lac_mesh_box (LAC_QUAD8, n, L, 0, &m), LAC_SUCCESS, "box");
  if (m)
    test_files (m);
  test_batches ();
  test_refusals ();
  lac_mesh_free (m);
  cleanup ();
  rmdir (base);

  /* A directory that cannot be made: a message, no crash. */
  check_true (lac_output_batch_alloc ("/proc/lac-t702/x", NULL) == NULL,
              "uncreatable directory");
  check_message ("cannot create directory", "message");
  return check_summary ();
}
