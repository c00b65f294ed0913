/* lac_strategy.h -- solve the LAC system for a given active set
 *                                                 [LAC (17), Alg. 1 l. 21]
 *
 * Every iteration of Algorithm 1 (solve/lac_newton.h), small strain or
 * large deformation, solves the saddle-point system (*) of
 * solve/lac_system.h for the statuses of the moment.  How is chosen once
 * per scene, from the problem:
 *
 *   dense      (d) a dense LU of the whole system: classroom sizes, matrices
 *                  a student can print (solve/lac_saddle.h);
 *   schur      (a) every body held by its Dirichlet conditions: K = L L^T
 *                  once, the columns of S = C^T K^{-1} C of the active
 *                  multipliers computed the first time they are needed
 *                  and kept, the multipliers by a dense Cholesky of S_AA
 *                  (solve/lac_schur.h);
 *   augmented  (b) the Cholesky factor of K + C_A W C_A^T, positive
 *                  definite as soon as the active multipliers hold the
 *                  bodies (also those held by contact alone), the
 *                  multipliers by conjugate gradients in about ten
 *                  iterations (solve/lac_augmented.h);
 *   split     (b') the same augmentation on the bodies held by contact
 *                  alone only: one Cholesky factor for the bodies held by
 *                  their Dirichlet conditions (once per scene), one for
 *                  the others plus C_S,A W C_S,A^T (when the statuses
 *                  change), the bodies never joined in one factor; the
 *                  multipliers by GMRES in about ten iterations
 *                  (solve/lac_split.h);
 *   saddle     (c) UMFPACK's LU of the whole system, METIS ordering: the
 *                  fallback and the reference (solve/lac_saddle.h);
 *   petsc      (e) no factorization: the augmented system of (b) by
 *                  conjugate gradients on the null space of C_A^T,
 *                  preconditioned by algebraic multigrid on
 *                  K + C_A W C_A^T, on one or N MPI processes
 *                  (solve/lac_petsc.h; optional: a build without PETSc
 *                  says how to install it).
 *
 * Each way is a type (lac_strategy_type, in the spirit of GSL's
 * gsl_*_type and PETSc's KSPType): its operations (lac_strategy_ops of
 * solve/lac_system.h, one file each) and its properties, one row of
 * lac_strategy_table.  The choice, the refusals and the fallback read the
 * properties; nothing outside this module asks which strategy runs.
 * Bodies held by contact alone are known before anything is factorized
 * (the system's N): (a) is refused for them, (b') for scenes without
 * them (nothing to augment: the multipliers would be left to GMRES on S
 * itself).  `auto` takes the first row that applies up to its size:
 * dense for n + k <= LAC_STRATEGY_DENSE_MAX, else schur when every body
 * is held (one factorization for the whole active-set iteration), split
 * when a body is held by contact alone (chapter 07 has the measurements).
 * Before the sizes, two facts of the run (lac_strategy_context) come
 * first: on more than one MPI process auto takes the first row that
 * solves on the processes (petsc), and on one process, when the factor
 * of a direct strategy is estimated not to fit in memory, the first row
 * that factorizes nothing (petsc; chapter 13, section 4).
 * Before (b) or (b') factorizes, lac_system_check_held says whether the
 * active multipliers hold the bodies (else a message naming the body and
 * its free motion, never NaN).  If a Cholesky factorization fails all the
 * same (a large-deformation tangent past a limit point), the type's
 * factor_failed says so and the strategy falls back to (c) for the rest
 * of its life and says so (lac_strategy_fallback): unasked for (b) and
 * (b'); for (a) only when allowed (lac_strategy_allow_fallback: the
 * large-deformation loop), a linear scene reporting a K that is not
 * positive definite as an error (LAC_ESING), its caller having said every
 * body was held.  Every type solves a system without contact too (k = 0:
 * K U = F).  A new strategy is one file and one row of the table
 * (tests/unit/t503-strategy-table.c registers one of its own).
 *
 * After the solve, the residual of (*) is computed in full and up to
 * three steps of iterative refinement (the same solver on the residual,
 * an inner Krylov method to 1e-3 only) bring the backward error to
 * LAC_STRATEGY_TOL where they can: without them the augmented strategy
 * leaves errors of a few 1e-12 on lambda (K_W's condition number is
 * omega times K's), with one of them the Taylor patch tests are exact to
 * 1e-14.  A type that factorizes nothing (petsc) refines only above a
 * backward error of 1e-11 (two steps at most): a step costs half a
 * Krylov solve, and the projected CG to 1e-10 (true residual) usually
 * gives 1e-12 and lambda to about 1e-10 at once.
 *
 * Usage:
 *   lac_strategy *s = lac_strategy_alloc (kind);
 *   lac_strategy_set (s, &sys);          (new numbers: set again)
 *   lac_strategy_solve (s, active, U, lambda);   (U, lambda: warm start)
 *   lac_strategy_free (s);
 * Ownership: the system is borrowed from set until the next set or free,
 * the type from alloc until free.
 */
#ifndef LAC_STRATEGY_H
#define LAC_STRATEGY_H

#include <stddef.h>
#include "solve/lac_system.h"

typedef enum
{
  LAC_STRATEGY_AUTO, LAC_STRATEGY_DENSE, LAC_STRATEGY_SCHUR,
  LAC_STRATEGY_AUGMENTED, LAC_STRATEGY_SADDLE, LAC_STRATEGY_PETSC,
  LAC_STRATEGY_SPLIT, LAC_NSTRATEGIES
} lac_strategy_kind;

#define LAC_STRATEGY_DENSE_MAX 600   /* n + k of the dense strategy     */
#define LAC_STRATEGY_ITERATIVE_BYTES 9e8  /* a 3D run of linear cells
                                        with a Cholesky factor estimated
                                        at this many bytes: on one
                                        process petsc takes at most about
                                        1.4 times its time with a quarter
                                        of its memory (chapter 13,
                                        section 4; quadratic cells: 3 to
                                        4 times the time, never)        */
#define LAC_STRATEGY_TOL 1e-15       /* backward error aimed at: a few
                                        units of rounding (2.2e-16)     */

/* What a type factorizes (the memory a mesh needs, run/lac_run_mesh.c);
 * NONE: Krylov methods to a tolerance. */
typedef enum
{
  LAC_FACTOR_NONE, LAC_FACTOR_DENSE, LAC_FACTOR_LU, LAC_FACTOR_CHOLESKY
} lac_strategy_factor;

/* The scenes a type applies to: any, every body held by its Dirichlet
 * conditions (nfree = 0: K positive definite), a body held by contact
 * alone (nfree > 0). */
typedef enum
{
  LAC_BODIES_ANY, LAC_BODIES_HELD, LAC_BODIES_FLOATING
} lac_strategy_bodies;

/* A strategy's type: a row of lac_strategy_table, or the caller's
 * (lac_strategy_alloc_type). */
typedef struct lac_strategy_type
{
  const char *name;             /* first: the scene keys read the names */
  const lac_strategy_ops *ops;  /* NULL: auto (a choice, not a type)     */
  lac_strategy_bodies bodies;   /* the others: lac_strategy_choose
                                   refuses it                           */
  size_t auto_upto;             /* auto takes it up to n + k unknowns
                                   (0: never)                           */
  lac_strategy_factor factor;   /* NONE: the Krylov counts are reported,
                                   refinement only above 1e-11          */
  int falls_back;               /* a failed Cholesky factorization falls
                                   back to saddle unasked               */
  int processes;                /* solves on N MPI processes: MPI and
                                   PETSc started before the scene, the
                                   processes 1..N-1 serving process 0   */
  double auto_from_bytes[2];    /* in 3D on one process, auto takes it
                                   when a run with a Cholesky factor is
                                   estimated at this many bytes or more,
                                   [0] linear cells, [1] quadratic: where
                                   the factor's memory costs more than
                                   its time saves (0: never)            */
} lac_strategy_type;

/* The types in lac_strategy_kind order, auto first, ended by a row whose
 * name is NULL.  A new strategy is one file (its lac_strategy_ops) and
 * one row here (and its kind). */
extern const lac_strategy_type lac_strategy_table[];

/* "auto" | "dense" | "schur" | "augmented" | "saddle" | "petsc" |
 * "split" -> kind, -1 if unknown; and back. */
int lac_strategy_from_name (const char *name);
const char *lac_strategy_name (lac_strategy_kind kind);
/* The row of a concrete kind; NULL for auto or an unknown kind. */
const lac_strategy_type *lac_strategy_type_of (int kind);
/* The strategy for a system of n displacements, k multipliers and nfree
 * rigid motions left free by the Dirichlet conditions, asked for `want`
 * (auto: the rule above).  LAC_NSTRATEGIES with a message if `want`
 * cannot solve such a system (its bodies property, when k > 0: without
 * contact every type solves K U = F). */
lac_strategy_kind lac_strategy_choose (lac_strategy_kind want, size_t n,
                                       size_t k, size_t nfree);

/* What auto reads of the run besides the system (the caller's: the MPI
 * processes from linalg/lac_petsc_env.h, the memory from the size of the
 * mesh, run/lac_run_mesh.h). */
typedef struct lac_strategy_context
{
  int processes;      /* MPI processes of the run (1: one)                */
  int factor_fits;    /* 0: a direct factor is estimated not to fit in
                         memory and a type that factorizes nothing can
                         run (lac built with PETSc); 1 otherwise          */
  int dim;            /* of the mesh (0: unknown)                         */
  int order;          /* of its cells: 1 linear, 2 quadratic (0: unknown) */
  double cholesky_bytes;  /* the run's memory estimated with a Cholesky
                         factor, when a type that factorizes nothing can
                         run (lac built with PETSc); 0 otherwise          */
} lac_strategy_context;

/* lac_strategy_choose in the run described by ctx (NULL: one process,
 * the factor fits -- lac_strategy_choose): auto takes a row that solves
 * on the processes when ctx->processes > 1, else one that factorizes
 * nothing when !ctx->factor_fits, else in 3D the first row whose
 * auto_from_bytes for the cells' order ctx->cholesky_bytes reaches, else
 * the rule of the sizes. */
lac_strategy_kind lac_strategy_choose_in (lac_strategy_kind want, size_t n,
                                          size_t k, size_t nfree,
                                          const lac_strategy_context *ctx);

/* The first type of the table that factorizes as `factor` and applies to
 * nfree rigid motions left free (a scene's [scene] solver: dense,
 * UMFPACK's LU or CHOLMOD's Cholesky); saddle if none does. */
lac_strategy_kind lac_strategy_choose_factor (lac_strategy_factor factor,
                                              size_t nfree);

typedef struct lac_strategy lac_strategy;     /* opaque */

typedef struct lac_strategy_counts
{
  int solves;          /* solves of (*) asked for                          */
  int factorizations;  /* numeric factorizations                           */
  int analyses;        /* symbolic analyses (orderings)                    */
  int substitutions;   /* forward and back substitutions (schur, augmented) */
  int iterations;      /* conjugate-gradient iterations                    */
  int refinements;     /* refinement steps                                 */
  double backward_error; /* of the last solve, after refinement            */
  double rcond;        /* condition estimate of the last factorization     */
  double time_factor;  /* seconds in analyses and factorizations          */
  double flops;        /* of the numeric factorizations, summed           */
  double time_solve;   /* seconds in the rest of set and of the solves    */
  int last_iterations; /* Krylov iterations of the last solve of (*),
                          before refinement (schur, augmented, petsc)      */
  double last_residual; /* and its relative residual (petsc: the true one) */
  int processes;       /* MPI processes that solve (1: no MPI)           */
} lac_strategy_counts;

/* kind: a concrete one (from lac_strategy_choose), not auto. */
lac_strategy *lac_strategy_alloc (lac_strategy_kind kind);
/* Any type, the table's or the caller's (borrowed until free). */
lac_strategy *lac_strategy_alloc_type (const lac_strategy_type *type);
void lac_strategy_free (lac_strategy *s);      /* NULL allowed */
/* allow = 1: a failed Cholesky factorization falls back to saddle also
 * for a type that does not do it unasked (schur: the large-deformation
 * loop); 0: only for those that do (the default). */
void lac_strategy_allow_fallback (lac_strategy *s, int allow);
int lac_strategy_set (lac_strategy *s, const lac_contact_system *sys);
/* U, lambda of (*) for the statuses `active` (1: in contact); on entry
 * they are the start (warm start of the conjugate gradients), on return
 * the solution, lambda_i = 0 where inactive. */
int lac_strategy_solve (lac_strategy *s, const char *active, double *U,
                        double *lambda);
/* As a preconditioner (the consistent step of large deformations,
 * solve/lac_consistent.h): lac_strategy_reset is lac_strategy_set, except
 * that the schur strategy keeps its factorization of K (the last set's):
 * only what depends on C is made again, and the solves are those of the
 * old K with the new C; *kept says whether the factorization was kept
 * (the other strategies factor K + C_A W C_A^T or the whole system, which
 * depend on C, so they factor again).  With same_columns (the caller
 * says that the columns of sys->C are the constraints of the last set's,
 * in the same order) schur keeps the older C as well, and the columns of
 * C_A^T K^-1 C_A it made: the solves are those of the older system, none
 * is made again.  lac_strategy_solve_rhs is one solve of (*) with the
 * right-hand sides f, g instead of F, G, without the check of the bodies
 * held and without refinement. */
int lac_strategy_reset (lac_strategy *s, const lac_contact_system *sys,
                        int same_columns, int *kept);
/* U, lambda for the equations R of a contact law (lac_contact_rows of
 * solve/lac_system.h: friction), with the same refinement; LAC_EINVAL
 * with a message naming the strategies that can when the type cannot
 * (lac_strategy_solves_rows). */
int lac_strategy_solve_rows (lac_strategy *s, const lac_contact_rows *R,
                             double *U, double *lambda);
/* 1 if the type solves the equations of a contact law (solve_rows). */
int lac_strategy_solves_rows (lac_strategy_kind kind);
int lac_strategy_solve_rhs (lac_strategy *s, const char *active,
                            const double *f, const double *g, double *U,
                            double *lambda);
/* The nodal coordinates for the petsc strategy's multigrid (dof =
 * dim*node + comp, n entries, borrowed until free; NULL: none, e.g. the
 * axisymmetric model); the types without set_coordinates ignore them.
 * Before set. */
void lac_strategy_set_coordinates (lac_strategy *s, int dim,
                                   const double *x);
/* The cells, material and Dirichlet dofs K was assembled from (borrowed
 * until free; NULL: none), for a type that assembles K itself (petsc: on
 * the processes that own them).  Before set; the others ignore them. */
void lac_strategy_set_mesh (lac_strategy *s,
                            const struct lac_dist_source *src);
/* 1 if the type assembles its own K of these n dofs from the cells of
 * set_mesh (petsc, with the coordinates): the system's K may then be
 * NULL (lac_system.h's Kop), K x coming from _kmul.  After set_mesh and
 * set_coordinates. */
int lac_strategy_own_k (const lac_strategy *s, size_t n);
/* y = K x (n) with the K of the last set, from the type's own copy (the
 * petsc strategy: its processes' rows; a collective call); x = 0 gives
 * y = 0 without the type, also before the first set (Algorithm 1's
 * first residual, at U = 0). */
int lac_strategy_kmul (lac_strategy *s, size_t n, const double *x,
                       double *y);
/* ||K||_inf of the K of the last set, from the type's own copy (known on
 * the root once the set's matrices were made: an error before). */
int lac_strategy_knorm (const lac_strategy *s, double *norm);
/* 1 if the type computes the stresses and errors of a solution on the
 * processes that hold the cells (petsc on more than one process, K from
 * the cells); then lac_strategy_post does (fem/lac_post_dist.h). */
int lac_strategy_posts (const lac_strategy *s);
int lac_strategy_post (lac_strategy *s, struct lac_post_request *p);
/* What solves (*): the strategy's name, or for petsc its Krylov method,
 * preconditioner and processes. */
const char *lac_strategy_method (const lac_strategy *s);
/* The strategy in use (the fallback once it happened); its type.  The
 * kind of a type not in the table is LAC_NSTRATEGIES. */
lac_strategy_kind lac_strategy_kind_of (const lac_strategy *s);
const lac_strategy_type *lac_strategy_get_type (const lac_strategy *s);
/* Why the strategy fell back to saddle, NULL if it did not. */
const char *lac_strategy_fallback (const lac_strategy *s);
void lac_strategy_get_counts (const lac_strategy *s, lac_strategy_counts *c);

#endif /* LAC_STRATEGY_H */
