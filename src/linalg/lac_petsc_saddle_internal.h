/* lac_petsc_saddle_internal.h -- the Krylov solvers' state, shared by
 *                                their set-up and new values
 *                                (lac_petsc_saddle.c) and their solves
 *                                (lac_petsc_saddle_solve.c); not part of
 *                                the library's interface
 */
#ifndef LAC_PETSC_SADDLE_INTERNAL_H
#define LAC_PETSC_SADDLE_INTERNAL_H

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>
#include "linalg/lac_petsc_env.h"
#include "linalg/lac_petsc_mg.h"
#include "linalg/lac_petsc_saddle.h"

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

/* The tolerances of a Krylov method the user gave (-ksp_rtol, -ksp_atol,
 * -ksp_max_it with its prefix): they win over lac's, as PETSc's options
 * win over a program's settings. */
typedef struct
{
  PetscReal rtol, atol;
  PetscInt maxit;
  PetscBool has_rtol, has_atol, has_maxit;
} user_tolerances;

struct lac_petsc_saddle
{
  lac_saddle_method method;
  int size;                        /* MPI processes                      */
  Mat K, B;                        /* borrowed; B NULL: K alone          */
  KSP ku;                          /* K alone: CG + GAMG                 */
  Vec ru;                          /* K alone, projected: U's layout     */
  user_tolerances tol;             /* the user's, of the Krylov method   */
  /* projected */
  PC pg;                           /* the multigrid of K (NULL: none,
                                      -pc_type none)                     */
  lac_petsc_mg *mg;                /* owned: lac's contact multigrid in
                                      pg (NULL: a PETSc PC of -elast_)   */
  KSP kg, kp;                      /* B^T B + D (LU); CG on P K           */
  Mat G, Ah;                       /* B^T B + D; P K (shell)             */
  Vec u0, bu, tu, tk, sk;          /* U's layout; the multipliers'       */
  Mat Bl, Gl;                      /* N > 1: the own rows of B, a copy
                                      of G                               */
  KSP kl;                          /*   its LU (prefix gram_local_)      */
  int steps;                       /* Jacobi steps of Z (0: P only)      */
  Mat Z, Gz;                       /* Z ~ K^-1 B; B^T Z + D              */
  KSP kz;                          /*   its LU (prefix gramz_)           */
  Mat Zl, Gzl;                     /* N > 1: Z's own rows, a copy of G_Z */
  KSP kzl;                         /*   its LU (prefix gramz_local_)     */
  Vec dinv;                        /* diag(K)^-1                         */
  Vec vl, ul, tl, tg, sl;          /*   their vectors (own rows; k)      */
  /* fieldsplit */
  Mat Bt, D, Sp, A;                /* A = [K B; B^T D]                    */
  KSP ks;                          /* GMRES + PCFIELDSPLIT               */
  Vec b, x, r, dx;                 /* A's layout                         */
};

/* ksp's tolerances: lac's rtol, atol and iterations, but those the user
 * gave (sv->tol). */
int lac_petsc_saddle_set_tolerances (const lac_petsc_saddle *sv, KSP ksp,
                                     PetscReal rtol, PetscReal atol);
/* v = P v = v - B (B^T B + D)^-1 B^T v (projected). */
PetscErrorCode lac_petsc_saddle_project (lac_petsc_saddle *sv, Vec v);

#endif /* LAC_HAVE_PETSC */

#endif /* LAC_PETSC_SADDLE_INTERNAL_H */
