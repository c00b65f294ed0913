/* t505: the rules of the loop of Algorithm 1, each shown needed, and the
 *       loop without them              [LAC Alg. 1; solve/lac_newton_rules.h]
 *
 * 1. Cycle guard.  Three dofs, K = [6 -4 -1; -4 5 2; -1 2 1] (symmetric
 *    positive definite, not an M-matrix), an obstacle on each (C = I),
 *    F = (-6, 5, -1), G = (5, 1, 1), rho = 1.  The status rule alone goes
 *    (0,0,0) -> (1,1,0) -> (0,1,1) -> (0,0,0) -> ... for ever: every rule
 *    off, the loop stops with LAC_EMAXITER and says the statuses still
 *    change; the cycle guard alone on, it converges to the solution of
 *    the complementarity problem (checked: K U - lambda = F, d >= 0,
 *    lambda <= 0, lambda d = 0, to 1e-12).
 * 2. Every multiplier active.  A free-free chain of three dofs (K
 *    singular: a translation) pushed onto obstacles, the nearest at dof 0,
 *    the translation not declared (nfree = 0): the first statuses (the
 *    gaps are open) leave K alone, singular.  The rule on: the loop
 *    solves again with every multiplier active, releases the others and
 *    converges, lambda_0 = -(sum F); off: LAC_ESING.
 * 3. Held start.  The same chain with the translation declared (nfree =
 *    1), gaps 1, 2, 3: the held start switches on the smallest gap only,
 *    and the first solve is the solution; off, the all-active rule starts
 *    from every obstacle active and releases two (more iterations, the
 *    same solution).
 * 4. lac_rule_parse: names, all, none, a bad word named in the message;
 *    lac_rule_name.
 * 5. lac_rule_refactor (the inexact rule's renewals): at a load step's
 *    start the factor of the step before is kept after LAC_NEWTON_LAG
 *    GMRES iterations and renewed after one more; within a step the same
 *    at LAC_NEWTON_RENEW; always renewed with the rule off or without a
 *    consistent step.
 * The other rules (first contact, line search, inexact step) act on whole
 * scenes: tests/cases-newton.sh runs them with and without.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_linear_model.h"
#include "solve/lac_newton.h"

typedef struct problem
{
  lac_csc *K, *C;
  double F[3], G[3], N[3];
  lac_contact_system sys;
  lac_linear_model lin;
} problem;

static lac_csc *
csc_dense3 (const double A[3][3])
{
  lac_triplet *T = lac_triplet_alloc (3, 3, 9);
  for (size_t i = 0; i < 3; i++)
    for (size_t j = 0; j < 3; j++)
      if (A[i][j] != 0)
        lac_triplet_add (T, i, j, A[i][j]);
  lac_csc *M = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  return M;
}

static void
problem_init (problem *p, const double K[3][3], const double C[3][3],
              const double *F, const double *G, size_t nfree)
{
  static const char *what[] = { "the chain: translation" };
  memset (p, 0, sizeof *p);
  p->K = csc_dense3 (K);
  p->C = csc_dense3 (C);
  memcpy (p->F, F, sizeof p->F);
  memcpy (p->G, G, sizeof p->G);
  p->N[0] = p->N[1] = p->N[2] = 1 / sqrt (3.0);
  p->sys = (lac_contact_system) { p->K, p->F, p->C, p->G, NULL, nfree,
                                  nfree ? p->N : NULL,
                                  nfree ? what : NULL, NULL };
}

static void
problem_free (problem *p)
{
  lac_linear_model_clear (&p->lin);
  lac_csc_free (p->K);
  lac_csc_free (p->C);
}

/* The loop over p with the rules `off` switched off (rho = 1, dense). */
static int
run (problem *p, int off, lac_newton **out)
{
  lac_contact_model m;
  lac_newton_opts o;
  int status = lac_linear_model_init (&p->lin, &p->sys, 1.0, &m);
  if (status)
    return status;
  lac_newton_opts_init (&o);
  o.kind = LAC_STRATEGY_DENSE;
  o.rho = 1.0;
  o.maxit = 20;
  o.off = off;
  *out = lac_newton_alloc (&m, &o);
  return *out ? lac_newton_solve (*out) : LAC_ENOMEM;
}

/* The complementarity conditions of the solution (C = I). */
static void
check_lcp (const char *what, const problem *p, const lac_newton *s)
{
  double r[3], worst = 0;
  lac_csc_matvec (p->K, s->U, r);
  for (int j = 0; j < 3; j++)
    {
      double d = p->G[j] - s->U[j];
      worst = fmax (worst, fabs (r[j] - s->lambda[j] - p->F[j]));
      check_true (d >= -1e-12 && s->lambda[j] <= 1e-12
                  && fabs (s->lambda[j] * d) <= 1e-12, "%s: dof %d: gap "
                  "%.3g, lambda %.3g", what, j, d, s->lambda[j]);
    }
  check_true (worst <= 1e-12, "%s: equilibrium %.1e", what, worst);
}

static const double I3[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };

static void
cycle_guard (void)
{
  static const double K[3][3] = { { 6, -4, -1 }, { -4, 5, 2 },
                                  { -1, 2, 1 } };
  static const double F[3] = { -6, 5, -1 }, G[3] = { 5, 1, 1 };
  problem p;
  lac_newton *s = NULL;
  problem_init (&p, K, I3, F, G, 0);
  check_status (run (&p, LAC_RULES_ALL, &s), LAC_EMAXITER,
                "cycle: the status rule alone");
  check_message ("statuses still change", "cycle: the stop names it");
  check_int ((long) lac_newton_iterations (s), 20, "cycle: to the limit");
  lac_newton_free (s);
  problem_free (&p);
  problem_init (&p, K, I3, F, G, 0);
  check_status (run (&p, LAC_RULES_ALL & ~LAC_RULE_CYCLE_GUARD, &s),
                LAC_SUCCESS, "cycle: with the guard");
  if (s)
    {
      check_lcp ("cycle guard", &p, s);
      check_true (s->nhist > 0 && lac_newton_iterations (s) <= 6,
                  "cycle guard: %zu iterations", lac_newton_iterations (s));
      int damped = 0;
      for (size_t j = 0; j < s->nhist; j++)
        damped += s->hist[j].damped;
      check_true (damped > 0, "cycle guard: it damped");
    }
  lac_newton_free (s);
  problem_free (&p);
}

/* The free-free chain: springs of 1 between dofs 0-1 and 1-2. */
static const double KCHAIN[3][3] = { { 1, -1, 0 }, { -1, 2, -1 },
                                     { 0, -1, 1 } };

/* The obstacles u_j >= -G_j at every dof: C = -I, d = G + U. */
static const double CLEFT[3][3] = { { -1, 0, 0 }, { 0, -1, 0 },
                                    { 0, 0, -1 } };
/* The chain pushed to the left by 3 at dof 0: it lands on the nearest
 * obstacle, dof 0's (lambda_0 = -3), and the others stay open. */
static const double FLEFT[3] = { -3, 0, 0 };

static void
all_active (void)
{
  static const double G[3] = { 0.5, 2, 3 };
  problem p;
  lac_newton *s = NULL;
  problem_init (&p, KCHAIN, CLEFT, FLEFT, G, 0);
  check_status (run (&p, LAC_RULE_ALL_ACTIVE, &s), LAC_ESING,
                "all active: off, the first solve is singular");
  lac_newton_free (s);
  problem_free (&p);
  problem_init (&p, KCHAIN, CLEFT, FLEFT, G, 0);
  check_status (run (&p, 0, &s), LAC_SUCCESS, "all active: on");
  if (s)
    {
      check_rel (s->lambda[0], -3.0, 1e-12, "all active: lambda_0");
      check_rel (s->U[0], -0.5, 1e-12, "all active: u_0 on the obstacle");
      check_abs (s->lambda[1] + s->lambda[2], 0, 1e-12, "all active: the "
                 "others free");
      check_true (s->restarted, "all active: restarted");
    }
  lac_newton_free (s);
  problem_free (&p);
}

static void
held_start (void)
{
  static const double G[3] = { 1, 2, 3 };
  problem p;
  lac_newton *s = NULL;
  size_t it[2] = { 0, 0 };
  for (int off = 0; off < 2; off++)
    {
      problem_init (&p, KCHAIN, CLEFT, FLEFT, G, 1);
      check_status (run (&p, off ? LAC_RULE_HELD_START : 0, &s),
                    LAC_SUCCESS, "held start %s", off ? "off" : "on");
      if (s)
        {
          it[off] = lac_newton_iterations (s);
          check_rel (s->lambda[0], -3.0, 1e-12, "held start %s: lambda_0",
                     off ? "off" : "on");
          check_abs (s->lambda[1] + s->lambda[2], 0, 1e-12, "held start "
                     "%s: the others free", off ? "off" : "on");
          check_int ((long) s->held_start, off ? 0 : 1, "held start %s: "
                     "switched on", off ? "off" : "on");
        }
      lac_newton_free (s);
      problem_free (&p);
    }
  check_true (it[0] < it[1], "held start: %zu iterations, %zu without",
              it[0], it[1]);
}

static void
parse (void)
{
  int b;
  check_status (lac_rule_parse ("all", &b), LAC_SUCCESS, "parse all");
  check_int (b, LAC_RULES_ALL, "all");
  check_status (lac_rule_parse ("none", &b), LAC_SUCCESS, "parse none");
  check_int (b, 0, "none");
  check_status (lac_rule_parse ("cycle_guard, held_start", &b), LAC_SUCCESS,
                "parse a list");
  check_int (b, LAC_RULE_CYCLE_GUARD | LAC_RULE_HELD_START, "a list");
  check_status (lac_rule_parse ("held_start,cycle", &b), LAC_EINVAL,
                "a bad word");
  check_message ("'cycle' is not a rule", "the word named");
  for (int r = 1; r < LAC_RULES_ALL; r <<= 1)
    {
      check_true (lac_rule_name (r) != NULL, "rule %d has a name", r);
      check_status (lac_rule_parse (lac_rule_name (r), &b), LAC_SUCCESS,
                    "parse %s", lac_rule_name (r));
      check_int (b, r, "%s", lac_rule_name (r));
    }
  check_true (lac_rule_name (3) == NULL, "3 is no rule");
}

static void
refactor (void)
{
  check_int (lac_rule_refactor (1, 0, 1, LAC_NEWTON_LAG), 0,
             "a load step's start: the older factor kept");
  check_int (lac_rule_refactor (1, 0, 1, LAC_NEWTON_LAG + 1), 1,
             "a load step's start: renewed");
  check_int (lac_rule_refactor (1, 3, 1, LAC_NEWTON_RENEW), 0,
             "within a step: kept");
  check_int (lac_rule_refactor (1, 3, 1, LAC_NEWTON_RENEW + 1), 1,
             "within a step: renewed");
  check_true (LAC_NEWTON_LAG < LAC_NEWTON_RENEW, "renewed sooner at a "
              "step's start (%d) than within one (%d)", LAC_NEWTON_LAG,
              LAC_NEWTON_RENEW);
  check_int (lac_rule_refactor (0, 3, 1, 0), 1, "the rule off: renewed");
  check_int (lac_rule_refactor (1, 3, 0, 0), 1, "no consistent step: "
             "renewed");
}

int
main (void)
{
  cycle_guard ();
  all_active ();
  held_start ();
  parse ();
  refactor ();
  return check_summary ();
}
