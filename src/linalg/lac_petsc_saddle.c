/* lac_petsc_saddle.c -- a stiffness under linear constraints by Krylov
 *                       methods and multigrid (see lac_petsc_saddle.h)
 *
 * The solvers of the three methods, the projections of the projected CG
 * and the new values; the solves themselves in lac_petsc_saddle_solve.c
 * (the solvers' state: lac_petsc_saddle_internal.h).
 */
#include "linalg/lac_petsc_saddle.h"

#ifdef LAC_HAVE_PETSC

#include <stdio.h>
#include <string.h>
#include <petscksp.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_env.h"
#include "linalg/lac_petsc_mg.h"
#include "linalg/lac_petsc_saddle_internal.h"

#define KSP_MAXIT 2000        /* Krylov iterations at most per solve     */
#define PROJECTION_STEPS 1    /* projected: Jacobi steps of Z ~ K^-1 B   */
#define PROJECTION_STEPS_MAX 100  /* -lac_projection_steps at most       */

#define COUNT(a) (sizeof (a) / sizeof *(a))

void
lac_petsc_saddle_free (lac_petsc_saddle *sv)
{
  if (!sv)
    return;
  KSP *ksp[] = { &sv->ku, &sv->kg, &sv->kp, &sv->kl, &sv->ks, &sv->kz,
                 &sv->kzl };
  Mat *mat[] = { &sv->G, &sv->Ah, &sv->Bl, &sv->Gl, &sv->A, &sv->Bt,
                 &sv->D, &sv->Sp, &sv->Z, &sv->Gz, &sv->Zl, &sv->Gzl };
  Vec *vec[] = { &sv->ru, &sv->u0, &sv->bu, &sv->tu, &sv->tk, &sv->sk,
                 &sv->vl, &sv->ul, &sv->tl, &sv->tg, &sv->sl, &sv->b,
                 &sv->x, &sv->r, &sv->dx, &sv->dinv };
  for (size_t i = 0; i < COUNT (ksp); i++)
    KSPDestroy (ksp[i]);
  PCDestroy (&sv->pg);
  lac_petsc_mg_free (sv->mg);
  for (size_t i = 0; i < COUNT (mat); i++)
    MatDestroy (mat[i]);
  for (size_t i = 0; i < COUNT (vec); i++)
    VecDestroy (vec[i]);
  lac_free (sv);
}

/* ---- the projection ----------------------------------------------------- */

/* *ksp: one application of a factorization (pc_type: PCLU on a
 * process's own copy, PCREDUNDANT on a distributed matrix), options
 * prefix `prefix`. */
static int
direct_solver (MPI_Comm comm, const char *prefix, PCType pc_type, KSP *ksp)
{
  PC pc;
  TRY (KSPCreate (comm, ksp));
  TRY (KSPSetOptionsPrefix (*ksp, prefix));
  TRY (KSPSetType (*ksp, KSPPREONLY));
  TRY (KSPGetPC (*ksp, &pc));
  TRY (PCSetType (pc, pc_type));
  TRY (KSPSetFromOptions (*ksp));
  return LAC_SUCCESS;
}

/* v -= Y G^-1 X^T v (G^-T: trans), G's solver kx: the projections'
 * common step.  On N > 1 processes (Xl, Yl: the own rows of X and Y, kl
 * a copy of G's LU on every process) with one reduction: each process
 * makes X_own^T v_own, one MPI_Allreduce sums them, each solves with its
 * own copy of G and subtracts Y_own s from its rows (instead of the
 * scatters of X^T v, of PCREDUNDANT and of Y s: fewer waits for the
 * other processes, twice per CG iteration). */
static PetscErrorCode
subtract (lac_petsc_saddle *sv, Mat X, Mat Y, KSP kx, Mat Xl, Mat Yl,
          KSP kl, int trans, Vec v)
{
  PetscScalar *a, *g;
  const PetscScalar *t;
  PetscInt k;
  if (!kl)
    {
      PetscCall (MatMultTranspose (X, v, sv->tk));
      PetscCall ((trans ? KSPSolveTranspose : KSPSolve) (kx, sv->tk,
                                                          sv->sk));
      PetscCall (MatMult (Y, sv->sk, sv->tu));
      return VecAXPY (v, -1.0, sv->tu);
    }
  PetscCall (VecGetSize (sv->tg, &k));
  PetscCall (VecGetArray (v, &a));
  PetscCall (VecPlaceArray (sv->vl, a));
  PetscCall (MatMultTranspose (Xl, sv->vl, sv->tl));
  PetscCall (VecGetArrayRead (sv->tl, &t));
  PetscCall (VecGetArray (sv->tg, &g));
  PetscCallMPI (MPI_Allreduce (t, g, (int) k, MPIU_SCALAR, MPIU_SUM,
                               PETSC_COMM_WORLD));
  PetscCall (VecRestoreArray (sv->tg, &g));
  PetscCall (VecRestoreArrayRead (sv->tl, &t));
  PetscCall ((trans ? KSPSolveTranspose : KSPSolve) (kl, sv->tg, sv->sl));
  PetscCall (MatMult (Yl, sv->sl, sv->ul));
  PetscCall (VecAXPY (sv->vl, -1.0, sv->ul));
  PetscCall (VecResetArray (sv->vl));
  PetscCall (VecRestoreArray (v, &a));
  return 0;
}

/* v = P v = v - B (B^T B + D)^-1 B^T v: v without its part in the range
 * of B (l2-orthogonal projection on the null space of B^T). */
PetscErrorCode
lac_petsc_saddle_project (lac_petsc_saddle *sv, Vec v)
{
  return subtract (sv, sv->B, sv->B, sv->kg, sv->Bl, sv->Bl, sv->kl, 0, v);
}

/* N > 1: the own rows of B and a copy of G on every process, G's LU
 * there (after each new G). */
static int
update_local (lac_petsc_saddle *sv)
{
  PetscInt nl, k;
  int status;
  TRY (MatGetLocalSize (sv->B, &nl, NULL));
  TRY (MatGetSize (sv->B, NULL, &k));
  TRY (MatMPIAIJGetLocalMat (sv->B, sv->Bl ? MAT_REUSE_MATRIX
                             : MAT_INITIAL_MATRIX, &sv->Bl));
  TRY (MatCreateRedundantMatrix (sv->G, sv->size, MPI_COMM_NULL, sv->Gl
                                 ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX,
                                 &sv->Gl));
  if (!sv->kl)
    {
      if ((status = direct_solver (PetscObjectComm ((PetscObject) sv->Gl),
                                   "gram_local_", PCLU, &sv->kl)))
        return status;
      TRY (MatCreateVecs (sv->Gl, &sv->sl, &sv->tg));
      TRY (VecCreateSeqWithArray (PETSC_COMM_SELF, 1, nl, NULL, &sv->vl));
      TRY (VecCreateSeq (PETSC_COMM_SELF, nl, &sv->ul));
      TRY (VecCreateSeq (PETSC_COMM_SELF, k, &sv->tl));
    }
  TRY (KSPSetOperators (sv->kl, sv->Gl, sv->Gl));
  return LAC_SUCCESS;
}

/* The operator of the projected CG: y = P K x. */
static PetscErrorCode
projected_op (Mat A, Vec x, Vec y)
{
  lac_petsc_saddle *sv;
  PetscCall (MatShellGetContext (A, &sv));
  PetscCall (MatMult (sv->K, x, y));
  return lac_petsc_saddle_project (sv, y);
}

/* Its preconditioner, M one V-cycle of multigrid on K: z = P M r, or
 * with Z (steps > 0) z = P_Z M P_Z^T r, P_Z = I - Z G_Z^-1 B^T and
 * G_Z = B^T Z + D: P_Z is K-orthogonal when Z = K^-1 B. */
static PetscErrorCode
projected_pc (PC pc, Vec r, Vec z)
{
  lac_petsc_saddle *sv;
  PetscCall (PCShellGetContext (pc, &sv));
  if (!sv->steps)
    {
      PetscCall (sv->pg ? PCApply (sv->pg, r, z) : VecCopy (r, z));
      return lac_petsc_saddle_project (sv, z);
    }
  PetscCall (VecCopy (r, sv->ru));                     /* P_Z^T r */
  PetscCall (subtract (sv, sv->Z, sv->B, sv->kz, sv->Zl, sv->Bl, sv->kzl, 1,
                       sv->ru));
  PetscCall (sv->pg ? PCApply (sv->pg, sv->ru, z)      /* M */
             : VecCopy (sv->ru, z));
  return subtract (sv, sv->B, sv->Z, sv->kz, sv->Bl, sv->Zl, sv->kzl, 0, z);
}

/* ---- the solvers -------------------------------------------------------- */

/* GAMG, which keeps its interpolation when only the values of the matrix
 * change (new statuses: chapter 13). */
static PetscErrorCode
gamg_setup (PC pc)
{
  PetscCall (PCSetType (pc, PCGAMG));
  PetscCall (PCGAMGSetReuseInterpolation (pc, PETSC_TRUE));
  return 0;
}

/* The tolerances the user gave a Krylov method of options prefix
 * `prefix` (NULL: none) into *u. */
static int
read_tolerances (const char *prefix, user_tolerances *u)
{
  memset (u, 0, sizeof *u);
  TRY (PetscOptionsGetReal (NULL, prefix, "-ksp_rtol", &u->rtol,
                            &u->has_rtol));
  TRY (PetscOptionsGetReal (NULL, prefix, "-ksp_atol", &u->atol,
                            &u->has_atol));
  TRY (PetscOptionsGetInt (NULL, prefix, "-ksp_max_it", &u->maxit,
                           &u->has_maxit));
  return LAC_SUCCESS;
}

/* ksp's tolerances: lac's rtol, atol and KSP_MAXIT, but those the user
 * gave (sv->tol); a relative tolerance of the user's stands alone (no
 * atol of lac's beside it, PETSc's 1e-50). */
int
lac_petsc_saddle_set_tolerances (const lac_petsc_saddle *sv, KSP ksp,
                                 PetscReal rtol, PetscReal atol)
{
  const user_tolerances *u = &sv->tol;
  TRY (KSPSetTolerances (ksp, u->has_rtol ? u->rtol : rtol,
                         u->has_atol ? u->atol : u->has_rtol ? 1e-50 : atol,
                         PETSC_DEFAULT, u->has_maxit ? u->maxit
                         : KSP_MAXIT));
  return LAC_SUCCESS;
}

/* K alone: conjugate gradients and GAMG (prefix elast_). */
static int
create_alone (lac_petsc_saddle *sv)
{
  PC pc;
  TRY (KSPCreate (PETSC_COMM_WORLD, &sv->ku));
  TRY (KSPSetOptionsPrefix (sv->ku, "elast_"));
  TRY (KSPSetOperators (sv->ku, sv->K, sv->K));
  TRY (KSPSetType (sv->ku, KSPCG));
  TRY (KSPSetNormType (sv->ku, KSP_NORM_UNPRECONDITIONED));
  TRY (KSPGetPC (sv->ku, &pc));
  TRY (gamg_setup (pc));
  TRY (KSPSetFromOptions (sv->ku));
  TRY (MatCreateVecs (sv->K, NULL, &sv->ru));
  return read_tolerances ("elast_", &sv->tol);
}

/* -pc_type of the projected CG (no prefix): its preconditioner is the
 * projection around M, the multigrid of K; "none" leaves M out (*none =
 * 1: z = P_Z P_Z^T r), another type is refused (-elast_pc_type chooses
 * M). */
static int
projected_pc_type (int *none)
{
  char type[64] = "";
  PetscBool set = PETSC_FALSE;
  *none = 0;
  TRY (PetscOptionsGetString (NULL, NULL, "-pc_type", type, sizeof type,
                              &set));
  if (set && strcmp (type, "none") != 0)
    LAC_ERROR (LAC_EINVAL, "-pc_type %s: the projected CG of the contact "
               "solve is preconditioned by the projection around the "
               "multigrid of K_W; -elast_pc_type chooses that one, -pc_type "
               "none leaves it out", type);
  *none = set;
  return LAC_SUCCESS;
}

/* M, the multigrid of K (prefix elast_): lac's contact multigrid with
 * threshold (lac_petsc_mg.h), the PETSc preconditioner -elast_pc_type
 * names, or none (-pc_type none). */
static int
kernel_pc (lac_petsc_saddle *sv, double threshold)
{
  PetscBool set = PETSC_FALSE;
  int none, status;
  if ((status = projected_pc_type (&none)) || none)
    return status;
  TRY (PCCreate (PETSC_COMM_WORLD, &sv->pg));
  TRY (PCSetOptionsPrefix (sv->pg, "elast_"));
  TRY (PCSetOperators (sv->pg, sv->K, sv->K));
  TRY (PetscOptionsHasName (NULL, "elast_", "-pc_type", &set));
  if (!set)
    return lac_petsc_mg_create (sv->pg, threshold, &sv->mg);
  TRY (gamg_setup (sv->pg));                /* the user's preconditioner */
  TRY (PCSetFromOptions (sv->pg));
  return LAC_SUCCESS;
}

/* projected: M (kernel_pc), the solver of B^T B + D (prefix gram_:
 * redundant LU), CG on P K (no prefix). */
static int
create_projected (lac_petsc_saddle *sv, double threshold)
{
  /* each step is a product by K per solve, and more than a few change
   * little (chapter 13): at most PROJECTION_STEPS_MAX */
  const lac_number_spec spec = { 0, PROJECTION_STEPS_MAX, 0, 1, 0 };
  double steps = PROJECTION_STEPS;
  PetscInt nl, n;
  PC pc;
  int status;
  if ((status = lac_petsc_option_number ("-lac_projection_steps", &spec,
                                         "an integer from 0 to 100",
                                         &steps)))
    return status;
  sv->steps = (int) steps;
  if ((status = kernel_pc (sv, threshold))
      || (status = read_tolerances (NULL, &sv->tol)))
    return status;
  if ((status = direct_solver (PETSC_COMM_WORLD, "gram_", PCREDUNDANT,
                              &sv->kg)))
    return status;
  TRY (MatGetLocalSize (sv->K, &nl, NULL));
  TRY (MatGetSize (sv->K, &n, NULL));
  TRY (MatCreateShell (PETSC_COMM_WORLD, nl, nl, n, n, sv, &sv->Ah));
  TRY (MatShellSetOperation (sv->Ah, MATOP_MULT, (void (*) (void))
                             projected_op));
  TRY (KSPCreate (PETSC_COMM_WORLD, &sv->kp));
  TRY (KSPSetOperators (sv->kp, sv->Ah, sv->Ah));
  TRY (KSPSetType (sv->kp, KSPCG));
  TRY (KSPSetNormType (sv->kp, KSP_NORM_UNPRECONDITIONED));
  TRY (KSPSetFromOptions (sv->kp));
  TRY (KSPGetPC (sv->kp, &pc));
  TRY (PCSetType (pc, PCSHELL));
  TRY (PCShellSetContext (pc, sv));
  TRY (PCShellSetApply (pc, projected_pc));
  TRY (MatCreateVecs (sv->B, &sv->sk, &sv->u0));
  TRY (VecDuplicate (sv->sk, &sv->tk));
  TRY (VecDuplicate (sv->u0, &sv->bu));
  TRY (VecDuplicate (sv->u0, &sv->tu));
  TRY (VecDuplicate (sv->u0, &sv->ru));
  return LAC_SUCCESS;
}

/* k x k diagonal matrix of the multipliers' layout (zeros). */
static int
create_diagonal (lac_petsc_saddle *sv, Mat *M)
{
  PetscInt kl, k, l0, l1;
  TRY (MatGetLocalSize (sv->B, NULL, &kl));
  TRY (MatGetSize (sv->B, NULL, &k));
  TRY (MatCreateAIJ (PETSC_COMM_WORLD, kl, kl, k, k, 1, NULL, 0, NULL, M));
  TRY (MatGetOwnershipRange (*M, &l0, &l1));
  for (PetscInt i = l0; i < l1; i++)
    TRY (MatSetValue (*M, i, i, 0.0, INSERT_VALUES));
  TRY (MatAssemblyBegin (*M, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (*M, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* fieldsplit: the nest A = [K B; B^T D], its vectors, the Schur
 * preconditioner Sp, and GMRES with the Schur factorization of
 * PCFIELDSPLIT (no prefix; blocks fieldsplit_u_, fieldsplit_lambda_). */
static int
create_fieldsplit (lac_petsc_saddle *sv, double threshold)
{
  Mat blocks[4];
  PC pc;
  IS is[2];
  char th[40];
  int status;
  static const char *const defaults[][2] = {
    { "-fieldsplit_u_ksp_type", "preonly" },
    { "-fieldsplit_u_pc_type", "gamg" },
    { "-fieldsplit_u_pc_gamg_reuse_interpolation", "true" },
    { "-fieldsplit_lambda_ksp_type", "preonly" },
    { "-fieldsplit_lambda_pc_type", "jacobi" } };
  snprintf (th, sizeof th, "%g,0", threshold);  /* the finest level only */
  if ((threshold >= 0
       && (status = lac_petsc_option_default
                      ("-fieldsplit_u_pc_gamg_threshold", th)))
      || (status = create_diagonal (sv, &sv->D))
      || (status = create_diagonal (sv, &sv->Sp)))
    return status;
  for (size_t i = 0; i < COUNT (defaults); i++)
    if ((status = lac_petsc_option_default (defaults[i][0], defaults[i][1])))
      return status;
  TRY (MatCreateTranspose (sv->B, &sv->Bt));
  blocks[0] = sv->K, blocks[1] = sv->B, blocks[2] = sv->Bt, blocks[3] = sv->D;
  TRY (MatCreateNest (PETSC_COMM_WORLD, 2, NULL, 2, NULL, blocks, &sv->A));
  TRY (MatCreateVecs (sv->A, &sv->x, &sv->b));
  TRY (VecDuplicate (sv->b, &sv->r));
  TRY (VecDuplicate (sv->b, &sv->dx));
  TRY (KSPCreate (PETSC_COMM_WORLD, &sv->ks));
  TRY (KSPSetOperators (sv->ks, sv->A, sv->A));
  TRY (KSPSetType (sv->ks, KSPGMRES));
  TRY (KSPGMRESSetRestart (sv->ks, 100));
  TRY (KSPSetPCSide (sv->ks, PC_RIGHT));
  TRY (KSPSetNormType (sv->ks, KSP_NORM_UNPRECONDITIONED));
  TRY (KSPGetPC (sv->ks, &pc));
  TRY (PCSetType (pc, PCFIELDSPLIT));
  TRY (MatNestGetISs (sv->A, is, NULL));
  TRY (PCFieldSplitSetIS (pc, "u", is[0]));
  TRY (PCFieldSplitSetIS (pc, "lambda", is[1]));
  TRY (PCFieldSplitSetType (pc, PC_COMPOSITE_SCHUR));
  TRY (PCFieldSplitSetSchurFactType (pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER));
  TRY (PCFieldSplitSetSchurPre (pc, PC_FIELDSPLIT_SCHUR_PRE_USER, sv->Sp));
  TRY (KSPSetFromOptions (sv->ks));
  return read_tolerances (NULL, &sv->tol);
}

int
lac_petsc_saddle_create (lac_saddle_method method, lac_saddle_mat K,
                         lac_saddle_mat B, double threshold,
                         lac_petsc_saddle **out)
{
  lac_petsc_saddle *sv;
  int status, rank;
  *out = NULL;
  if (!(sv = lac_calloc (1, sizeof *sv)))
    LAC_ERROR (LAC_ENOMEM, "the Krylov solvers");
  sv->method = method;
  sv->K = K;
  sv->B = B;
  lac_petsc_rank (&rank, &sv->size);
  status = !B ? create_alone (sv) : method == LAC_SADDLE_FIELDSPLIT
           ? create_fieldsplit (sv, threshold)
           : create_projected (sv, threshold);
  if (status)
    {
      lac_petsc_saddle_free (sv);
      return status;
    }
  *out = sv;
  return LAC_SUCCESS;
}

/* ---- new values --------------------------------------------------------- */

/* The weight w of the Jacobi steps: 1 / (a bound of the largest
 * eigenvalue of D^-1 K, Gershgorin's: max_i sum_j |k_ij| / k_ii), so
 * that every step keeps Z's directions those of a positive K^-1. */
static int
jacobi_weight (lac_petsc_saddle *sv, PetscReal *w)
{
  PetscInt r0, r1, nc;
  const PetscScalar *a, *dinv;
  PetscReal g = 0, gall;
  TRY (MatGetOwnershipRange (sv->K, &r0, &r1));
  TRY (VecGetArrayRead (sv->dinv, &dinv));
  for (PetscInt i = r0; i < r1; i++)
    {
      PetscReal sum = 0;
      TRY (MatGetRow (sv->K, i, &nc, NULL, &a));
      for (PetscInt q = 0; q < nc; q++)
        sum += PetscAbsScalar (a[q]);
      TRY (MatRestoreRow (sv->K, i, &nc, NULL, &a));
      g = PetscMax (g, sum * PetscAbsScalar (dinv[i - r0]));
    }
  TRY (VecRestoreArrayRead (sv->dinv, &dinv));
  if (MPI_Allreduce (&g, &gall, 1, MPIU_REAL, MPI_MAX, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Allreduce of the Jacobi weight failed");
  *w = gall > 0 ? 1 / gall : 1;
  return LAC_SUCCESS;
}

/* Z ~ K^-1 B by `steps` Jacobi steps from Y = D^-1 B,
 *   Z += w D^-1 (B - K Z),  i.e.  Z = -w D^-1 (K Z) + Z + w Y,
 * made in the product K Z, whose pattern holds Z's and Y's (K has its
 * diagonal): no matrix of a third pattern (sparse: each step widens a
 * column by one ring of nodes); then the LU of G_Z = B^T Z + D
 * (projected_pc). */
static int
smoothed_constraints (lac_petsc_saddle *sv, Vec d)
{
  PetscReal w = 1;
  Mat Y;
  int status;
  if (!sv->dinv)
    TRY (MatCreateVecs (sv->K, NULL, &sv->dinv));
  TRY (MatGetDiagonal (sv->K, sv->dinv));
  TRY (VecReciprocal (sv->dinv));
  if ((status = jacobi_weight (sv, &w)))
    return status;
  TRY (MatDestroy (&sv->Z));
  TRY (MatDuplicate (sv->B, MAT_COPY_VALUES, &Y));
  TRY (MatDiagonalScale (Y, sv->dinv, NULL));              /* D^-1 B */
  TRY (MatDuplicate (Y, MAT_COPY_VALUES, &sv->Z));
  for (int j = 0; j < sv->steps; j++)
    {
      Mat KZ;
      TRY (MatMatMult (sv->K, sv->Z, MAT_INITIAL_MATRIX, PETSC_DEFAULT,
                       &KZ));
      TRY (MatDiagonalScale (KZ, sv->dinv, NULL));
      TRY (MatScale (KZ, -w));
      TRY (MatAXPY (KZ, 1.0, sv->Z, SUBSET_NONZERO_PATTERN));
      TRY (MatAXPY (KZ, w, Y, SUBSET_NONZERO_PATTERN));
      TRY (MatDestroy (&sv->Z));
      sv->Z = KZ;
    }
  TRY (MatDestroy (&Y));
  TRY (MatProductClear (sv->Z));        /* no product data kept for reuse */
  TRY (MatDestroy (&sv->Gz));
  TRY (MatTransposeMatMult (sv->B, sv->Z, MAT_INITIAL_MATRIX, PETSC_DEFAULT,
                            &sv->Gz));
  TRY (MatProductClear (sv->Gz));
  TRY (MatDiagonalSet (sv->Gz, d, ADD_VALUES));
  if (!sv->kz && (status = direct_solver (PETSC_COMM_WORLD, "gramz_",
                                          PCREDUNDANT, &sv->kz)))
    return status;
  TRY (KSPSetOperators (sv->kz, sv->Gz, sv->Gz));
  if (sv->size == 1)
    return LAC_SUCCESS;
  TRY (MatDestroy (&sv->Zl));                  /* N > 1: local copies */
  TRY (MatMPIAIJGetLocalMat (sv->Z, MAT_INITIAL_MATRIX, &sv->Zl));
  TRY (MatDestroy (&sv->Gzl));
  TRY (MatCreateRedundantMatrix (sv->Gz, sv->size, MPI_COMM_NULL,
                                 MAT_INITIAL_MATRIX, &sv->Gzl));
  if (!sv->kzl
      && (status = direct_solver (PetscObjectComm ((PetscObject) sv->Gzl),
                                  "gramz_local_", PCLU, &sv->kzl)))
    return status;
  TRY (KSPSetOperators (sv->kzl, sv->Gzl, sv->Gzl));
  return LAC_SUCCESS;
}

/* projected: G = B^T B + D, its solver, Z and G_Z, and the multigrid of
 * the new K. */
static int
update_projected (lac_petsc_saddle *sv, Vec d)
{
  int status;
  TRY (MatTransposeMatMult (sv->B, sv->B, sv->G ? MAT_REUSE_MATRIX
                            : MAT_INITIAL_MATRIX, PETSC_DEFAULT, &sv->G));
  TRY (MatDiagonalSet (sv->G, d, ADD_VALUES));
  TRY (KSPSetOperators (sv->kg, sv->G, sv->G));
  if ((sv->size > 1 && (status = update_local (sv)))
      || (sv->steps && (status = smoothed_constraints (sv, d))))
    return status;
  if (sv->mg)
    return lac_petsc_mg_update (sv->mg, sv->K, sv->B);
  if (sv->pg)
    TRY (PCSetOperators (sv->pg, sv->K, sv->K));
  return LAC_SUCCESS;
}

/* fieldsplit: D, Sp and the nest that holds them. */
static int
update_fieldsplit (lac_petsc_saddle *sv, Vec d, Vec sp)
{
  TRY (MatDiagonalSet (sv->D, d, INSERT_VALUES));
  TRY (MatDiagonalSet (sv->Sp, sp, INSERT_VALUES));
  TRY (MatAssemblyBegin (sv->A, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (sv->A, MAT_FINAL_ASSEMBLY));
  TRY (KSPSetOperators (sv->ks, sv->A, sv->A));
  return LAC_SUCCESS;
}

int
lac_petsc_saddle_update (lac_petsc_saddle *sv, lac_saddle_vec d,
                         lac_saddle_vec sp)
{
  if (sv->ku)
    {
      TRY (KSPSetOperators (sv->ku, sv->K, sv->K));
      return LAC_SUCCESS;
    }
  if (!d || (sv->ks && !sp))
    LAC_ERROR (LAC_EINVAL, "the diagonal of the multipliers is missing");
  return sv->ks ? update_fieldsplit (sv, d, sp) : update_projected (sv, d);
}

#else /* LAC_HAVE_PETSC */

typedef int lac_petsc_saddle_unused;   /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */