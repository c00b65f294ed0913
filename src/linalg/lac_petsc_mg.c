/* lac_petsc_mg.c -- the multigrid of K_W near the contact: smoothed
 *                   aggregation's finest level by lac, GAMG below
 *                   (see lac_petsc_mg.h)                      [chapter 13]
 *
 * The two levels: the finest one made of the steps (the graph and the
 * aggregates, lac_petsc_mg_aggregate.c; the prolongator,
 * lac_petsc_mg_prolong.c), its operator, its smoother, and the coarse
 * solve by GAMG, wired into PETSc's PCMG.
 */
#include "linalg/lac_petsc_mg.h"

#ifdef LAC_HAVE_PETSC

#include <stdio.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"
#include "linalg/lac_petsc_mg_internal.h"

#define SMOOTH_STEPS 2       /* Chebyshev steps on the finest level       */
#define CHEB_LOW 0.1         /* its interval: [0.1, 1.1] lambda (GAMG's)  */
#define CHEB_HIGH 1.1

struct lac_petsc_mg
{
  PetscLogEvent event;       /* "lac contact MG" (-log_view): the finest
                                level's set-up                           */
  PC pc;                     /* borrowed: the PCMG it configures         */
  double threshold;          /* contact nodes' couplings below it out    */
  Mat P, A1;                 /* owned: the prolongator, P^T K P          */
  MatNullSpace nsp;          /* owned: A_1's near-null space             */
  lac_petsc_mg_counts counts;
};

/* ---- the two levels ----------------------------------------------------- */

/* Steps 1 to 3 on this process: agg (n + 1), *nagg, and the counts. */
static int
aggregates (lac_petsc_mg *mg, Mat K, Mat B, int **agg, int *nagg)
{
  lac_mg_graph g;
  near_null z;
  int grouped, joined, min, status;
  long long dropped;
  *agg = NULL;
  if ((status = lac_petsc_mg_near_null_open (K, &z))
      || (status = lac_petsc_mg_near_null_close (&z))
      || (status = lac_petsc_mg_graph (K, B, mg->threshold, &g, &dropped)))
    return status;
  min = z.bs < z.m ? 2 : 1;             /* an aggregate holds m dofs     */
  if (!(*agg = lac_malloc (((size_t) g.n + 1) * sizeof **agg)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the aggregates of %d nodes", g.n);
  else
    status = lac_petsc_mg_aggregate (&g, min, *agg, nagg, &grouped, &joined);
  mg->counts.nodes = g.n;
  mg->counts.dropped = dropped;
  mg->counts.grouped = grouped;
  mg->counts.joined = joined;
  mg->counts.left = 0;
  for (int i = 0; !status && i < g.n; i++)
    mg->counts.left += (*agg)[i] < 0;
  lac_petsc_mg_graph_free (&g);
  return status;
}

/* The counts summed over the processes (nagg: this process's aggregates),
 * and, in PETSc's -info, nnz(A_1) / nnz(K). */
static int
sum_counts (lac_petsc_mg *mg, Mat K, int nagg)
{
  lac_petsc_mg_counts *c = &mg->counts;
  long long mine[6] = { c->nodes, nagg, c->dropped, c->grouped, c->joined,
                        c->left }, all[6];
  MatInfo ik, i1;
  if (MPI_Allreduce (mine, all, 6, MPI_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI: the counts of the contact multigrid");
  c->nodes = all[0], c->aggregates = all[1], c->dropped = all[2];
  c->grouped = all[3], c->joined = all[4], c->left = all[5];
  TRY (MatGetInfo (K, MAT_GLOBAL_SUM, &ik));
  TRY (MatGetInfo (mg->A1, MAT_GLOBAL_SUM, &i1));
  TRY (PetscInfo (mg->pc, "lac's finest level: %lld nodes, %lld aggregates, "
                  "%lld couplings dropped, %lld single nodes grouped, %lld "
                  "joined, %lld in none, lambda %g, nnz(A_1) / nnz(K) %g\n",
                  all[0], all[1], all[2], all[3], all[4], all[5], c->lambda,
                  ik.nz_used > 0 ? i1.nz_used / ik.nz_used : 0.0));
  return LAC_SUCCESS;
}

/* The finest level from K and B: P and A_1 = P^T K P with its near-null
 * space, the interpolation and the smoother's interval. */
static int
finest_level (lac_petsc_mg *mg, Mat K, Mat B)
{
  int *agg = NULL, nagg = 0;
  int status = lac_petsc_agree (aggregates (mg, K, B, &agg, &nagg));
  KSP ks;
  if (!status)
    status = lac_petsc_mg_tentative (K, agg, nagg, &mg->P, &mg->nsp);
  lac_free (agg);
  if (status
      || (status = lac_petsc_mg_largest_eigenvalue (K, &mg->counts.lambda))
      || (status = lac_petsc_mg_smooth (K, mg->counts.lambda, &mg->P)))
    return status;
  TRY (MatPtAP (K, mg->P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &mg->A1));
  if ((status = sum_counts (mg, K, nagg)))
    return status;
  TRY (MatSetNearNullSpace (mg->A1, mg->nsp));
  TRY (PCMGSetInterpolation (mg->pc, 1, mg->P));
  TRY (PCMGGetSmoother (mg->pc, 1, &ks));
  TRY (KSPChebyshevSetEigenvalues (ks, CHEB_HIGH * mg->counts.lambda,
                                   CHEB_LOW * mg->counts.lambda));
  return LAC_SUCCESS;
}

int
lac_petsc_mg_update (lac_petsc_mg *mg, Mat K, Mat B)
{
  KSP ks, kc;
  int status = LAC_SUCCESS;
  TRY (PetscLogEventBegin (mg->event, 0, 0, 0, 0));
  if (!mg->P)
    status = finest_level (mg, K, B);
  else          /* new values: the aggregates and P kept, A_1 made again */
    TRY (MatPtAP (K, mg->P, MAT_REUSE_MATRIX, PETSC_DEFAULT, &mg->A1));
  TRY (PetscLogEventEnd (mg->event, 0, 0, 0, 0));
  if (status)
    return status;
  TRY (PCMGGetSmoother (mg->pc, 1, &ks));
  TRY (KSPSetOperators (ks, K, K));
  TRY (PCMGGetCoarseSolve (mg->pc, &kc));
  TRY (KSPSetOperators (kc, mg->A1, mg->A1));
  TRY (PCSetOperators (mg->pc, K, K));
  return LAC_SUCCESS;
}

void
lac_petsc_mg_get_counts (const lac_petsc_mg *mg, lac_petsc_mg_counts *c)
{
  *c = mg->counts;
}

/* The finest level's smoother: SMOOTH_STEPS of Chebyshev with Jacobi,
 * its interval from lambda (no estimate of its own). */
static int
fine_smoother (PC pc)
{
  KSP ks;
  PC p;
  TRY (PCMGGetSmoother (pc, 1, &ks));
  TRY (KSPSetType (ks, KSPCHEBYSHEV));
  TRY (KSPChebyshevEstEigSet (ks, 0, 0, 0, 0));
  TRY (KSPSetTolerances (ks, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT,
                         SMOOTH_STEPS));
  TRY (KSPSetConvergenceTest (ks, KSPConvergedSkip, NULL, NULL));
  TRY (KSPSetNormType (ks, KSP_NORM_NONE));
  TRY (KSPGetPC (ks, &p));
  TRY (PCSetType (p, PCJACOBI));
  return LAC_SUCCESS;
}

/* The coarse solve: one V-cycle of GAMG on A_1, every nonzero coupling of
 * its graph kept (threshold 0 on every level), no aggressive
 * aggregation (the finest level had it), its interpolation kept when
 * only the values change.  The aggressive levels by the option (PETSc
 * reads it again at its set-up, over PCGAMGSetAggressiveLevels); its
 * name changed with PETSc 3.18. */
static int
coarse_solver (PC pc)
{
  KSP kc;
  PC p;
  PetscReal zero = 0;
  const char *pre;
  char name[200];
  TRY (PCMGGetCoarseSolve (pc, &kc));
  TRY (KSPSetType (kc, KSPPREONLY));
  TRY (KSPGetPC (kc, &p));
  TRY (PCSetType (p, PCGAMG));
  TRY (PCGAMGSetThreshold (p, &zero, 1));
  TRY (PCGAMGSetReuseInterpolation (p, PETSC_TRUE));
  TRY (PCGetOptionsPrefix (p, &pre));
  snprintf (name, sizeof name, "-%s%s", pre ? pre : "",
            PETSC_VERSION_LT (3, 18, 0) ? "pc_gamg_square_graph"
            : "pc_gamg_aggressive_coarsening");
  return lac_petsc_option_default (name, "0");
}

/* pc as the two levels, then its options. */
static int
configure (PC pc)
{
  PetscInt levels;
  int status;
  TRY (PCSetType (pc, PCMG));
  TRY (PCMGSetLevels (pc, 2, NULL));
  TRY (PCMGSetGalerkin (pc, PC_MG_GALERKIN_NONE));
  if ((status = fine_smoother (pc)) || (status = coarse_solver (pc)))
    return status;
  TRY (PCSetFromOptions (pc));
  TRY (PCMGGetLevels (pc, &levels));
  if (levels != 2)
    LAC_ERROR (LAC_EINVAL, "the contact multigrid has two levels (lac's "
               "finest, GAMG below), not %d: leave -pc_mg_levels unset, or "
               "choose another preconditioner with -elast_pc_type",
               (int) levels);
  return LAC_SUCCESS;
}

int
lac_petsc_mg_create (PC pc, double threshold, lac_petsc_mg **out)
{
  lac_petsc_mg *mg = lac_calloc (1, sizeof *mg);
  int status;
  *out = NULL;
  if (!mg)
    LAC_ERROR (LAC_ENOMEM, "the contact multigrid");
  mg->pc = pc;
  mg->threshold = threshold;
  if (PetscLogEventRegister ("lac contact MG", PC_CLASSID, &mg->event))
    status = lac_petsc_fail (1, __func__, "PetscLogEventRegister");
  else
    status = configure (pc);
  if (status)
    {
      lac_free (mg);
      return status;
    }
  *out = mg;
  return LAC_SUCCESS;
}

void
lac_petsc_mg_free (lac_petsc_mg *mg)
{
  if (!mg)
    return;
  MatDestroy (&mg->P);
  MatDestroy (&mg->A1);
  MatNullSpaceDestroy (&mg->nsp);
  lac_free (mg);
}

#else

typedef int lac_petsc_mg_unused;        /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
