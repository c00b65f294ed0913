/* bench_elasticity.c -- sizes, times and memory of the elasticity solve
 *
 * A block of steel (E = 210e3, nu = 0.3), clamped on zmin, pressed on zmax
 * (p = 1), meshed by lac_mesh_box with cubic cells:
 *   1. dense / sparse crossover: dense (GSL LU), UMFPACK and CHOLMOD on
 *      small hex8 cubes; where does dense become slower?
 *   2. hex8 cubes of increasing size, to about 1,000,000 dofs, and a
 *      slender hex8 column at 1,000,000 dofs (same element, banded fill);
 *   3. tet10 cubes of increasing size, to a few hundred thousand dofs.
 * For every size and solver: assembly time (triplets, CSC, Dirichlet),
 * factorization time (including lac_solver's symmetry check and condition
 * estimate) and solve time, nnz and flop rate of the factorization, peak
 * resident memory of the assembly and of the solve, relative residual, and
 * the largest relative difference between the back ends' solutions.
 *
 * Each (size, solver) runs in a forked child, so that the peak memory
 * (VmHWM of /proc/self/status) is its own; between assembly and solve the
 * peak is reset by writing 5 to /proc/self/clear_refs (Linux >= 4.0), so
 * the "solve" peak is that of the factorization with K resident.  The child
 * sends its numbers and its solution back through a pipe, and asks the
 * kernel to be the first one killed if memory runs out (oom_score_adj).
 * From ESTIMATE_FROM_DOFS on, a symbolic analysis predicts the factor's
 * memory first, and the factorization is skipped (with the prediction
 * printed) if it would not fit.  Times are CLOCK_MONOTONIC wall-clock
 * seconds; OpenBLAS may use several threads.
 *
 * Run by `make bench` (not in CI).  Options:
 *   --quick                      small sizes only (about 15 s)
 *   --part N                     run only part 1, 2 or 3
 *   --min-dofs N, --max-dofs N   skip sizes outside [N, M] dofs (parts 2, 3)
 *   --solver cholmod|umfpack     one sparse back end only (parts 2, 3)
 *   --mem-fraction F             factorize if the predicted factor takes
 *                                at most F x MemAvailable (default 0.85)
 * A progress line per run goes to stderr; the tables (markdown) to stdout.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "fem/lac_mesh.h"
#include "base/lac_status.h"

/* UMFPACK is not run on 3D cubes above this many dofs, for time: its LU of
 * a 3D stiffness has 3-3.5 times the entries of CHOLMOD's factor and
 * takes 2-9 times longer (measured here: about a minute and 5.7 GB at 108k
 * hex8 dofs, minutes at 200k).  The slender column has no such cap. */
#define UMFPACK_MAX_DOFS 110000
/* Dense is not run above this many dofs (GSL LU with the reference CBLAS
 * of libgslcblas is O(n^3): seconds at 2000 dofs). */
#define DENSE_MAX_DOFS 2500
/* From this size on, lac_solver_estimate first predicts the factor's
 * memory; the factorization is skipped, with the prediction printed, if it
 * exceeds 85% of MemAvailable (--mem-fraction F changes the 85%). */
#ifndef ESTIMATE_FROM_DOFS
#define ESTIMATE_FROM_DOFS 200000
#endif
#define SKIPPED (-100)

typedef struct result
{
  int status;
  size_t ndof, nnzK;
  double t_asm, t_factor, t_solve;
  double mb_asm, mb_solve;      /* peak resident MB of the two phases    */
  double nnz_factor, flops, resid;
  char method[64], msg[240];
} result;

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* The number after `key` in a /proc file, in MB (the files give kB). */
static double
proc_mb (const char *path, const char *key)
{
  char line[256];
  size_t nk = strlen (key);
  double kb = -1;
  FILE *f = fopen (path, "r");
  if (!f)
    return -1;
  while (fgets (line, sizeof line, f))
    if (!strncmp (line, key, nk) && sscanf (line + nk, "%lf", &kb) == 1)
      break;
  fclose (f);
  return kb / 1024;
}

/* Write a string to a /proc file of this process (best effort). */
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

/* ---- the problem -------------------------------------------------------- */

typedef struct problem
{
  lac_mesh *m;
  lac_csc *K;
  double *F;
  size_t ndof;
} problem;

static void
problem_free (problem *P)
{
  lac_mesh_free (P->m);
  lac_csc_free (P->K);
  free (P->F);
}

/* Mesh n[0] x n[1] x n[2] cubic cells, assemble K and F, clamp zmin. */
static int
problem_build (lac_elem_type type, const size_t *n, problem *P)
{
  const double L[3] = { 1, (double) n[1] / (double) n[0],
                        (double) n[2] / (double) n[0] };
  lac_triplet *T = NULL;
  lac_dirichlet *d = NULL;
  double *E = NULL, *nu = NULL;
  int status;
  memset (P, 0, sizeof *P);
  status = lac_mesh_box (type, n, L, 0.0, &P->m);
  if (!status)
    {
      size_t nc = P->m->ncells, nen = P->m->ptr[1] - P->m->ptr[0];
      P->ndof = 3 * P->m->nnodes;
      E = malloc (nc * sizeof *E);
      nu = malloc (nc * sizeof *nu);
      for (size_t c = 0; E && nu && c < nc; c++)
        {
          E[c] = 210e3;
          nu[c] = 0.3;
        }
      T = lac_triplet_alloc (P->ndof, P->ndof, nc * 9 * nen * nen);
      P->F = calloc (P->ndof, sizeof *P->F);
      d = lac_dirichlet_alloc ();
      status = E && nu && T && P->F && d ? LAC_SUCCESS : LAC_ENOMEM;
    }
  if (!status)
    {
      lac_elastic mat = { LAC_SOLID3D, E, nu };
      status = lac_assembly_stiffness (P->m, &mat, T);     /* K = sum Ke */
    }
  if (!status)
    status = lac_assembly_pressure (P->m, LAC_SOLID3D,
                                    lac_mesh_group (P->m, "zmax"), 1.0, P->F);
  for (int comp = 0; comp < 3 && !status; comp++)
    status = lac_dirichlet_add_group (d, P->m, lac_mesh_group (P->m, "zmin"),
                                      comp, 0.0);
  if (!status && !(P->K = lac_csc_from_triplet (T)))
    status = LAC_ENOMEM;
  lac_triplet_free (T);
  if (!status)
    status = lac_dirichlet_apply (d, P->K, P->F);
  lac_dirichlet_free (d);
  free (E);
  free (nu);
  return status;
}

/* ||F - K u||_inf / ||F||_inf */
static double
residual (const lac_csc *K, const double *u, const double *F)
{
  size_t n = K->nrow;
  double *r = malloc (n * sizeof *r), num = 0, den = 0;
  if (!r)
    return NAN;
  lac_csc_matvec (K, u, r);
  for (size_t i = 0; i < n; i++)
    {
      num = fmax (num, fabs (F[i] - r[i]));
      den = fmax (den, fabs (F[i]));
    }
  free (r);
  return num / den;
}

/* Fraction of MemAvailable the predicted factor may take (--mem-fraction). */
static double mem_fraction = 0.85;

/* Predict the factor's memory; SKIPPED (message in r) if it will not fit. */
static int
check_fits (lac_solver_kind kind, const lac_csc *K, result *r)
{
  lac_solver_info info;
  double avail = proc_mb ("/proc/meminfo", "MemAvailable:"), need;
  int status = lac_solver_estimate (kind, K, &info);
  if (status)
    return status;
  need = info.peak_bytes / 1048576.0;
  r->nnz_factor = info.nnz_factor;
  r->flops = info.flops;
  if (avail > 0 && need > mem_fraction * avail)
    {
      snprintf (r->msg, sizeof r->msg, "skipped: the %s analysis predicts "
                "%.1f GB for the factor (nnz %.3g, %.3g flop), %.1f GB are "
                "available", lac_solver_kind_name (kind), need / 1024,
                info.nnz_factor, info.flops, avail / 1024);
      return SKIPPED;
    }
  return LAC_SUCCESS;
}

/* The child: build, factor, solve; fill r and u (allocated here). */
static void
run_child (lac_elem_type type, const size_t *ncell, lac_solver_kind kind,
           int reps, result *r, double **u)
{
  problem P;
  lac_solver *S = NULL;
  lac_solver_info info;
  double t0 = now ();
  *u = NULL;
  r->status = problem_build (type, ncell, &P);
  r->t_asm = now () - t0;
  r->ndof = P.ndof;
  r->mb_asm = proc_mb ("/proc/self/status", "VmHWM:");
  if (r->status)
    goto done;
  r->nnzK = (size_t) P.K->p[P.ndof];
  if (P.ndof >= ESTIMATE_FROM_DOFS
      && (r->status = check_fits (kind, P.K, r)))
    goto done;
  proc_write ("/proc/self/clear_refs", "5");        /* VmHWM = VmRSS */
  *u = malloc (P.ndof * sizeof **u);
  S = lac_solver_alloc (kind);
  if (!*u || !S)
    {
      r->status = LAC_ENOMEM;
      goto done;
    }
  /* Small problems are repeated so that the times are not clock noise. */
  t0 = now ();
  for (int k = 0; k < reps && !r->status; k++)
    r->status = lac_solver_factor (S, P.K);
  r->t_factor = (now () - t0) / reps;
  t0 = now ();
  for (int k = 0; k < reps && !r->status; k++)
    r->status = lac_solver_solve (S, P.F, *u);
  r->t_solve = (now () - t0) / reps;
  if (r->status)
    goto done;
  r->mb_solve = proc_mb ("/proc/self/status", "VmHWM:");
  lac_solver_get_info (S, &info);
  r->nnz_factor = info.nnz_factor;
  r->flops = info.flops;
  snprintf (r->method, sizeof r->method, "%s%s%s", info.method,
            info.ordering[0] ? ", " : "", info.ordering);
  r->resid = residual (P.K, *u, P.F);
done:
  if (r->status && !r->msg[0])
    snprintf (r->msg, sizeof r->msg, "%s", lac_error_message ());
  lac_solver_free (S);
  problem_free (&P);
}

static int
write_all (int fd, const void *buf, size_t n)
{
  const char *p = buf;
  while (n > 0)
    {
      ssize_t k = write (fd, p, n);
      if (k < 0 && errno == EINTR)
        continue;
      if (k <= 0)
        return -1;
      p += k;
      n -= (size_t) k;
    }
  return 0;
}

static int
read_all (int fd, void *buf, size_t n)
{
  char *p = buf;
  while (n > 0)
    {
      ssize_t k = read (fd, p, n);
      if (k < 0 && errno == EINTR)
        continue;
      if (k <= 0)
        return -1;
      p += k;
      n -= (size_t) k;
    }
  return 0;
}

/* Fork, run, collect.  *u (malloc'ed, ndof) receives the solution. */
static void
run (lac_elem_type type, const size_t *ncell, lac_solver_kind kind, int reps,
     result *r, double **u)
{
  int fd[2], wst = 0;
  pid_t pid;
  memset (r, 0, sizeof *r);
  *u = NULL;
  fflush (NULL);
  if (pipe (fd) != 0 || (pid = fork ()) < 0)
    {
      r->status = LAC_EIO;
      snprintf (r->msg, sizeof r->msg, "pipe/fork: %s", strerror (errno));
      return;
    }
  if (pid == 0)
    {
      double *x;
      close (fd[0]);
      proc_write ("/proc/self/oom_score_adj", "1000");  /* killed first */
      lac_init ();
      run_child (type, ncell, kind, reps, r, &x);
      if (write_all (fd[1], r, sizeof *r) == 0 && !r->status)
        write_all (fd[1], x, r->ndof * sizeof *x);
      _exit (0);
    }
  close (fd[1]);
  if (read_all (fd[0], r, sizeof *r) != 0)
    {
      r->status = LAC_EDEP;
      snprintf (r->msg, sizeof r->msg, "child died (killed when memory ran "
                "out?)");
    }
  else if (!r->status)
    {
      *u = malloc (r->ndof * sizeof **u);
      if (!*u || read_all (fd[0], *u, r->ndof * sizeof **u) != 0)
        {
          free (*u);
          *u = NULL;
          r->status = LAC_EDEP;
          snprintf (r->msg, sizeof r->msg, "solution lost in the pipe");
        }
    }
  close (fd[0]);
  waitpid (pid, &wst, 0);
  if (WIFSIGNALED (wst))
    snprintf (r->msg + strlen (r->msg), sizeof r->msg - strlen (r->msg),
              " (signal %d)", WTERMSIG (wst));
}

static double
reldiff (size_t n, const double *x, const double *y)
{
  double num = 0, den = 0;
  if (!x || !y)
    return NAN;
  for (size_t i = 0; i < n; i++)
    {
      num = fmax (num, fabs (x[i] - y[i]));
      den = fmax (den, fabs (y[i]));
    }
  return num / den;
}

static const char *
type_name (lac_elem_type t)
{
  return t == LAC_HEX8 ? "hex8" : "tet10";
}

static size_t
ndofs (lac_elem_type type, const size_t *n)
{
  size_t d = type == LAC_HEX8 ? 1 : 2;
  return 3 * (d * n[0] + 1) * (d * n[1] + 1) * (d * n[2] + 1);
}

/* ---- part 1: dense / sparse crossover ---------------------------------- */

static void
crossover (size_t max_dofs, int quick)
{
  size_t found = 0;
  printf ("\n## 1. dense / sparse crossover, hex8 cube (ms per factor+solve;"
          " factor includes the condition estimate)\n\n");
  printf ("| cells | dofs | dense | umfpack | cholmod | fastest | "
          "max rel diff |\n|---|---:|---:|---:|---:|---|---:|\n");
  for (size_t c = 1; c <= 12; c++)
    {
      const size_t n3[3] = { c, c, c };
      size_t nd = ndofs (LAC_HEX8, n3);
      result r[3];
      double *u[3], t[3], diff = 0;
      int best = -1;
      if (nd > max_dofs || nd > DENSE_MAX_DOFS || (quick && nd > 700))
        break;
      for (int k = 0; k < 3; k++)
        {
          int reps = nd < 200 ? 200 : nd < 1000 ? 10 : 1;
          fprintf (stderr, "[crossover] hex8 %zu^3 (%zu dofs) %s x%d\n", c,
                   nd, lac_solver_kind_name (k), reps);
          run (LAC_HEX8, n3, (lac_solver_kind) k, reps, &r[k], &u[k]);
          t[k] = r[k].status ? NAN : 1e3 * (r[k].t_factor + r[k].t_solve);
          if (!r[k].status && (best < 0 || t[k] < t[best]))
            best = k;
          if (r[k].status)
            fprintf (stderr, "  failed: %s\n", r[k].msg);
        }
      for (int k = 1; k < 3; k++)
        diff = fmax (diff, reldiff (nd, u[k], u[0]));
      printf ("| %zu^3 | %zu | %.3g | %.3g | %.3g | %s | %.1e |\n", c, nd,
              t[0], t[1], t[2], best < 0 ? "-" : lac_solver_kind_name (best),
              diff);
      if (!found && best > 0)
        found = nd;
      for (int k = 0; k < 3; k++)
        free (u[k]);
    }
  if (found)
    printf ("\nDense (GSL LU, gslcblas) is no longer the fastest from %zu "
            "dofs on.\n", found);
  else
    printf ("\nDense stayed the fastest over the sizes run.\n");
}

/* ---- parts 2 and 3: sparse scaling ------------------------------------ */

static size_t min_dofs;           /* --min-dofs: skip smaller sizes     */
static int only_kind = -1;        /* --solver: run only this back end   */

/* Run CHOLMOD, then UMFPACK (up to umf_max dofs) on each size. */
static void
scaling (lac_elem_type type, const size_t (*ncell)[3], size_t nsizes,
         size_t max_dofs, size_t umf_max)
{
  printf ("\n| cells | dofs | nnz(K) | assembly s | asm peak MB | solver | "
          "factor s | solve s | nnz(factor) | Gflop/s | solve peak MB | "
          "residual | rel diff |\n|---|---:|---:|---:|---:|---|---:|---:|"
          "---:|---:|---:|---:|---:|\n");
  for (size_t s = 0; s < nsizes; s++)
    {
      size_t nd = ndofs (type, ncell[s]);
      char cells[64];
      result r[2];
      double *u[2] = { NULL, NULL };
      if (nd > max_dofs)
        break;
      if (nd < min_dofs)
        continue;
      snprintf (cells, sizeof cells, "%zux%zux%zu", ncell[s][0], ncell[s][1],
                ncell[s][2]);
      for (int k = 0; k < 2; k++)
        {
          lac_solver_kind kind = k == 0 ? LAC_SOLVER_CHOLMOD
                                        : LAC_SOLVER_UMFPACK;
          const char *name = lac_solver_kind_name (kind);
          double t0 = now ();
          if (only_kind >= 0 && (int) kind != only_kind)
            continue;
          if (kind == LAC_SOLVER_UMFPACK && nd > umf_max)
            {
              printf ("| %s | %zu | | | | umfpack | skipped: above %zu dofs "
                      "(time; see UMFPACK_MAX_DOFS) | | | | | | |\n", cells,
                      nd, umf_max);
              continue;
            }
          fprintf (stderr, "[%s] %s cells, %zu dofs, %s ...\n",
                   type_name (type), cells, nd, name);
          run (type, ncell[s], kind, 1, &r[k], &u[k]);
          fprintf (stderr, "  %.1f s wall%s%s\n", now () - t0,
                   r[k].status ? ": " : "", r[k].msg);
          if (r[k].status)
            printf ("| %s | %zu | %zu | %.2f | %.0f | %s | %s | | %.3g | | | "
                    "| |\n", cells, nd, r[k].nnzK, r[k].t_asm, r[k].mb_asm,
                    name, r[k].msg, r[k].nnz_factor);
          else
            printf ("| %s | %zu | %zu | %.2f | %.0f | %s | %.2f | %.3f | "
                    "%.3g | %.1f | %.0f | %.1e | %s |\n", cells, r[k].ndof,
                    r[k].nnzK, r[k].t_asm, r[k].mb_asm, name, r[k].t_factor,
                    r[k].t_solve, r[k].nnz_factor,
                    1e-9 * r[k].flops / r[k].t_factor, r[k].mb_solve,
                    r[k].resid, k == 0 ? "ref" : "");
          if (k == 1 && u[0] && u[1])
            printf ("| | | | | | umfpack vs cholmod | | | | | | | %.1e |\n",
                    reldiff (nd, u[1], u[0]));
          fflush (stdout);
        }
      free (u[0]);
      free (u[1]);
    }
}

int
main (int argc, char **argv)
{
  /* cells: hex8 dofs 3(n0+1)(n1+1)(n2+1), tet10 dofs 3(2n0+1)(2n1+1)(2n2+1) */
  static const size_t hex[][3] = { { 8, 8, 8 }, { 12, 12, 12 },
    { 16, 16, 16 }, { 20, 20, 20 }, { 26, 26, 26 }, { 32, 32, 32 },
    { 40, 40, 40 }, { 50, 50, 50 }, { 60, 60, 60 }, { 69, 69, 69 } };
  static const size_t beam[][3] = { { 10, 10, 700 }, { 10, 10, 2800 } };
  static const size_t tet[][3] = { { 4, 4, 4 }, { 6, 6, 6 }, { 8, 8, 8 },
    { 10, 10, 10 }, { 13, 13, 13 }, { 16, 16, 16 }, { 20, 20, 20 },
    { 24, 24, 24 } };
  size_t max_dofs = (size_t) -1;
  int part = 0, quick = 0;
  for (int a = 1; a < argc; a++)
    if (!strcmp (argv[a], "--quick"))
      quick = 1;
    else if (!strcmp (argv[a], "--part") && a + 1 < argc)
      part = atoi (argv[++a]);
    else if (!strcmp (argv[a], "--max-dofs") && a + 1 < argc)
      max_dofs = (size_t) atof (argv[++a]);
    else if (!strcmp (argv[a], "--min-dofs") && a + 1 < argc)
      min_dofs = (size_t) atof (argv[++a]);
    else if (!strcmp (argv[a], "--mem-fraction") && a + 1 < argc)
      mem_fraction = atof (argv[++a]);
    else if (!strcmp (argv[a], "--solver") && a + 1 < argc
             && lac_solver_kind_from_name (argv[a + 1]) > 0)
      only_kind = lac_solver_kind_from_name (argv[++a]);
    else
      {
        fprintf (stderr, "usage: %s [--quick] [--part 1|2|3] [--min-dofs N]"
                 " [--max-dofs N] [--solver cholmod|umfpack]"
                 " [--mem-fraction F]\n", argv[0]);
        return 2;
      }
  if (quick && max_dofs > 30000)
    max_dofs = 30000;
  lac_init ();
  printf ("# Elasticity benchmark: E = 210e3, nu = 0.3, clamped on zmin, "
          "pressure on zmax\n\n");
  printf ("OPENBLAS_NUM_THREADS=%s, %ld online CPUs, %.1f GB available.  "
          "Peak MB = VmHWM of the child process (assembly: from its start; "
          "solve: reset after the assembly, K stays resident).\n",
          getenv ("OPENBLAS_NUM_THREADS") ? getenv ("OPENBLAS_NUM_THREADS")
          : "(unset)", sysconf (_SC_NPROCESSORS_ONLN),
          proc_mb ("/proc/meminfo", "MemAvailable:") / 1024);
  if (!part || part == 1)
    crossover (max_dofs, quick);
  if (!part || part == 2)
    {
      printf ("\n## 2. hex8 cube [0,1]^3, CHOLMOD and UMFPACK\n");
      scaling (LAC_HEX8, hex, sizeof hex / sizeof *hex, max_dofs,
               UMFPACK_MAX_DOFS);
      printf ("\n## 2b. hex8 column, 10 x 10 cells across: the same element,"
              " the fill of a banded matrix\n");
      scaling (LAC_HEX8, beam, sizeof beam / sizeof *beam, max_dofs,
               (size_t) -1);
    }
  if (!part || part == 3)
    {
      printf ("\n## 3. tet10 cube [0,1]^3 (6 tetrahedra per box), CHOLMOD "
              "and UMFPACK\n");
      scaling (LAC_TET10, tet, sizeof tet / sizeof *tet, max_dofs,
               UMFPACK_MAX_DOFS);
    }
  return 0;
}
