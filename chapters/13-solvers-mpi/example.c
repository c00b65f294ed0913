/* LAC chapter 13 -- Krylov methods, algebraic multigrid and MPI for the
 *                   system of one active set           [LAC Alg. 1 l. 21]
 *
 * Build:        make  (builds it as build/chapters/13-solvers-mpi)
 * Sample runs:  build/chapters/13-solvers-mpi     (from the repository
 *                                root: it reads the 3D Taylor patch test
 *                                of chapter 08)
 *               mpirun -n 2 build/chapters/13-solvers-mpi  (part 1 on two
 *                                processes; as root Open MPI also wants
 *                                --allow-run-as-root, which
 *                                chapters/13-solvers-mpi/mpirun.sh adds)
 * Description:  The 3D Taylor patch test (two hex8 cubes, the upper one
 *               held by the contact alone, 25 MPa on its top) is run
 *               through stages 1-4 of `lac run`: mesh, contact, material,
 *               system.  Its system of one active set (every multiplier
 *               active, the statuses of the exact solution) is then solved
 *               by lac's strategies, without Algorithm 1 around them.
 *               Part 1: a direct strategy (split: Cholesky factors) and
 *               the petsc strategy (conjugate gradients on the null space
 *               of C_A^T, preconditioned by lac's smoothed-aggregation
 *               multigrid): the same U and lambda, the constraint rows
 *               exact to rounding while the force rows stop at the
 *               tolerance.  Part 2: the CG iterations at two mesh sizes,
 *               with lac's multigrid, with every coupling of the contact
 *               nodes kept, with PETSc's GAMG alone, and with no multigrid
 *               at all.  Under mpirun -n N the program runs part 1 on N
 *               processes: process 0 prints, the others serve the petsc
 *               strategy; part 2 needs one process (it changes PETSc's
 *               options between solves).  Without PETSc in lac (make
 *               PETSC=no) only the direct strategy runs.  No timings: the
 *               output is the same on every machine, up to the last digit
 *               of the residuals (rounding).
 * Read first:   chapter 07 (the strategies of one active set), chapter 08
 *               (the Taylor patch test).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lac.h"
#include "linalg/lac_petsc_env.h"
#include "solve/lac_petsc.h"

// @sect The system of one active set
/* A library call that fails stops the program with the one-line message
 * the library stored (library code never prints). */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex13: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* The patch test with n and n - 1 hex8 cells per edge (its [mesh]
 * numbers), run up to the solve: stages 1-4 of `lac run` make the mesh,
 * the macro-mesh and the pairing, then K, F, C and G.  keep_k: the run
 * keeps K whole for us to compute residuals with.  The run owns all of it
 * (r->sys) and the scene must outlive it. */
static lac_run *
system_of (int n, lac_scene **sc)
{
  char set[32];
  const char *sets[1] = { set };
  lac_run_opts o = { .no_output = 1, .strategy = LAC_STRATEGY_SPLIT,
                     .keep_k = 1 };
  const char *path = "chapters/08-experiments/taylor3d.scene";
  snprintf (set, sizeof set, "mesh.numbers=n=%d", n);
  check_status (lac_scene_read (path, 1, sets, sc), path);
  lac_run *r = lac_run_alloc (*sc, &o);
  check_status (r ? LAC_SUCCESS : LAC_ENOMEM, "lac_run_alloc");
  while (r->stage < LAC_STAGE_SOLVE)          /* LAC_CONTINUE after each */
    {
      int status = lac_run_iterate (r);
      check_status (status == LAC_CONTINUE ? LAC_SUCCESS : status,
                    "stages 1-4");
    }
  return r;
}

/* The system (*) of chapter 07 for this run: K U - C_A lambda = F,
 * C_A^T U = G_A, with the rigid motions the Dirichlet conditions leave
 * free (the upper cube's translation along z), which the strategies
 * check the active multipliers hold. */
static lac_contact_system
contact_system (const lac_run *r)
{
  const lac_run_system *s = &r->sys;
  return (lac_contact_system) { s->K, s->b, s->contact->C, s->contact->G,
                                NULL, s->nfree, s->N,
                                (const char *const *) s->N_what, NULL };
}

// @sect What a solve leaves unsolved
/* The two rows of (*) measured apart.  The forces: ||F - K U + C lambda||
 * relative to ||F|| (2-norms).  The constraints: max_i |c_i^T U - g_i|
 * relative to the size of its terms, max_i (|c_i|^T |U| + |g_i|): zero
 * up to rounding means exact. */
static void
residuals (const lac_contact_system *cs, const double *U,
           const double *lambda, double *force, double *gap)
{
  const lac_csc *K = cs->K, *C = cs->C;
  size_t n = K->nrow, k = C->ncol;
  double *r = malloc (n * sizeof *r), rr = 0, ff = 0, num = 0, den = 0;
  check_status (r ? LAC_SUCCESS : LAC_ENOMEM, "residuals");
  check_status (lac_csc_matvec (K, U, r), "K U");
  for (size_t j = 0; j < k; j++)
    {
      double cu = 0, size = fabs (cs->G[j]);
      for (int p = C->p[j]; p < C->p[j + 1]; p++)
        {
          r[C->i[p]] -= C->x[p] * lambda[j];
          cu += C->x[p] * U[C->i[p]];
          size += fabs (C->x[p] * U[C->i[p]]);
        }
      num = fmax (num, fabs (cu - cs->G[j]));
      den = fmax (den, size);
    }
  for (size_t i = 0; i < n; i++)
    {
      rr += (cs->F[i] - r[i]) * (cs->F[i] - r[i]);
      ff += cs->F[i] * cs->F[i];
    }
  free (r);
  *force = sqrt (rr / ff);
  *gap = num / den;
}

// @sect One solve by one strategy
/* What a solve gives: U, lambda and the counts of the strategy. */
typedef struct solve
{
  double *U, *lambda;
  lac_strategy_counts c;
  char method[128];
} solve;

/* The system of r for every multiplier active, by `kind`, from U = 0.
 * The petsc strategy is told the nodal coordinates (the rigid motions
 * its multigrid starts from) and the cells K came from (it assembles K
 * again where the cells are: on N processes each process its share). */
static solve
solve_by (lac_strategy_kind kind, const lac_run *r)
{
  lac_contact_system cs = contact_system (r);
  size_t n = r->sys.ndof, k = cs.C->ncol;
  solve x = { calloc (n, sizeof (double)), calloc (k, sizeof (double)),
              { 0 }, "" };
  char *active = malloc (k);
  lac_strategy *s = lac_strategy_alloc (kind);
  check_status (x.U && x.lambda && active ? LAC_SUCCESS : LAC_ENOMEM,
                "solve_by");
  check_status (s ? LAC_SUCCESS : LAC_EDEP, "lac_strategy_alloc");
  memset (active, 1, k);
  lac_strategy_set_coordinates (s, r->sys.coord_dim, r->sys.x);
  lac_strategy_set_mesh (s, r->sys.cells.mesh ? &r->sys.cells : NULL);
  check_status (lac_strategy_set (s, &cs), "lac_strategy_set");
  check_status (lac_strategy_solve (s, active, x.U, x.lambda),
                "lac_strategy_solve");
  lac_strategy_get_counts (s, &x.c);
  snprintf (x.method, sizeof x.method, "%s", lac_strategy_method (s));
  lac_strategy_free (s);   /* on N processes: one petsc strategy at a time */
  free (active);
  return x;
}

static void
solve_free (solve *x)
{
  free (x->U);
  free (x->lambda);
}

// @sect Part 1: a direct strategy and the projected CG
/* The same system by Cholesky factors (split, chapter 07) and by the
 * petsc strategy.  The CG works on the null space of C_A^T: it starts
 * from u0 with C_A^T u0 = G_A and adds only projected directions, so the
 * constraint rows hold to rounding at every iteration; the force rows
 * hold to the tolerance of the CG, a true relative residual of 1e-10.
 * lambda comes after, by least squares on the force rows.  The two U
 * agree to that tolerance, and lambda = -25 (the exact pressure) on
 * every macro-element. */
static void
part1 (int cells)
{
  lac_scene *sc = NULL;
  lac_run *r = system_of (cells, &sc);
  lac_contact_system cs = contact_system (r);
  size_t n = r->sys.ndof, k = cs.C->ncol;
  printf ("Part 1: the Taylor patch test, hex8, n = %d: %zu displacements, "
          "%zu multipliers\n\n", cells, n, k);
  solve ref = solve_by (LAC_STRATEGY_SPLIT, r);
  printf ("%-9s %10s  %-14s %-14s %-14s %s\n", "strategy", "iterations",
          "force res.", "constraint res.", "|U - U_split|", "lambda");
  for (int p = 0; p < 2; p++)
    {
      if (p == 1 && !lac_petsc_available ())
        {
          printf ("petsc: lac was built without PETSc (make PETSC=no)\n");
          break;
        }
      solve x = p ? solve_by (LAC_STRATEGY_PETSC, r) : ref;
      double force, gap, du = 0, umax = 0, lmin = INFINITY, lmax = -INFINITY;
      residuals (&cs, x.U, x.lambda, &force, &gap);
      for (size_t i = 0; i < n; i++)
        {
          du = fmax (du, fabs (x.U[i] - ref.U[i]));
          umax = fmax (umax, fabs (ref.U[i]));
        }
      for (size_t i = 0; i < k; i++)
        {
          lmin = fmin (lmin, x.lambda[i]);
          lmax = fmax (lmax, x.lambda[i]);
        }
      printf ("%-9s %10d  %-14.1e %-15.1e %-14.1e [%.8f, %.8f]\n",
              p ? "petsc" : "split", x.c.iterations, force, gap, du / umax,
              lmin, lmax);
      if (p)
        {
          printf ("\npetsc: %s\n", x.method);
          printf ("processes = %d\n", x.c.processes);
          solve_free (&x);
        }
    }
  solve_free (&ref);
  lac_run_free (r);
  lac_scene_free (sc);
}

// @sect Part 2: what the multigrid does
/* The CG iterations of the petsc strategy at two sizes for four
 * preconditioners, chosen by PETSc options (added to PETSc's options
 * database by lac_petsc_initialize, as --petsc-options of `lac run`):
 *   lac-sa      lac's finest level (its graph without the weak couplings
 *               of the contact nodes, aggregates with no single node),
 *               PETSc's GAMG below it: the default;
 *   all         the same with every coupling of the graph kept
 *               (-lac_contact_threshold -1);
 *   gamg        PETSc's GAMG on K_W from the finest level down
 *               (-elast_pc_type gamg);
 *   none        no multigrid, the projections alone (-pc_type none).
 * An option once given stays given, so they come in that order: each
 * row adds one option that the rows below either need or ignore.  With
 * a multigrid the iterations barely grow with the mesh; without one they
 * grow like the square root of K's condition number, like 1/h. */
static void
part2 (void)
{
  static const char *name[4] = { "lac-sa", "all", "gamg", "none" };
  static const char *option[4] = { "", "-lac_contact_threshold -1",
                                   "-elast_pc_type gamg", "-pc_type none" };
  const int cells[2] = { 6, 12 };
  lac_scene *sc[2] = { NULL, NULL };
  lac_run *r[2];
  for (int m = 0; m < 2; m++)
    r[m] = system_of (cells[m], &sc[m]);
  printf ("\nPart 2: CG iterations against the preconditioner\n\n");
  printf ("%-8s %-28s %12zu %12zu  (displacements)\n", "row", "option",
          r[0]->sys.ndof, r[1]->sys.ndof);
  for (int p = 0; p < 4; p++)
    {
      check_status (lac_petsc_initialize (option[p]), option[p]);
      printf ("%-8s %-28s", name[p], *option[p] ? option[p] : "(default)");
      for (int m = 0; m < 2; m++)
        {
          solve x = solve_by (LAC_STRATEGY_PETSC, r[m]);
          double lerr = 0;
          for (size_t i = 0; i < r[m]->sys.contact->C->ncol; i++)
            lerr = fmax (lerr, fabs (x.lambda[i] + 25) / 25);
          /* every row solves the same system: lambda = -25 */
          check_status (lerr < 1e-8 ? LAC_SUCCESS : LAC_ESANITY, name[p]);
          printf (" %12d", x.c.iterations);
          solve_free (&x);
        }
      printf ("\n");
    }
  for (int m = 0; m < 2; m++)
    {
      lac_run_free (r[m]);
      lac_scene_free (sc[m]);
    }
}

// @sect The main program
/* With PETSc, MPI and PETSc start first, on every process (under mpirun
 * -n N: N of them).  Process 0 runs the program; the others wait in
 * lac_petsc_serve for its commands (build, new values, solve, free) and
 * make the same collective PETSc calls, until lac_petsc_finalize on
 * process 0 sends them "quit".  The partitioner of the cells is asked
 * for blocks of consecutive cells ("average"), which cuts the same way in
 * every run: PT-Scotch, the default of Debian's PETSc, may not, and the
 * aggregates of the multigrid, which never span two processes, and so
 * the iteration count, would then depend on the run. */
int
main (void)
{
  int rank = 0, size = 1, status = LAC_SUCCESS;
  lac_init ();
  if (lac_petsc_available ())
    {
      check_status (lac_petsc_initialize
                    ("-lac_part_mat_partitioning_type average"),
                    "lac_petsc_initialize");
      lac_petsc_rank (&rank, &size);
    }
  if (rank > 0)
    status = lac_petsc_serve ();
  else
    {
      part1 (12);
      if (size == 1 && lac_petsc_available ())
        part2 ();
    }
  lac_petsc_finalize ();
  lac_finalize ();
  check_status (status, "lac_petsc_serve");
  return 0;
}
