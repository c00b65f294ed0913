/* lac_nonlinear.h -- load steps and one generalized Newton loop for
 *                    contact, material and geometric nonlinearity
 *                                             [LAC §4.5, Alg. 1; §5.4]
 *
 * [LAC §4.5] solves every nonlinearity with ONE Newton loop: the contact
 * statuses, the hyperelastic material and the large displacements are
 * updated together, and the pairing (hence C and the mean gaps) is
 * recomputed on the current configuration at every iteration
 * [LAC Alg. 1, line 25].  The macro-mesh is built once, on the reference
 * mesh [LAC Remark 3]; only the pairing moves.
 *
 * The load is applied in steps: at load factor t in (0, 1] the Dirichlet
 * values are t * g (entries flagged "ramp") or g (the others) and the
 * external load is t * F.  In each step, iteration k at the current
 * displacement U (x = X + U):
 *
 *   1. internal force F_int(U) and tangent K_T(U) (lac_hyper.h);
 *   2. pairing of the slave sub-facets with the master on the CURRENT
 *      coordinates; admissibility, C(U) and the current mean gaps
 *      d(U) = int_{T^m cap Gamma_C} g(U) dGamma           [LAC (16)-(18)];
 *   3. statuses [LAC Alg. 1, lines 26-33]: macro-element m is active iff
 *      lambda_m + rho_m d_m < 0 (lac_newton.h's convention: lambda <= 0
 *      compression, d >= 0 open); in the first iteration of the whole
 *      run, active iff d_m <= 0 [LAC Alg. 1, lines 2-8];
 *   4. convergence: no status changed, the out-of-balance force
 *        r = t F - F_int(U) + C lambda      (free dofs)
 *      is below tol * max(|F_int|, |t F|, |C lambda|, |r_0|), with r_0
 *      the right-hand side of the step's first solve on the free dofs
 *      (the force of the imposed increments: the scale left when all
 *      forces vanish, in a rigid motion), and the mean gaps of the active
 *      macro-elements are below tol * h_m |T^m cap Gamma_C| -> the step
 *      is done (at least one solve per step);
 *   5. otherwise solve, with C_A the columns of the active multipliers,
 *        [ K_T - H   -C_A ] [ dU       ]   [ t F - F_int(U)   ]
 *        [ B_A^T       0  ] [ lambda_A ] = [ d_A(U)           ]
 *      (Dirichlet dofs: dU = their remaining increment; lambda is the
 *      TOTAL multiplier, not an increment) and set U += dU, lambda =
 *      lambda_A (0 elsewhere).  H = d(C lambda)/dU at the multipliers of
 *      the iteration's start and B = -d(d)/dU are the derivatives of the
 *      contact terms (contact/lac_contact_tangent.h): of the normals, the
 *      surface elements and the projection onto the master.  With
 *      opts.frozen, H = 0 and B = C: the "frozen geometry" of the
 *      generalized Newton method of [LAC §4.5].
 * The frozen system (symmetric) is solved by the strategy of
 * solve/lac_strategy.h (the statuses being those of step 3, the last
 * multipliers the start), kept from iteration to iteration so that its
 * orderings and symbolic analyses are made once; the consistent system
 * (not symmetric) by GMRES with that solve as the preconditioner, from
 * the frozen solution, to a relative accuracy eta = 1e-2 times the
 * residual of step 4 (at most 1e-3, at least 1e-12; 1e-5 in the first
 * iteration of a sub-step) (solve/lac_consistent.h).  Since GMRES makes
 * the step exact whatever the preconditioner, the factorization of K_T
 * need not be new: with the schur strategy it is kept from iteration to
 * iteration (and step to step; lac_strategy_reset: only the Schur columns
 * of the new C are made) and renewed when the last GMRES took more than 6
 * iterations, about half the time of a factorization (a count, not a
 * time: the same path on a busy machine); the other strategies factor at
 * every iteration, and the frozen tangent always does.  The statuses follow
 * the rule of solve/lac_complementarity.h, the rule of the linear active
 * set.  Without any admissible macro-element (bodies apart) step 5 is
 * K_T dU = t F - F_int(U).
 *
 * Step 1 leaves K_T out (F_int alone) when the last solve was made on
 * settled statuses from a residual below 1e-5: quadratic convergence makes
 * that evaluation the last of the sub-step; if it is not, step 5
 * assembles K_T.
 *
 * Convergence.  Quadratic once the statuses have settled, whatever the
 * pressure (t435 checks the derivatives against finite differences).  The
 * frozen geometry leaves out H and B - C (the stretch and rotation of
 * n dGamma under the pressure, and the motion of the master points): its
 * convergence turns linear when |lambda| / E is large, and diverges for
 * the quadratic elements of t433's block compressed by 40 % (|lambda| / E
 * = 0.6); the late steps of the ring took 10 iterations or more.
 *
 * rho_m = E_ref / (h_m |T^m cap Gamma_C|), h_m = |T^m cap Gamma_C|^(1/(dim-1)),
 * E_ref the smallest Young modulus: rho_m d_m is then a pressure, the
 * stiffness of a layer of depth h_m pushed in by the mean gap d_m / |T^m|.
 *
 * Line search: from the second solve of a step on, a Newton step that
 * turns a cell inside out (det F <= 0 at a quadrature point), or that was
 * made on settled statuses (none changed) and does not lower
 * max(residual, gap residual), is halved (U and lambda back half way),
 * up to 4 times.  A step whose residual rises 1000 times above its best
 * is a failure like opts.maxit iterations without convergence; the load
 * step driver (solve/lac_loadstep.h) then cuts the load step into
 * smaller sub-steps, and lets them grow back when they converge fast.
 *
 * Usage (INITIALIZE / ITERATE / TEST; the loop over steps and any
 * printing belong to the caller):
 *   lac_nl *s = lac_nl_alloc (&problem, &opts);
 *   for (each load factor t)
 *     { status = lac_nl_step_to (s, t);   (solve/lac_loadstep.h)
 *       report s->steps[s->nsteps - 1], s->U, s->lambda ... }
 *   lac_nl_free (s);
 * or iteration by iteration with lac_nl_step_begin / lac_nl_step_iterate
 * (solve/lac_loadstep.h), or, for one Newton loop to t without cuts,
 * lac_nl_begin (s, t); while ((st = lac_nl_iterate (s)) == LAC_CONTINUE)
 * { report s->iters[s->niters-1] }.
 *
 * Ownership: the problem's data are borrowed and must outlive the
 * workspace; the workspace owns U, the multipliers, the statuses, the
 * last pairing and contact data, and the records.
 */
#ifndef LAC_NONLINEAR_H
#define LAC_NONLINEAR_H

#include <stddef.h>
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "contact/lac_contact_tangent.h"
#include "fem/lac_hyper.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_strategy.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_obstacle.h"
#include "contact/lac_pairing.h"

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
  /* contact (M == NULL: none) */
  const lac_macro *M;            /* macro-mesh of the slave surface        */
  const lac_pairing_facets *master; /* master facets of `mesh`, or NULL    */
  const lac_obstacle *obstacle;  /* rigid master when master == NULL       */
  double epsilon;                /* [LAC Def. 1]; 0: LAC_EPSILON_DEFAULT   */
  /* bodies held by contact alone (solve/lac_system.h), or nfree = 0 */
  size_t nfree;
  const double *N;               /* ndof x nfree: their rigid motions      */
  const char *const *N_what;     /* nfree descriptions, or NULL            */
} lac_nl_problem;

typedef struct lac_nl_opts
{
  lac_strategy_kind kind; /* how the saddle system is solved
                            (solve/lac_strategy.h; saddle by default): a
                            Cholesky strategy falls back to saddle for the
                            rest of a step where K_T is not positive
                            definite                                       */
  int maxit;             /* Newton iterations per step (0: 25)              */
  double tol;            /* relative tolerance of step 4 (0: 1e-8)          */
  double rho;            /* > 0: rho_m = rho for all m; 0: the default above */
  int max_cuts;          /* a sub-step is at least 2^-max_cuts of its load
                            step (0: 6; < 0: no cut)                       */
  int predict;           /* 1: a sub-step starts from U and lambda
                            extrapolated from the last two converged
                            states (solve/lac_loadstep.h); 0: from the last */
  int frozen;            /* 1: the frozen-geometry tangent (the generalized
                            Newton method of [LAC §4.5]); 0: the consistent
                            one (solve/lac_consistent.h)                   */
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

/* One Newton iteration. */
typedef struct lac_nl_iter
{
  int step;              /* 1, 2, ... (step records index + 1)             */
  int iter;              /* 1, 2, ... within the step                       */
  size_t k;              /* admissible multipliers (paired macro-elements)  */
  size_t nactive;        /* active ones                                     */
  size_t nchanged;       /* statuses changed by step 3                      */
  double residual;       /* |r| / scale (step 4) at the start of the
                            iteration, before its solve                    */
  double du;             /* |dU| / max(|U|, tiny) of the solve (0: none)    */
  double max_penetration;/* max over active m of -d_m / |T^m cap Gamma_C|  */
  int krylov;            /* GMRES iterations of the consistent step          */
  int factored;          /* K_T factored in this iteration (else the factor
                            of an earlier one preconditions GMRES)         */
  double krylov_residual;/* its relative residual at the end                */
  int backtracks;        /* line search: halvings of the last step before
                            this iteration's residual                      */
  double t;              /* load factor of the (sub-)step                   */
  int cuts;              /* cuts of the load step before this iteration     */
  double start, seconds; /* lac_seconds () at the iteration's start, and its
                            duration (assembly, pairing, solve)            */
} lac_nl_iter;

/* One load step (converged or not; solve/lac_loadstep.h). */
typedef struct lac_nl_step
{
  double t;              /* load factor reached                             */
  int iters;             /* Newton iterations (solves), all sub-steps        */
  int cuts;              /* sub-steps cut (failed and halved)               */
  int substeps;          /* sub-steps that converged                        */
  double dt_min;         /* the shortest of them (load factor)              */
  int grown;             /* sub-steps longer than the one before them       */
  double seconds;        /* wall time of the step, and in it:               */
  double time_assemble, time_pairing, time_solve;
  double time_factor;    /*   the factorizations (part of time_solve)       */
  double residual;       /* final relative residual (the check that ended
                            the step)                                      */
  size_t k, nactive;     /* multipliers and active ones at the end          */
  int status;            /* LAC_SUCCESS or the error                        */
} lac_nl_step;

/* The load step under way (solve/lac_loadstep.h). */
typedef struct lac_nl_loadstep
{
  int in_step, in_sub;   /* a step, a sub-step under way                    */
  double t0, t;          /* the step: from t0 to t                          */
  double dt;             /* the sub-step length in use                      */
  int iters, cuts, substeps, grown;
  double dt_min, dt_last;  /* sub-steps converged: shortest, last         */
  int first_save;        /* s->first at the sub-step's beginning            */
  double start;          /* lac_seconds () at the step's beginning          */
  double time0[4];       /* time_assemble, _pairing, _solve, _factor then   */
} lac_nl_loadstep;

typedef struct lac_nl
{
  lac_nl_problem prob;   /* copy of the problem (pointers borrowed)         */
  lac_nl_opts opts;
  size_t ndof, nmacro;
  double *U;             /* owned, ndof: total displacement                 */
  double *lambda;        /* owned, nmacro: multiplier of macro-element m
                            (0 if not admissible or inactive)              */
  char *active;          /* owned, nmacro: status of macro-element m        */
  lac_pairing *pairing;  /* owned: the last pairing (current coordinates)   */
  lac_contact *contact;  /* owned: the last C, mean gaps (Dirichlet moved
                            in), built on the current coordinates          */
  double *x;             /* owned, nnodes*dim: current coordinates X + U    */
  double t, t_prev;      /* load factors: current step, last converged      */
  int converged;         /* the current step converged                      */
  lac_nl_loadstep ls;    /* the load step under way                         */
  double dt_next;        /* > 0: the sub-step length to start the next load
                            step with (the last one was cut)               */
  char cut_msg[256];     /* why the last sub-step was cut ("" if none)      */
  double residual;       /* relative residual at the last evaluation        */
  size_t nsteps, capsteps;
  lac_nl_step *steps;    /* owned, nsteps records                           */
  size_t niters, capiters;
  lac_nl_iter *iters;    /* owned, niters records (all steps)               */
  double time_assemble;  /* seconds, cumulated: F_int and K_T,            */
  double time_pairing;   /*   pairing, admissibility, C and mean gaps,    */
  double time_solve;     /*   saddle-point solves (with the consistent
                                 step's GMRES),                          */
  double time_tangent;   /*   derivatives of the contact terms, and of
                              the contact solves in time_solve:         */
  double time_factor;    /*   the strategy's factorizations,             */
  double time_frozen;    /*   its solve of the frozen system,            */
  double time_krylov;    /*   the consistent step (GMRES, tangent incl.) */
  size_t npairings;      /* pairings computed                               */
  /* internals */
  lac_mesh cur;          /* shallow copy of *mesh with x = the array above  */
  char *fixed;           /* owned, ndof: dof fixed                          */
  double *g1, *g0;       /* owned, ndof: value at t = 1 (ramped), constant  */
  lac_pattern *pat;      /* owned: the kept pattern of K_T and its scatter
                            map (fem/lac_pattern.h)                        */
  lac_csc *K;            /* K_T: pat's matrix                               */
  lac_solver *solver;    /* owned: the solver of K_T without contact, kept
                            between iterations: the ordering and symbolic
                            analysis are made once (lac_solver_refactor)   */
  lac_strategy *strategy; /* owned: the saddle solves, kept likewise        */
  double *klam;          /* owned, kcap: lambda per multiplier            */
  char *kact;            /* owned, kcap: statuses per multiplier          */
  double *klin;          /* owned, kcap: lambda of the linearization point */
  double *kgap;          /* owned, kcap: mean gaps d(U)                   */
  size_t kcap;
  double *lam_lin;       /* owned, nmacro: lambda before the statuses     */
  double *lam_step;      /* owned, nmacro: lambda before the last solve    */
  double *dU_last;       /* owned, ndof: the last Newton step              */
  double *U_old, *lambda_old; /* owned: the converged state before the last
                            one (the predictor's)                          */
  double dt_old;         /* the load factor between them (0: none yet)      */
  int predicted;         /* the sub-step started from the predictor         */
  double alpha;          /* line search: the fraction of it taken          */
  double merit;          /* max(residual, gap residual) at the last evaluation */
  double merit_best;     /* the smallest after the second iteration        */
  int settled;           /* the last solve changed no status              */
  double res_solved;     /* the residual the last solve started from       */
  int have_K;            /* K_T holds the tangent at U                    */
  lac_contact_system sys;    /* the frozen system of the last solve       */
  lac_contact_tangent *tangent; /* owned: H and B of the last solve       */
  double eta;            /* accuracy asked of the consistent step          */
  int strategy_set;      /* the strategy holds a factorization of K_T      */
  int gmres_last;        /* GMRES iterations of the last consistent step
                            since the last factorization (0: none)        */
  double *r, *Fint, *dU; /* owned, ndof                                     */
  double *U_save, *lambda_save;  /* owned: state at the step's beginning    */
  char *active_save;
  int first;             /* no iteration done yet in the whole run          */
  int it;                /* iterations in the current (sub)step             */
  double last_du;        /* |dU| / |U| of the last solve                    */
  double fref;           /* |r| on the free dofs in the step's first solve,
                            Dirichlet increments included (a floor of the
                            residual's scale)                              */
} lac_nl;

lac_nl *lac_nl_alloc (const lac_nl_problem *p, const lac_nl_opts *opts);
void lac_nl_free (lac_nl *s);                  /* NULL allowed */

/* Start a step to load factor t (> the last converged one). */
int lac_nl_begin (lac_nl *s, double t);
/* One pass of steps 1-5 above: LAC_SUCCESS when step 4 finds the step
 * converged (nothing solved), LAC_CONTINUE after a solve, an error status
 * otherwise (LAC_EMAXITER after opts.maxit solves). */
int lac_nl_iterate (lac_nl *s);

/* query */
size_t lac_nl_nactive (const lac_nl *s);
/* Contact force on the slave side per macro-element is lambda[m] times
 * |T^m cap Gamma_C|; this is the sum over the active ones (<= 0). */
double lac_nl_contact_force (const lac_nl *s);

#endif /* LAC_NONLINEAR_H */
