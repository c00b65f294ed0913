/* lac_nonlinear.h -- the contact model of large deformations
 *                                             [LAC §4.5, Alg. 1; §5.4]
 *
 * [LAC §4.5] solves every nonlinearity with ONE Newton loop: the contact
 * statuses, the hyperelastic material and the large displacements are
 * updated together, and the pairing (hence C and the mean gaps) is
 * recomputed on the current configuration at every iteration
 * [LAC Alg. 1, line 25].  The loop is the one of every scene
 * (solve/lac_newton.h); this module is the contact model it is given
 * (solve/lac_contact_model.h) for a hyperelastic scene; the load steps
 * that drive it are in solve/lac_loadstep.h.  The macro-mesh is built
 * once, on the reference mesh [LAC Remark 3]; only the pairing moves.
 *
 * At load factor t the Dirichlet values are t * g (entries flagged
 * "ramp") or g (the others), the external load is t * F and the
 * interference of a shrink fit t * delta (each pair its own delta).  At U
 * (x = X + U):
 *
 *   evaluate   the internal force F_int(U) and, unless left out, the
 *              tangent K_T(U) (fem/lac_hyper.h); the pairing of the slave
 *              sub-facets with the master on the CURRENT coordinates,
 *              admissibility, C(U) and the current mean gaps
 *              d(U) = int_{T^m cap Gamma_C} g(U) dGamma  [LAC (16)-(18)];
 *              r = t F - F_int(U); the force scale max(|F_int|, |t F|,
 *              r_0), r_0 the right-hand side of the first solve of the
 *              load factor on the free dofs (the force of the imposed
 *              increments: the scale left when all forces vanish, in a
 *              rigid motion);
 *   linearize  the frozen system of the Newton step,
 *                [ K_T    -C_A ] [ dU       ]   [ t F - F_int(U) ]
 *                [ -C_A^T   0  ] [ lambda_A ] = [ -d_A(U)        ]
 *              with the Dirichlet increments moved in (dU = the
 *              remaining increment on the fixed dofs); lambda is the
 *              TOTAL multiplier, not an increment;
 *   consistent the exact step: K_T - H and B in place of K_T and C in the
 *              rows of the multipliers, H = d(C lambda)/dU at the
 *              multipliers of the iteration's start and B = -d(d)/dU
 *              (contact/lac_contact_tangent.h: the derivatives of the
 *              normals, the surface elements and the projection onto the
 *              master), by GMRES preconditioned by the frozen solve
 *              (solve/lac_consistent.h); with opts.frozen the loop leaves
 *              it out: the "frozen geometry" of the generalized Newton
 *              method of [LAC §4.5];
 *   uncovered, widen  the pair at U (contact/lac_contact_pair.h).
 *
 * Rollers.  With nodal frames in the Dirichlet data (dir->frames,
 * fem/lac_frames.h) U is the loop's U~ in the frames: each evaluation
 * works in the axes at T U~ and turns what it made, T^T F_int, T^T K_T T,
 * T^T C, T^T B, T^T H T (and the load T^T F once); the fixed dofs and
 * their values are the frames' axes.  With several pairs, C and the
 * tangent of all of them side by side are turned once, after the
 * concatenation (a node on two contact surfaces has rows in both).
 *
 * Convergence.  Quadratic once the statuses have settled, whatever the
 * pressure (t435 checks the derivatives against finite differences).  The
 * frozen geometry leaves out H and B - C (the stretch and rotation of
 * n dGamma under the pressure, and the motion of the master points): its
 * convergence turns linear when |lambda| / E is large, and diverges for
 * the quadratic elements of t433's block compressed by 40 % (|lambda| / E
 * = 0.6); the late steps of the ring took 10 iterations or more.
 *
 * Ownership: the problem's data are borrowed and must outlive the model;
 * the model owns the last pairing and contact data, K_T and its pattern.
 */
#ifndef LAC_NONLINEAR_H
#define LAC_NONLINEAR_H

#include <stddef.h>
#include "contact/lac_contact_set.h"
#include "contact/lac_contact_tangent.h"
#include "fem/lac_assembly.h"
#include "fem/lac_hyper.h"
#include "fem/lac_pattern.h"
#include "solve/lac_contact_model.h"

/* The problem (everything borrowed). */
typedef struct lac_nl_problem
{
  const lac_mesh *mesh;          /* the reference mesh (after the macro-mesh
                                    refinement)                            */
  const lac_hyper *mat;          /* material per cell                      */
  const double *F;               /* ndof: external load at t = 1, or NULL  */
  const lac_dirichlet *dir;      /* fixed dofs and their values at t = 1   */
  const char *ramp;              /* dir->n flags: 1 value * t, 0 value; NULL:
                                    every value is ramped                  */
  /* contact, one pair (M == NULL and set == NULL: none) */
  const lac_macro *M;            /* macro-mesh of the slave surface        */
  const lac_pairing_facets *master; /* master facets of `mesh`, or NULL    */
  const lac_obstacle *obstacle;  /* rigid master when master == NULL       */
  double epsilon;                /* [LAC Def. 1]; 0: LAC_EPSILON_DEFAULT   */
  /* bodies held by contact alone (solve/lac_system.h), or nfree = 0 */
  size_t nfree;
  const double *N;               /* ndof x nfree: their rigid motions      */
  const char *const *N_what;     /* nfree descriptions, or NULL            */
  /* or several pairs: their set (contact/lac_contact_set.h; the four
   * fields of one pair above are then not read); the model pairs copies
   * of them, with the pairing options of lac_nl_opts, and takes their
   * offsets as the interferences at t = 1, t delta at load factor t) */
  const lac_contact_set *set;
} lac_nl_problem;

/* The options of a large-deformation solve: of the loop, of the load
 * steps (solve/lac_loadstep.h) and of the pairing. */
/* The defaults of a load step's loop, defined here only. */
#define LAC_NL_MAXIT 25         /* Newton iterations per step           */
#define LAC_NL_TOL 1e-8         /* relative tolerance of the loop's test */

typedef struct lac_nl_opts
{
  lac_strategy_kind kind; /* how the saddle system is solved
                            (solve/lac_strategy.h; by default the LU of the
                            whole system, which takes any tangent): a
                            Cholesky strategy falls back to saddle for the
                            rest of a step where K_T is not positive
                            definite                                       */
  int maxit;             /* Newton iterations per step (0: LAC_NL_MAXIT)    */
  double tol;            /* relative tolerance of the loop's test (0:
                            LAC_NL_TOL)                                    */
  double rho;            /* > 0: rho_m = rho for all m; 0: E / (h |T|)      */
  int max_cuts;          /* a sub-step is at least 2^-max_cuts of its load
                            step (0: 6; < 0: no cut)                       */
  int predict;           /* 1: a sub-step starts from U and lambda
                            extrapolated from the last two converged
                            states (solve/lac_loadstep.h); 0: from the last */
  int frozen;            /* 1: the frozen-geometry tangent (the generalized
                            Newton method of [LAC §4.5]); 0: the consistent
                            one (solve/lac_consistent.h)                   */
  int off;               /* the rules of the loop switched off
                            (solve/lac_newton_rules.h; 0: none)            */
  lac_pairing_opts popts;  /* pairing options (allow_empty is forced);
                            degree_nonaffine = 8 instead of 18: deformed
                            facets are all non-affine, and with 100 points
                            per triangle the pairing and C cost a quarter
                            of a hex20 ring run; 8 changes the ring's
                            displacements by < 1e-3 mm.  The cost: C and
                            the gaps are exact to ~1e-9 only (trapezoids,
                            curved facets), which is the floor of the
                            residual; 0 restores lac_pairing's exact rule
                            (t433 does, for its 1e-10 tolerance)        */
} lac_nl_opts;

void lac_nl_opts_init (lac_nl_opts *o);   /* the defaults above */

typedef struct lac_nl
{
  lac_nl_problem prob;   /* copy of the problem (pointers borrowed)         */
  size_t npair;
  lac_contact_pair *pair; /* owned, npair: the slaves, the masters, epsilon,
                            the pairing options                           */
  lac_contact_set set;   /* over pair: the slots of the multipliers         */
  int frozen;            /* opts.frozen: no consistent op                  */
  size_t ndof, nmacro;
  double t;              /* the load factor of the evaluations              */
  lac_contact_set_data data; /* the last pairings and contact data, on the
                            current coordinates                           */
  const lac_contact *contact; /* data.all: every column (NULL: nothing in
                            reach)                                        */
  lac_mesh cur;          /* shallow copy of the mesh with x = X + U         */
  double time_assemble;  /* seconds, cumulated: F_int and K_T,            */
  double time_pairing;   /*   pairing, admissibility, C and mean gaps,    */
  double time_tangent;   /*   derivatives of the contact terms            */
  size_t npairings;      /* pairings computed                               */
  /* internals */
  double *x;             /* owned, ndof: cur's coordinates                  */
  char *fixed;           /* owned, ndof: dof fixed                          */
  double *g1, *g0;       /* owned, ndof: value at t = 1 (ramped), constant  */
  lac_pattern *pat;      /* owned: the kept pattern of K_T (fem/lac_pattern.h) */
  int have_K;            /* pat->K holds the tangent at the last U          */
  double *r, *Fint;      /* owned, ndof                                     */
  lac_dirichlet inc;     /* owned arrays (ndof): the Dirichlet increments   */
  double *kgap;          /* owned, nmacro: d(U) before the increments       */
  lac_csc *C0;           /* owned: n x 0, the C of no contact               */
  double fref;           /* r_0 (0: not yet made for this load factor)      */
  double moved;          /* max |x - x_before| of the last pairing: how far
                            a node went since the pairing before it       */
  lac_contact_system sys;       /* the frozen system of the last linearize */
  lac_contact_tangent *tangent; /* owned: H and B of the last step         */
  double *delta;         /* owned, npair: the interference of pair q at
                            t = 1 (the set's pair's offset), 0 for none */
  const double *F;       /* the load in the nodal frames: prob.F or Floc    */
  double *ug, *Floc;     /* owned, ndof, with frames only (else NULL): U in
                            the axes, T^T F                               */
} lac_nl;

lac_nl *lac_nl_alloc (const lac_nl_problem *p, const lac_nl_opts *opts);
void lac_nl_free (lac_nl *s);                  /* NULL allowed */
/* The interface of the loop (solve/lac_contact_model.h): slots are the
 * macro-elements; E the smallest Young modulus. */
void lac_nl_model (lac_nl *s, lac_contact_model *m);
/* The load factor of the next evaluations. */
void lac_nl_set_load (lac_nl *s, double t);

/* Contact force on the slave side per macro-element is lambda[m] times
 * |T^m cap Gamma_C|; this is the sum over the columns of the last
 * evaluation (<= 0), lambda per macro-element. */
double lac_nl_contact_force (const lac_nl *s, const double *lambda);

#endif /* LAC_NONLINEAR_H */
