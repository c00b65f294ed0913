/* lac_petsc_internal.h -- the petsc strategy's state, shared by its
 *                         object, layout, build and solves (lac_petsc.c),
 *                         the values for the statuses
 *                         (lac_petsc_values.c) and the other processes'
 *                         loop (lac_petsc_serve.c); not part of the API
 */
#ifndef LAC_PETSC_INTERNAL_H
#define LAC_PETSC_INTERNAL_H

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>
#include "fem/lac_assembly_dist.h"
#include "linalg/lac_petsc_saddle.h"
#include "solve/lac_petsc.h"

enum { PROJECTED = LAC_SADDLE_PROJECTED,     /* the contact solvers  */
       FIELDSPLIT = LAC_SADDLE_FIELDSPLIT };  /* (-lac_contact)        */

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

typedef struct lac_petsc
{
  double omega;                    /* W_i = omega / s_i                   */
  double threshold;                /* the multigrid's, on contact nodes   */
  int rank, size, root;            /* root: rank 0                        */
  size_t n, k;
  int mode, coords_given, built, cells;   /* cells: K from the cells     */
  PetscInt bs, r0, r1, l0, l1;     /* block size; own rows of U, lambda   */
  lac_dist *dist;                  /* owned: the rows, the cells, C       */
  /* the root's: the whole system */
  const lac_contact_system *sys;   /* borrowed                            */
  const lac_dist_source *src;      /* borrowed: the cells of K, or NULL   */
  int dim;                         /* components per node (coordinates)   */
  const double *coords;            /* borrowed, n, or NULL                */
  unsigned long long hK, hC;       /* patterns the matrices were made for */
  int have_stat, new_numbers;
  double *xv;                      /* owned, n: scratch                   */
  size_t na, *idx;                 /* owned, k: the active multipliers    */
  double *rhs, *lst;               /* owned, k                            */
  /* every process */
  double *s;                       /* owned, k: c_i^T diag(K)^-1 c_i      */
  double knorm;                    /* ||K||_inf (before the kappa)        */
  double *w, *wold, *dw;           /* owned, k: W, the W in K_W, change   */
  char *stat;                      /* owned, k: statuses of the matrices  */
  double kappa;                    /* the mean of diag(K): PETSc's K_W and
                                      f_W are divided by it              */
  Mat Kw, B;                       /* K_W; B = -C_A (n x k)               */
  lac_petsc_saddle *sv;            /* owned: the Krylov solvers of (*W)   */
  Vec fw, xu, ru;                  /* U's layout: f_W, U, scratch         */
  Vec gk, lk, dk, pk;              /* the multipliers': -g_A, lambda, D's
                                      diagonal, the Schur preconditioner's */
  Vec useq, lseq;                  /* U, lambda whole on the root (empty
                                      elsewhere)                          */
  VecScatter gu, gl;               /* root -> distributed (forward)       */
  lac_solve_counts counts;
  char method[200];
} lac_petsc;

/* The PETSc objects and the layout freed (every process), and the arrays
 * of the root's system and of the weights. */
void lac_petsc_free_petsc (lac_petsc *s);
void lac_petsc_free_arrays (lac_petsc *s);

/* The collective steps of the root's commands (all processes; the root's
 * data, NULL on the others): build the sizes and patterns of c; the
 * values for the statuses (lac_petsc_values.c); one solve of (*W); K_W x.
 * lac_petsc_update: the root's side of the values, when the statuses or
 * the numbers changed. */
int lac_petsc_build (lac_petsc *s, const lac_petsc_command *c,
                     const lac_contact_system *sys);
int lac_petsc_update_values (lac_petsc *s, const lac_petsc_command *c,
                             const lac_contact_system *sys);
int lac_petsc_update (lac_petsc *s, const char *active);
int lac_petsc_step_solve (lac_petsc *s, const lac_petsc_command *c,
                          const double *fw, const double *gl, double *U,
                          double *lambda);
int lac_petsc_step_kmul (lac_petsc *s, const double *x, double *y);

#endif /* LAC_HAVE_PETSC */

#endif /* LAC_PETSC_INTERNAL_H */
