/* bench_contact -- where the time and the memory of a contact run go, and
 * a yardstick                                        [LAC Alg. 1; ch. 07]
 *
 * Usage:  bench_contact                 the table of `make bench` (below)
 *         bench_contact LABEL SCENE [--strategy NAME] [--repeat N]
 *                       [--set KEY=VALUE]...
 *         bench_contact --header
 *
 * Runs the scene twice, each time in a child process of its own (so that
 * the peak memory, getrusage's ru_maxrss of the child, is the run's alone),
 * N times in turn (--repeat, 3 in the table of make bench, else 1) keeping
 * the fastest of each: on a shared machine other jobs only slow a run
 * down, and the minimum is the least disturbed.
 *   run        the whole run without output files (lac_run_all): wall
 *              time of the mesh, contact set-up, assembly, solve and post
 *              stages, inside the solve the time of the factorizations
 *              (with the analyses) and of the solves, the active-set
 *              iterations, the factorizations, the CG iterations, the
 *              error of lambda where the scene has an exact solution;
 *   yardstick  the same stages up to the assembly, then one CHOLMOD
 *              factorization (lac_solver_factor: analysis + numeric) of
 *              K + delta I, delta = 1e-10 max |K_ii| (K is singular when a
 *              body is held by contact alone): what a plain elastic solve
 *              of the same mesh would cost.
 * Prints one line: the label, dofs, multipliers, the times in seconds, the
 * ratio solve stage / yardstick (mesh, set-up and assembly come before
 * both), the total of the run's stages and both peaks in MB.
 */
#define _DEFAULT_SOURCE /* wait4 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "base/lac_status.h"
#include "io/lac_scene.h"
#include "linalg/lac_linalg.h"
#include "run/lac_run.h"
#include "solve/lac_strategy.h"

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

typedef struct
{
  const char *scene;
  size_t nset;
  const char **set;
  int strategy;
  int repeat;          /* pairs of runs; the fastest of each kind is kept */
} args;

/* Read the scene and run its stages up to (not including) `stop`. */
static lac_run *
start (const args *a, int stop, lac_scene **sc)
{
  lac_run_opts o = { NULL, 1, 1, a->strategy, 0, NULL, 1, 0 };
  lac_run *r;
  if (lac_scene_read (a->scene, a->nset, a->set, sc)
      || !(r = lac_run_alloc (*sc, &o)))
    return NULL;
  while (r->stage < stop)
    {
      int st = lac_run_iterate (r);
      if (st != LAC_SUCCESS && st != LAC_CONTINUE)
        {
          lac_run_free (r);
          return NULL;
        }
    }
  return r;
}

/* Child: the whole run; one line of numbers on fd. */
static int
child_run (const args *a, FILE *out)
{
  lac_scene *sc = NULL;
  lac_run *r = start (a, LAC_NSTAGES, &sc);
  lac_strategy_counts c;
  const char *e;
  if (!r)
    {
      fprintf (stderr, "bench_contact: %s\n", lac_error_message ());
      return 1;
    }
  memset (&c, 0, sizeof c);
  if (r->sol.newton)
    lac_strategy_get_counts (r->sol.newton->strategy, &c);
  e = lac_run_summary_get (r, "max_rel_err_lambda");
  fprintf (out, "%zu %zu %.3f %.3f %.3f %.3f %.3f %.3f %.3f %zu %d %d %s %s "
           "%.6g\n",
           r->sys.ndof, r->sys.contact ? r->sys.contact->k : 0,
           r->time[LAC_STAGE_MESH], r->time[LAC_STAGE_CONTACT],
           r->time[LAC_STAGE_ASSEMBLE], r->time[LAC_STAGE_SOLVE],
           c.time_factor, c.time_solve, r->time[LAC_STAGE_POST],
           r->sol.newton ? r->sol.newton->nhist : 0, c.factorizations,
           c.iterations, lac_strategy_name (r->sol.strategy), e ? e : "-",
           c.flops);
  lac_run_free (r);
  lac_scene_free (sc);
  return 0;
}

/* Child: one CHOLMOD factorization of K + delta I. */
static int
child_yardstick (const args *a, FILE *out)
{
  lac_scene *sc = NULL;
  lac_run *r = start (a, LAC_STAGE_SOLVE, &sc);
  lac_csc *K;
  lac_solver *s;
  double dmax = 0, t0;
  int st;
  if (!r || !(K = lac_csc_copy (r->sys.K)))
    {
      fprintf (stderr, "bench_contact: %s\n", lac_error_message ());
      return 1;
    }
  for (size_t j = 0; j < K->ncol; j++)
    for (int p = K->p[j]; p < K->p[j + 1]; p++)
      if ((size_t) K->i[p] == j)
        dmax = fmax (dmax, fabs (K->x[p]));
  for (size_t j = 0; j < K->ncol; j++)
    for (int p = K->p[j]; p < K->p[j + 1]; p++)
      if ((size_t) K->i[p] == j)
        K->x[p] += 1e-10 * dmax;
  lac_run_free (r);           /* only K is kept: the run's peak is the factor */
  s = lac_solver_alloc (LAC_SOLVER_CHOLMOD);
  t0 = now ();
  st = s ? lac_solver_factor (s, K) : LAC_ENOMEM;
  if (st)
    {
      fprintf (stderr, "bench_contact: yardstick: %s\n", lac_error_message ());
      return 1;
    }
  lac_solver_info info;
  fprintf (out, "%.3f %.6g\n", now () - t0,
           lac_solver_get_info (s, &info) == LAC_SUCCESS ? info.flops : 0.0);
  lac_solver_free (s);
  lac_csc_free (K);
  lac_scene_free (sc);
  return 0;
}

/* Fork, run `fn` in the child with its stdout on a pipe; the child's line
 * in buf, its peak resident memory in MB. */
static int
in_child (int (*fn) (const args *, FILE *), const args *a, char *buf,
          size_t size, double *peak_mb)
{
  int fd[2], wst;
  struct rusage ru;
  pid_t pid;
  FILE *in;
  if (pipe (fd))
    return 1;
  if ((pid = fork ()) < 0)
    return 1;
  if (pid == 0)
    {
      FILE *out = fdopen (fd[1], "w");
      close (fd[0]);
      _exit (out ? fn (a, out) | (fclose (out) != 0) : 1);
    }
  close (fd[1]);
  in = fdopen (fd[0], "r");
  buf[0] = '\0';
  if (!in || !fgets (buf, (int) size, in))
    buf[0] = '\0';
  if (in)
    fclose (in);
  if (wait4 (pid, &wst, 0, &ru) < 0 || !WIFEXITED (wst)
      || WEXITSTATUS (wst) != 0 || !buf[0])
    return 1;
  *peak_mb = (double) ru.ru_maxrss / 1024.0;
  return 0;
}

static void
header (void)
{
  printf ("%-14s %8s %5s %6s %6s %6s %7s %7s %6s %5s %4s %4s %4s %-9s %7s"
          " %6s %6s %8s %8s %9s %7s %7s\n", "case", "dofs", "mult", "mesh",
          "setup", "assem", "solve", "factor", "subst", "post", "its", "fact",
          "cg", "strategy", "yardst", "ratio", "total", "peak_MB", "yard_MB",
          "err_lam", "Gflop", "yGflop");
}

/* One case: a->repeat pairs of children, run and yardstick in turn (on
 * a shared machine the other jobs slow both alike); the run with the
 * fastest solve stage and the fastest yardstick are kept; one line. */
static int
bench_case (const char *label, const args *a)
{
  char run[512], yard[128], strat[32], err[32];
  double peak = 0, ypeak = 0, t[7], ty = 0, best[7], peak1, ypeak1, ty1;
  double fl = 0, yfl = 0;
  size_t ndof, k, its;
  int nfact, ncg;
  for (int r = 0; r < (a->repeat > 0 ? a->repeat : 1); r++)
    {
      if (in_child (child_run, a, run, sizeof run, &peak1)
          || in_child (child_yardstick, a, yard, sizeof yard, &ypeak1)
          || sscanf (run, "%zu %zu %lf %lf %lf %lf %lf %lf %lf %zu %d %d "
                     "%31s %31s %lf", &ndof, &k, &best[0], &best[1], &best[2],
                     &best[3], &best[4], &best[5], &best[6], &its, &nfact,
                     &ncg, strat, err, &fl) != 15
          || sscanf (yard, "%lf %lf", &ty1, &yfl) != 2)
        {
          fprintf (stderr, "bench_contact: %s failed\n", label);
          return 1;
        }
      if (r == 0 || best[3] < t[3])
        memcpy (t, best, sizeof t);
      if (r == 0 || ty1 < ty)
        ty = ty1;
      peak = fmax (peak, peak1);
      ypeak = fmax (ypeak, ypeak1);
    }
  printf ("%-14s %8zu %5zu %6.2f %6.2f %6.2f %7.2f %7.2f %6.2f %5.2f %4zu"
          " %4d %4d %-9s %7.2f %6.2f %6.1f %8.0f %8.0f %9s %7.1f %7.1f\n",
          label, ndof, k, t[0], t[1], t[2], t[3], t[4], t[5], t[6], its,
          nfact, ncg, strat, ty, t[3] / ty, t[0] + t[1] + t[2] + t[3] + t[6],
          peak, ypeak, err, fl * 1e-9, yfl * 1e-9);
  fflush (stdout);
  return 0;
}

/* The default table of `make bench`: the 3D patch test (hex8, n^3 over
 * (n-1)^3 cells) at about 7k, 53k, 141k and 269k dofs, the reference LU
 * at 141k, and the curved scenes of chapter 07 at their finer levels. */
static int
bench_default (void)
{
  static const char *T3 = "chapters/08-experiments/taylor3d.scene";
  static const char *CF = "chapters/07-newton/cylinder-flat.scene";
  static const char *CB = "chapters/07-newton/cylinder-block.scene";
  static const char *SP = "chapters/07-newton/sphere-plane.scene";
  static const struct { const char *label, *scene, *set; int strategy; }
  cases[] = {
    { "taylor3d-n10", NULL, "mesh.numbers=n=10", LAC_STRATEGY_AUTO },
    { "taylor3d-n20", NULL, "mesh.numbers=n=20", LAC_STRATEGY_AUTO },
    { "taylor3d-n28", NULL, "mesh.numbers=n=28", LAC_STRATEGY_AUTO },
    { "taylor3d-n28", NULL, "mesh.numbers=n=28", LAC_STRATEGY_AUGMENTED },
    { "taylor3d-n28", NULL, "mesh.numbers=n=28", LAC_STRATEGY_SADDLE },
    { "taylor3d-n35", NULL, "mesh.numbers=n=35", LAC_STRATEGY_AUTO },
    { "cyl-flat-4", NULL, "level=4", LAC_STRATEGY_AUTO },
    { "cyl-flat-5", NULL, "level=5", LAC_STRATEGY_AUTO },
    { "cyl-flat-6", NULL, "level=6", LAC_STRATEGY_AUTO },
    { "cyl-block-4", NULL, "level=4", LAC_STRATEGY_AUTO },
    { "cyl-block-5", NULL, "level=5", LAC_STRATEGY_AUTO },
    { "cyl-block-6", NULL, "level=6", LAC_STRATEGY_AUTO },
    { "ball-plane-0", NULL, "level=0", LAC_STRATEGY_AUTO },
    { "ball-plane-1", NULL, "level=1", LAC_STRATEGY_AUTO },
    { "ball-plane-2", NULL, "level=2", LAC_STRATEGY_AUTO },
  };
  int failed = 0;
  header ();
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
    {
      const char *set[1] = { cases[c].set };
      const char *lb = cases[c].label;
      args a = { !strncmp (lb, "taylor", 6) ? T3 : !strncmp (lb, "cyl-f", 5)
                 ? CF : !strncmp (lb, "cyl-b", 5) ? CB : SP, 1, set,
                 cases[c].strategy, 3 };
      failed |= bench_case (lb, &a);
    }
  printf ("(seconds; solve = the solve stage, factor = its analyses and "
          "factorizations, subst = the rest: substitutions, CG, "
          "refinement; its = active-set iterations, fact = factorizations, "
          "cg = Krylov iterations (CG, GMRES for split); yardst = one CHOLMOD factorization of K + "
          "delta I of the same mesh; ratio = solve / yardst; total = every "
          "stage; peaks of the run and of the yardstick's process; Gflop = "
          "the run's numeric factorizations, yGflop = the yardstick's, "
          "as counted by the analyses: what the times would be on an idle "
          "machine)\n");
  return failed;
}

int
main (int argc, char **argv)
{
  args a = { NULL, 0, NULL, LAC_STRATEGY_AUTO, 1 };
  int status;
  if (argc == 1)
    return bench_default ();
  if (argc == 2 && !strcmp (argv[1], "--header"))
    {
      header ();
      return 0;
    }
  if (argc < 3)
    {
      fprintf (stderr, "usage: bench_contact [LABEL SCENE [--strategy NAME] "
               "[--repeat N] [--set KEY=VALUE]...]\n       bench_contact --header\n"
               "(no argument: the table of make bench)\n");
      return 2;
    }
  a.scene = argv[2];
  a.set = calloc ((size_t) argc, sizeof *a.set);
  for (int i = 3; a.set && i + 1 < argc; i += 2)
    {
      if (!strcmp (argv[i], "--set"))
        a.set[a.nset++] = argv[i + 1];
      else if (!strcmp (argv[i], "--strategy")
               && (a.strategy = lac_strategy_from_name (argv[i + 1])) >= 0)
        continue;
      else if (!strcmp (argv[i], "--repeat")
               && (a.repeat = atoi (argv[i + 1])) > 0)
        continue;
      else
        {
          fprintf (stderr, "bench_contact: unknown option '%s'\n", argv[i]);
          free (a.set);
          return 2;
        }
    }
  status = a.set ? bench_case (argv[1], &a) : 1;
  free (a.set);
  return status;
}
