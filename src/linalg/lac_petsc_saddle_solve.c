/* lac_petsc_saddle_solve.c -- the solves of a stiffness under linear
 *                             constraints: K alone by CG, the projected
 *                             CG from u0 to u and the multipliers,
 *                             fieldsplit GMRES with one correction, and
 *                             their true residuals
 *                             (see lac_petsc_saddle.h)      [chapter 13]
 */
#ifdef LAC_HAVE_PETSC

#include <math.h>
#include <stdio.h>
#include "base/lac_status.h"
#include "linalg/lac_petsc_saddle_internal.h"

#define CORRECTION_RTOL 1e-6  /* fieldsplit: of its correction step      */

/* ---- the solves --------------------------------------------------------- */

/* After KSPSolve: iterations and reason into c; the relative true
 * residual res is the caller's. */
static int
check_ksp (KSP ksp, double res, const char *what, lac_saddle_counts *c)
{
  KSPConvergedReason why;
  PetscInt its;
  TRY (KSPGetIterationNumber (ksp, &its));
  TRY (KSPGetConvergedReason (ksp, &why));
  c->iterations += (int) its;
  c->solves++;
  c->residual = res;
  if (why < 0)
    LAC_ERROR (why == KSP_DIVERGED_INDEFINITE_PC
               || why == KSP_DIVERGED_INDEFINITE_MAT ? LAC_ESING
               : LAC_EMAXITER, "%s: %s after %d iterations, relative "
               "residual %.3g", what, KSPConvergedReasons[why], (int) its,
               res);
  return LAC_SUCCESS;
}

/* ||b - A x|| / ||b|| (r: scratch). */
static int
true_residual (Mat A, Vec b, Vec x, Vec r, double *res)
{
  PetscReal nb, nr;
  TRY (MatMult (A, x, r));
  TRY (VecAYPX (r, -1.0, b));
  TRY (VecNorm (r, NORM_2, &nr));
  TRY (VecNorm (b, NORM_2, &nb));
  *res = nb > 0 ? nr / nb : nr;
  return LAC_SUCCESS;
}

/* K alone: K u = f to rtol (u: the start and the solution). */
static int
solve_alone (lac_petsc_saddle *sv, Vec f, double rtol, const char *what,
             Vec u, lac_saddle_counts *c)
{
  double res;
  int status;
  TRY (KSPSetInitialGuessNonzero (sv->ku, PETSC_TRUE));
  TRY (lac_petsc_saddle_set_tolerances (sv, sv->ku, rtol, 0.0));
  TRY (KSPSolve (sv->ku, f, u));
  if ((status = true_residual (sv->K, f, u, sv->ru, &res)))
    return status;
  return check_ksp (sv->ku, res, what, c);
}

/* projected, before CG: u0 = B (B^T B + D)^-1 g with B^T u0 = g where D
 * = 0, the right-hand side P (f - K u0) in bu, the start P (u - u0). */
static PetscErrorCode
projected_start (lac_petsc_saddle *sv, Vec f, Vec g, Vec u)
{
  PetscCall (KSPSolve (sv->kg, g, sv->sk));
  PetscCall (MatMult (sv->B, sv->sk, sv->u0));
  PetscCall (MatMult (sv->K, sv->u0, sv->bu));
  PetscCall (VecAYPX (sv->bu, -1.0, f));
  PetscCall (lac_petsc_saddle_project (sv, sv->bu));
  PetscCall (VecAXPY (u, -1.0, sv->u0));
  return lac_petsc_saddle_project (sv, u);
}

/* projected, after CG: u = u0 + x, l = (B^T B + D)^-1 B^T (f - K u), and
 * the relative true residual, each block in its own unit (the larger of
 * the two): the forces f - K u - B l against f (2-norms, as the CG's),
 * the constraints g - B^T u against |g| + |B^T| |u| (max-norms). */
static PetscErrorCode
projected_finish (lac_petsc_saddle *sv, Vec f, Vec g, Vec u, Vec l,
                  double *res)
{
  PetscReal r1, r2, b1, b2, nB, nU;
  PetscCall (VecAXPY (u, 1.0, sv->u0));
  PetscCall (MatMult (sv->K, u, sv->ru));
  PetscCall (VecAYPX (sv->ru, -1.0, f));
  PetscCall (MatMultTranspose (sv->B, sv->ru, sv->tk));
  PetscCall (KSPSolve (sv->kg, sv->tk, l));
  PetscCall (MatMult (sv->B, l, sv->tu));
  PetscCall (VecAXPY (sv->ru, -1.0, sv->tu));
  PetscCall (VecNorm (sv->ru, NORM_2, &r1));
  PetscCall (MatMultTranspose (sv->B, u, sv->tk));
  PetscCall (VecAYPX (sv->tk, -1.0, g));
  PetscCall (VecNorm (sv->tk, NORM_INFINITY, &r2));
  PetscCall (VecNorm (f, NORM_2, &b1));
  PetscCall (VecNorm (g, NORM_INFINITY, &b2));
  PetscCall (MatNorm (sv->B, NORM_1, &nB));              /* |B^T|_inf */
  PetscCall (VecNorm (u, NORM_INFINITY, &nU));
  *res = fmax (r1 / fmax (b1, 1e-300), r2 / fmax (b2 + nB * nU, 1e-300));
  return 0;
}

/* projected: CG on the null space of B^T, to rtol of the forces. */
static int
solve_projected (lac_petsc_saddle *sv, Vec f, Vec g, double rtol,
                 const char *what, Vec u, Vec l, lac_saddle_counts *c)
{
  PetscReal b1;
  double res = 0;
  TRY (projected_start (sv, f, g, u));
  TRY (VecNorm (f, NORM_2, &b1));           /* the CG's residual: forces */
  TRY (KSPSetInitialGuessNonzero (sv->kp, PETSC_TRUE));
  TRY (lac_petsc_saddle_set_tolerances (sv, sv->kp, 0.0, rtol * b1));
  TRY (KSPSolve (sv->kp, sv->bu, u));
  TRY (projected_finish (sv, f, g, u, l, &res));
  return check_ksp (sv->kp, res, what, c);
}

/* fieldsplit: the blocks of a vector of A, in (to = 1) or out of it. */
static int
nest_blocks (lac_petsc_saddle *sv, Vec v, Vec vu, Vec vl, int to)
{
  IS is[2];
  Vec part[2] = { vu, vl }, sub;
  TRY (MatNestGetISs (sv->A, is, NULL));
  for (int j = 0; j < 2; j++)
    {
      TRY (VecGetSubVector (v, is[j], &sub));
      TRY (to ? VecCopy (part[j], sub) : VecCopy (sub, part[j]));
      TRY (VecRestoreSubVector (v, is[j], &sub));
    }
  return LAC_SUCCESS;
}

/* fieldsplit: A as a whole by GMRES, then one correction: GMRES
 * satisfies B^T u = g only to its tolerance relative to the forces (the
 * projected CG exactly), so x += A^-1 r once, to CORRECTION_RTOL. */
static int
solve_fieldsplit (lac_petsc_saddle *sv, Vec f, Vec g, double rtol,
                  const char *what, Vec u, Vec l, lac_saddle_counts *c)
{
  char part[200];
  double res;
  int status;
  if ((status = nest_blocks (sv, sv->b, f, g, 1))
      || (status = nest_blocks (sv, sv->x, u, l, 1)))
    return status;
  TRY (KSPSetInitialGuessNonzero (sv->ks, PETSC_TRUE));
  TRY (lac_petsc_saddle_set_tolerances (sv, sv->ks, rtol, 0.0));
  TRY (KSPSolve (sv->ks, sv->b, sv->x));
  if ((status = true_residual (sv->A, sv->b, sv->x, sv->r, &res))
      || (status = check_ksp (sv->ks, res, what, c)))
    return status;
  TRY (KSPSetInitialGuessNonzero (sv->ks, PETSC_FALSE));
  TRY (lac_petsc_saddle_set_tolerances (sv, sv->ks, CORRECTION_RTOL,
                                        0.0));
  TRY (KSPSolve (sv->ks, sv->r, sv->dx));
  TRY (VecAXPY (sv->x, 1.0, sv->dx));
  snprintf (part, sizeof part, "%s, correction", what);
  if ((status = true_residual (sv->A, sv->b, sv->x, sv->r, &res))
      || (status = check_ksp (sv->ks, res, part, c)))
    return status;
  return nest_blocks (sv, sv->x, u, l, 0);
}

int
lac_petsc_saddle_solve (lac_petsc_saddle *sv, lac_saddle_vec f,
                        lac_saddle_vec g, double rtol, const char *what,
                        lac_saddle_vec u, lac_saddle_vec l,
                        lac_saddle_counts *c)
{
  *c = (lac_saddle_counts) { 0, 0, 0.0 };
  if (sv->ku)
    return solve_alone (sv, f, rtol, what, u, c);
  if (!g || !l)
    LAC_ERROR (LAC_EINVAL, "%s: the constraints or the multipliers are "
               "missing", what);
  if (sv->kp)
    return solve_projected (sv, f, g, rtol, what, u, l, c);
  return solve_fieldsplit (sv, f, g, rtol, what, u, l, c);
}

int
lac_petsc_saddle_types (const lac_petsc_saddle *sv, char *krylov, char *pc,
                        size_t size)
{
  KSPType kt;
  PCType pt;
  PC p;
  PetscBool set;
  TRY (KSPGetType (sv->ks ? sv->ks : sv->kp ? sv->kp : sv->ku, &kt));
  snprintf (krylov, size, "%s", kt);
  if (sv->ks)
    {
      snprintf (pc, size, "gamg");
      TRY (PetscOptionsGetString (NULL, NULL, "-fieldsplit_u_pc_type", pc,
                                  size, &set));
      return LAC_SUCCESS;
    }
  if (sv->mg)
    {
      snprintf (pc, size, "%s", LAC_PETSC_MG_NAME);
      return LAC_SUCCESS;
    }
  if (sv->kp && !sv->pg)
    {
      snprintf (pc, size, "none");
      return LAC_SUCCESS;
    }
  if (sv->pg)
    p = sv->pg;
  else
    TRY (KSPGetPC (sv->ku, &p));
  TRY (PCGetType (p, &pt));
  snprintf (pc, size, "%s", pt);
  return LAC_SUCCESS;
}

#else /* LAC_HAVE_PETSC */

typedef int lac_petsc_saddle_solve_unused;   /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
