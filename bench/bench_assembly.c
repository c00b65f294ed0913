/* bench_assembly.c -- assembling K_T: a triplet list, or a kept pattern
 *
 * The large-deformation loop (solve/lac_nonlinear.h) assembles the tangent
 * K_T of the hyperelastic bodies (fem/lac_hyper.h) at every Newton
 * iteration, always with the same pattern.  Two routes on hex8 cubes up to
 * 1M dofs and hex20 cubes (the fine ring has 209k hex20 dofs):
 *   triplets  every entry of every cell block into a triplet list (16
 *             bytes each), then compressed and sorted (lac_csc_from_triplet):
 *             what each iteration cost before;
 *   pattern   the pattern built once from the mesh (fem/lac_pattern.h: node
 *             neighbours, no global list, no global sort) with the scatter
 *             map of every cell block, then each assembly writes straight
 *             into the CSC values.
 * For each: wall time, and the peak resident memory of the child process
 * that does it (VmHWM, reset after the mesh is built, so the mesh is in it
 * but not its construction); the pattern route gives the time of its
 * construction and of one assembly (the cost of every later iteration).
 * The two K agree (the largest difference relative to the largest entry
 * is printed).  u is a small pseudo-random displacement (|u| <= 1e-3 of
 * the cell size), E = 210e3, nu = 0.3, neo-Hookean.
 *
 * Run by `make bench` (not in CI).  Options:
 *   --quick            small sizes only (a few seconds)
 *   --max-dofs N       skip larger sizes
 * Each measurement runs in a forked child (its own peak memory); the table
 * (markdown) goes to stdout, a progress line per run to stderr.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "base/lac_status.h"
#include "fem/lac_hyper.h"
#include "fem/lac_mesh.h"
#include "fem/lac_pattern.h"

typedef struct result
{
  int status;
  size_t ndof, nnz;
  double t_build, t_asm, t_asm2;  /* s: pattern/list, first, second assembly */
  double mb_peak, mb_K;
  double sum, maxabs;             /* checksum and largest |entry| of K      */
  char msg[200];
} result;

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

static double
proc_mb (const char *key)
{
  char line[256];
  size_t nk = strlen (key);
  double kb = -1;
  FILE *f = fopen ("/proc/self/status", "r");
  if (!f)
    return -1;
  while (fgets (line, sizeof line, f))
    if (!strncmp (line, key, nk) && sscanf (line + nk, "%lf", &kb) == 1)
      break;
  fclose (f);
  return kb / 1024;
}

static void
proc_write (const char *path, const char *what)
{
  FILE *f = fopen (path, "w");
  if (f)
    {
      fputs (what, f);
      fclose (f);
    }
}

static void
checksum (const lac_csc *K, result *r)
{
  r->nnz = (size_t) K->p[K->ncol];
  r->mb_K = (double) r->nnz * 12.0 / 1048576.0;
  for (size_t q = 0; q < r->nnz; q++)
    {
      r->sum += K->x[q] * (double) (1 + q % 7);
      r->maxabs = fmax (r->maxabs, fabs (K->x[q]));
    }
}

/* In the child: mesh, material, u, then one route. */
static void
child (lac_elem_type type, size_t n, int route, result *r)
{
  size_t nc[3] = { n, n, n };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  if ((r->status = lac_mesh_box (type, nc, L, 0.0, &m)))
    {
      snprintf (r->msg, sizeof r->msg, "%s", lac_error_message ());
      return;
    }
  r->ndof = 3 * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells
                                                            * sizeof *nu);
  double *u = malloc (r->ndof * sizeof *u);
  unsigned s = 7;
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = 210e3, nu[c] = 0.3;
  for (size_t j = 0; j < r->ndof; j++)
    {
      s = s * 1103515245u + 12345u;
      u[j] = 1e-3 / (double) n * (((s >> 8) & 0xffff) / 32767.5 - 1.0);
    }
  lac_hyper h = { LAC_SOLID3D, E, nu, NULL, 0 };
  proc_write ("/proc/self/clear_refs", "5");           /* VmHWM = VmRSS */
  double t0 = now ();
  if (route == 0)
    {
      lac_triplet *T = lac_triplet_alloc (r->ndof, r->ndof, 0);
      r->status = lac_hyper_assemble (m, &h, u, NULL, T);
      r->t_build = now () - t0;
      lac_csc *K = r->status ? NULL : lac_csc_from_triplet (T);
      lac_triplet_free (T);
      r->t_asm = now () - t0;
      if (K)
        checksum (K, r);
      else if (!r->status)
        r->status = LAC_ENOMEM;
      lac_csc_free (K);
    }
  else
    {
      lac_pattern *P = lac_pattern_build (m, NULL);
      if (P && lac_pattern_slabs (P, m, 16))
        {
          lac_pattern_free (P);
          P = NULL;
        }
      r->t_build = now () - t0;
      r->status = P ? lac_hyper_assemble_pattern (m, &h, u, NULL, P)
                    : LAC_ENOMEM;
      r->t_asm = now () - t0 - r->t_build;
      double t1 = now ();
      if (!r->status)
        r->status = lac_hyper_assemble_pattern (m, &h, u, NULL, P);
      r->t_asm2 = now () - t1;
      if (!r->status)
        checksum (P->K, r);
      lac_pattern_free (P);
    }
  r->mb_peak = proc_mb ("VmHWM:");
  if (r->status)
    snprintf (r->msg, sizeof r->msg, "%s", lac_error_message ());
  free (E), free (nu), free (u);
  lac_mesh_free (m);
}

static void
run (lac_elem_type type, size_t n, int route, result *r)
{
  int fd[2], wst;
  memset (r, 0, sizeof *r);
  fflush (NULL);
  pid_t pid;
  if (pipe (fd) != 0 || (pid = fork ()) < 0)
    {
      r->status = LAC_EIO;
      snprintf (r->msg, sizeof r->msg, "pipe/fork: %s", strerror (errno));
      return;
    }
  if (pid == 0)
    {
      close (fd[0]);
      proc_write ("/proc/self/oom_score_adj", "1000");
      lac_init ();
      child (type, n, route, r);
      ssize_t k = write (fd[1], r, sizeof *r);
      _exit (k == (ssize_t) sizeof *r ? 0 : 1);
    }
  close (fd[1]);
  if (read (fd[0], r, sizeof *r) != (ssize_t) sizeof *r)
    {
      r->status = LAC_EDEP;
      snprintf (r->msg, sizeof r->msg, "child died (out of memory?)");
    }
  close (fd[0]);
  waitpid (pid, &wst, 0);
}

int
main (int argc, char **argv)
{
  int quick = 0;
  size_t maxdofs = (size_t) -1;
  for (int k = 1; k < argc; k++)
    if (!strcmp (argv[k], "--quick"))
      quick = 1;
    else if (!strcmp (argv[k], "--max-dofs") && k + 1 < argc)
      maxdofs = (size_t) atol (argv[++k]);
  static const struct { lac_elem_type type; size_t n; int quick; } sizes[] = {
    { LAC_HEX8, 20, 1 }, { LAC_HEX8, 40, 0 }, { LAC_HEX8, 60, 0 },
    { LAC_HEX8, 69, 0 }, { LAC_HEX20, 8, 1 }, { LAC_HEX20, 26, 0 },
  };
  printf ("| cells | dofs | nnz(K) | K MB | triplets: s | peak MB | pattern: "
          "build s | first s | next s | peak MB | K differs by |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++)
    {
      size_t n = sizes[k].n;
      size_t dofs = sizes[k].type == LAC_HEX8 ? 3 * (n + 1) * (n + 1) * (n + 1)
                    : 3 * ((n + 1) * (n + 1) * (n + 1)
                           + 3 * n * (n + 1) * (n + 1));
      if ((quick && !sizes[k].quick) || dofs > maxdofs)
        continue;
      const char *name = lac_refelem_get (sizes[k].type)->name;
      result a, b;
      fprintf (stderr, "bench_assembly: %s %zu^3, %zu dofs\n", name, n, dofs);
      run (sizes[k].type, n, 0, &a);
      run (sizes[k].type, n, 1, &b);
      if (a.status || b.status)
        {
          printf ("| %s %zu^3 | %zu | failed: %s %s |\n", name, n, dofs, a.msg,
                  b.msg);
          continue;
        }
      double diff = fabs (a.sum - b.sum) / (a.maxabs * (double) a.nnz * 4);
      printf ("| %s %zu^3 | %zu | %zu | %.0f | %.2f | %.0f | %.2f | %.2f | "
              "%.2f | %.0f | %.1e |\n", name, n, a.ndof, a.nnz, a.mb_K,
              a.t_asm, a.mb_peak, b.t_build, b.t_asm, b.t_asm2, b.mb_peak,
              diff);
    }
  printf ("\nPeak MB: VmHWM of the child after the mesh is built (the mesh "
          "is counted, not its construction).  K differs by: |sum of "
          "weighted entries| difference / (nnz max|K|).\n\n");
  return 0;
}
