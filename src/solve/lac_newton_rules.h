/* lac_newton_rules.h -- the rules that keep Algorithm 1's iterations few
 *                                            [LAC Alg. 1; chapter 07, §5]
 *
 * Algorithm 1 alone (solve/lac_newton.c with every rule switched off,
 * lac_newton_opts.off = LAC_RULES_ALL) is the semismooth Newton method of
 * the paper: statuses from lambda + rho d, one solve, again.  It
 * converges, but it can take many iterations, in rare cases cycle, and it
 * cannot start a body held by contact alone.  Each rule below answers one
 * measured problem; each is a function of what it is given (no state of
 * the loop but its own), switched by one bit of opts.off, and named in
 * chapter 07 next to the test that shows why it is there.
 *
 *   LAC_RULE_HELD_START     the first statuses do not hold a body held by
 *                           contact alone: switch on the multipliers of
 *                           the smallest gaps, 1, 2, 4, ... until they do.
 *                           Why: from every multiplier active the status
 *                           rule releases the tension a ring per iteration
 *                           (19/22/24 iterations for the tet10 ball on a
 *                           rigid flat, chapter 10, against 3/5/5).
 *                           Tests: t505 (part 3), tests/cases-newton.sh.
 *   LAC_RULE_ALL_ACTIVE     the first solve of a run is singular because a
 *                           body the system did not declare (no N) floats:
 *                           solve again with every multiplier active.
 *                           Test: t505 (part 2, the undeclared chain).
 *   LAC_RULE_FIRST_CONTACT  the first solve had no active multiplier (the
 *                           bodies passed through each other): switch on
 *                           only the elements that penetrate by at least
 *                           LAC_NEWTON_FIRST_CONTACT of the deepest (0.95
 *                           after a held start).  Why: a pressed
 *                           paraboloid's overlap is wider than its contact
 *                           zone (radius sqrt(2 R delta) against Hertz's
 *                           sqrt(R delta)); the rule alone would release
 *                           half the excess per iteration.  Tests:
 *                           tests/cases-newton.sh, chapter 07's table.
 *   LAC_RULE_CYCLE_GUARD    the statuses would return to a set already
 *                           tried: make only the most violated half of the
 *                           changes (then a quarter, ..., one).  Why:
 *                           the semismooth Newton method may cycle among
 *                           finitely many active sets.  Test: t505
 *                           (part 1, three obstacles that cycle).
 *   LAC_RULE_LINE_SEARCH    (nonlinear models) a Newton step that turns a
 *                           cell inside out, or that was made on settled
 *                           statuses and does not lower max(residual, gap
 *                           residual), is halved, up to LAC_NEWTON_HALVINGS
 *                           times; a residual LAC_NEWTON_DIVERGED times
 *                           its best is a failure.  Why: with the frozen
 *                           tangent of the paper, full Newton steps of the
 *                           ring of chapter 10 in 3 load steps overshoot:
 *                           43 iterations with it, 52 and a cut load step
 *                           without.  (With the consistent tangent no scene
 *                           of the book needs it.)  Test:
 *                           tests/cases-newton.sh.
 *   LAC_RULE_INEXACT        (nonlinear models with a consistent step) the
 *                           consistent step is solved to eta = 1e-2 times
 *                           the residual (in [1e-12, 1e-3]; 1e-5 at the
 *                           first iteration of a loop), the factor of an
 *                           older tangent is kept (renewed at the start of
 *                           a load step when the last consistent step
 *                           needed more than LAC_NEWTON_LAG GMRES
 *                           iterations, within one only after more than
 *                           LAC_NEWTON_RENEW), and the tangent is left out
 *                           of an evaluation expected to be the last.
 *                           Why: an exact step costs a
 *                           factorization per iteration for digits the
 *                           next iteration does not need (Eisenstat and
 *                           Walker's forcing terms).  Off: eta = 1e-12, a
 *                           factorization of every tangent.  Test:
 *                           tests/cases-newton.sh (the same answer with
 *                           fewer GMRES iterations).
 *
 * References: M. Hintermüller, K. Ito, K. Kunisch, The primal-dual active
 * set strategy as a semismooth Newton method, SIAM J. Optim. 13 (2002);
 * S. C. Eisenstat, H. F. Walker, Choosing the forcing terms in an inexact
 * Newton method, SIAM J. Sci. Comput. 17 (1996).
 *
 * Ownership: the guard owns its checksums (lac_cycle_guard_free); every
 * other argument is borrowed.
 */
#ifndef LAC_NEWTON_RULES_H
#define LAC_NEWTON_RULES_H

#include <stddef.h>
#include "solve/lac_consistent.h"
#include "solve/lac_contact_model.h"
#include "solve/lac_strategy.h"
#include "solve/lac_system.h"

/* The rules, one bit each (lac_newton_opts.off: the rules switched off). */
enum
{
  LAC_RULE_HELD_START = 1 << 0,
  LAC_RULE_ALL_ACTIVE = 1 << 1,
  LAC_RULE_FIRST_CONTACT = 1 << 2,
  LAC_RULE_CYCLE_GUARD = 1 << 3,
  LAC_RULE_LINE_SEARCH = 1 << 4,
  LAC_RULE_INEXACT = 1 << 5,
  LAC_RULES_ALL = (1 << 6) - 1
};

/* Fraction of the deepest penetration switched on at the first contact. */
#define LAC_NEWTON_FIRST_CONTACT 0.5
/* The same after a held start: the first solve pressed the bodies on a
 * few elements, its penetrations are those of a load concentrated there,
 * not of a rigid approach; the zone is grown from its deepest elements
 * instead (chapter 07, section 5). */
#define LAC_NEWTON_HELD_CONTACT 0.95
#define LAC_NEWTON_HALVINGS 4   /* line search: a step halved at most   */
#define LAC_NEWTON_DIVERGED 1e3 /* residual / the loop's best: failure  */
#define LAC_NEWTON_LAG 6        /* GMRES iterations of the last step
                                   that keep an older factorization at
                                   the start of a load step (a converged
                                   state, where the tangent has been
                                   positive definite); one costs about 20
                                   GMRES iterations on the hex20 rings
                                   with its Schur columns: bench/README  */
#define LAC_NEWTON_RENEW LAC_CONSISTENT_RESTART
                                /* the same within a load step (GMRES's
                                   restart length): there a tangent may
                                   not be positive definite, and the LU
                                   fallback would stay for the run       */

/* The name of rule bit r ("held_start", ...), NULL if r is not one. */
const char *lac_rule_name (int r);
/* The bits of a comma-separated list of names ("all", "none" too) into
 * *bits; LAC_EINVAL with a message naming the word otherwise. */
int lac_rule_parse (const char *list, int *bits);

/* ---- held start, all active ---------------------------------------------- */

/* The held start: kact (k) := the columns of the m smallest gaps d, m = 1,
 * 2, 4, ... until they hold every body of sys held by contact alone
 * (lac_system_check_held; all k if fewer do not).  pair: 2k doubles of
 * work.  Returns m. */
size_t lac_rule_held_start (const lac_contact_system *sys, size_t k,
                            const double *d, double *pair, char *kact);
/* After a first solve that failed with `status`: LAC_ESING with fewer
 * than k active is solved again with every multiplier active (kact, x,
 * klam as for lac_strategy_solve; *nactive = k).  Returns the status of
 * that solve, or `status` itself when the rule does not apply. */
int lac_rule_all_active (lac_strategy *st, int status, size_t k,
                         char *kact, double *x, double *klam,
                         size_t *nactive);

/* ---- first contact ------------------------------------------------------ */

/* Of the slots that want (nslot) switches on and are not active, keep on
 * only those whose column of p penetrates by at least frac times the
 * deepest of them. */
void lac_rule_first_contact (const lac_model_point *p, const char *active,
                             double frac, char *want);

/* ---- cycle guard ---------------------------------------------------------- */

typedef struct lac_cycle_guard
{
  unsigned long long *seen;  /* owned: checksums of the statuses solved  */
  size_t nseen, cap;
} lac_cycle_guard;

void lac_cycle_guard_free (lac_cycle_guard *g);
/* Forget the statuses (a new loop). */
void lac_cycle_guard_clear (lac_cycle_guard *g);
/* Remember the statuses `active` (nslot) of a solve. */
int lac_cycle_guard_remember (lac_cycle_guard *g, const char *active,
                              size_t nslot);
/* 1 if the statuses want (nslot) were solved already. */
int lac_cycle_guard_seen (const lac_cycle_guard *g, const char *want,
                          size_t nslot);
/* want := active with the changes to target that lead to statuses not
 * tried yet: of the nch changes ranked in pair[] (value, slot; sorted
 * here, most violated first), the first half, a quarter, ..., one.
 * Returns the number kept. */
size_t lac_cycle_guard_damp (const lac_cycle_guard *g, const char *active,
                             const char *target, char *want, double *pair,
                             size_t nch, size_t nslot);

/* ---- line search ---------------------------------------------------------- */

typedef struct lac_line_search
{
  double merit;          /* max(residual, gap residual) of the last
                            evaluation that was kept                     */
  double merit_best;     /* the smallest of the loop (from iteration 2)  */
  double alpha;          /* the fraction of the last step taken          */
  int backtracks;        /* halvings since the last record               */
} lac_line_search;

void lac_line_search_clear (lac_line_search *ls);
/* 1 if the evaluation (status, merit) after a step should be halved: a
 * cell turned inside out (LAC_ESING) from the second iteration, or no
 * decrease after a step on settled statuses (from the third); and alpha
 * can still be halved. */
int lac_line_search_reject (const lac_line_search *ls, int status,
                            double merit, int it, int settled);
/* Halve the last step: U (n) back to U_old + alpha dU, lambda (nslot)
 * halfway back to lam_step (the last solve gave U_old + 2 alpha dU). */
void lac_line_search_halve (lac_line_search *ls, size_t n, double *U,
                            const double *dU, size_t nslot, double *lambda,
                            const double *lam_step);
/* Take the merit of an iteration; 1 if it diverged (from the fifth
 * iteration, LAC_NEWTON_DIVERGED times above the best). */
int lac_line_search_diverged (lac_line_search *ls, int it);

/* ---- inexact consistent step ---------------------------------------------- */

/* The relative accuracy of the consistent step of iteration it (0: the
 * first of a loop) from the residual of step 3; on: the rule applies. */
double lac_rule_eta (int on, int it, double residual);
/* 1 if the strategy must factorize a new tangent at iteration it, 0 if
 * the factor of an older one may precondition the consistent step (the
 * last consistent step needed gmres_last iterations with it; it = 0: a
 * load step's first iteration, which may take the factor of the step
 * before). */
int lac_rule_refactor (int on, int it, int consistent, int gmres_last);
/* 1 if the evaluation after a step on settled statuses from the residual
 * res_solved may leave the tangent out (quadratic convergence makes it the
 * last). */
int lac_rule_lazy_tangent (int on, int it, int settled, double res_solved);

#endif /* LAC_NEWTON_RULES_H */
