/* t702: output files -- VTU and CSV contents, batches that appear together
 *
 * A 2 x 1 box of quad8 cells (lac_mesh_box) with a linear displacement is
 * written to a temporary directory; the files appear only on commit, a
 * batch freed without commit leaves the earlier files and no temporaries.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "base/lac_mem.h"
#include "io/lac_output.h"
#include "base/lac_status.h"

static char dir[64];

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

static int
count_files (void)
{
  DIR *d = opendir (dir);
  struct dirent *e;
  int n = 0;
  while (d && (e = readdir (d)) != NULL)
    n += e->d_name[0] != '.' || (strcmp (e->d_name, ".")
                                 && strcmp (e->d_name, ".."));
  if (d)
    closedir (d);
  return n;
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
  lac_output_fields f = { m, LAC_PLANE_STRAIN, u, NULL, sig, vm };
  lac_output_batch *b = lac_output_batch_alloc (dir);
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
  check_int (count_files (), 3, "three temporaries before commit");
  check_true (!(vtu = slurp ("solution.vtu")), "no solution.vtu yet");
  free (vtu);
  check_status (lac_output_commit (b), LAC_SUCCESS, "commit");
  lac_output_batch_free (b);
  check_int (count_files (), 3, "three files after commit");

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
  b = lac_output_batch_alloc (dir);
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
  free (sum);
done:
  lac_free (u), lac_free (sig), lac_free (vm);
}

static void
cleanup (void)
{
  const char *names[] = { "solution.vtu", "nodes.csv", "summary.txt" };
  char path[128];
  for (int k = 0; k < 3; k++)
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
  char base[] = "/tmp/lac-t702-XXXXXX";
  if (!mkdtemp (base))
    {
      check_true (0, "mkdtemp");
      return check_summary ();
    }
  snprintf (dir, sizeof dir, "%s/sub", base);    /* created by the batch */
  check_status (lac_mesh_box (LAC_QUAD8, n, L, 0, &m), LAC_SUCCESS, "box");
  if (m)
    test_files (m);
  lac_mesh_free (m);
  cleanup ();
  rmdir (base);

  /* A directory that cannot be made: a message, no crash. */
  check_true (lac_output_batch_alloc ("/proc/lac-t702/x") == NULL,
              "uncreatable directory");
  check_message ("cannot create directory", "message");
  return check_summary ();
}
