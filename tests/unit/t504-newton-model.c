/* t504: Algorithm 1 over a contact model of the test's own: the interface
 *       of solve/lac_contact_model.h and the check of the macro-elements
 *       left without a multiplier                     [LAC Alg. 1, (18)]
 *
 * A chain of N springs fixed at dof 0, every free dof pushed to the right
 * by 1, three obstacles u_j <= g_j at dofs 10, 20 and 30 (slots 0, 1, 2).
 * The model pairs only the obstacles in `reach` (a flag each): the others
 * have no column.  Its uncovered op reports an obstacle without a column
 * whose dof went past it (depth u_j - g_j, size 1); widen pairs them all
 * when it may.  Checked:
 *   1. every obstacle paired: the loop converges; K U - C lambda = F and
 *      the complementarity conditions hold to 1e-10;
 *   2. obstacle 2 out of reach: the first solutions pass it; the loop
 *      widens, goes on with three columns (slot 2 gets its multiplier, the
 *      others keep theirs) and ends with the solution of case 1;
 *   3. obstacle 2 out of reach and widen gaining nothing: LAC_EADMISS, and
 *      the message names the macro-element and the penetration;
 *   4. with pen_tol < 0 the check is off: case 3 converges (and
 *      penetrates, as it was asked to).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_newton.h"

enum { N = 40, NOB = 3 };
static const int at[NOB] = { 10, 20, 30 };
static const double gap[NOB] = { 0.5, 1.5, 2.0 };

typedef struct chain
{
  lac_csc *K, *C;              /* C: the columns of the obstacles paired */
  double F[N], G[NOB], d[NOB], r[N], area[NOB];
  size_t slot[NOB], k;
  char reach[NOB];             /* paired now                             */
  int may_widen;
  int news;
  lac_contact_system sys;
} chain;

static void
pair (chain *c)
{
  lac_triplet *T = lac_triplet_alloc (N, NOB, NOB);
  c->k = 0;
  for (int o = 0; o < NOB; o++)
    if (c->reach[o])
      {
        lac_triplet_add (T, (size_t) at[o], c->k, 1.0);
        c->G[c->k] = gap[o];
        c->area[c->k] = 1.0;
        c->slot[c->k++] = (size_t) o;
      }
  lac_csc_free (c->C);
  c->C = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  c->sys = (lac_contact_system) { c->K, c->F, c->C, c->G, NULL, 0, NULL,
                                  NULL, NULL };
}

static int
evaluate (void *self, const double *U, int tangent, lac_model_point *p)
{
  chain *c = self;
  double nf = 0;
  (void) tangent;
  lac_csc_matvec (c->K, U, c->r);
  for (int j = 0; j < N; j++)
    {
      c->r[j] = c->F[j] - c->r[j];                  /* r = F - K U */
      nf += c->F[j] * c->F[j];
    }
  lac_system_gaps (&c->sys, U, c->d);               /* d = G - C^T U */
  *p = (lac_model_point) { .k = c->k, .C = c->C, .d = c->d, .area = c->area,
                           .size = c->area, .slot = c->slot, .r = c->r,
                           .fscale = sqrt (nf) };
  return LAC_SUCCESS;
}

static int
linearize (void *self, const double *U, const lac_contact_system **sys,
           int *news)
{
  chain *c = self;
  (void) U;
  *sys = &c->sys;
  *news = c->news;
  c->news = LAC_MODEL_SAME;
  return LAC_SUCCESS;
}

static int
uncovered (void *self, const double *U, double tol, lac_contact_uncovered *u)
{
  chain *c = self;
  memset (u, 0, sizeof *u);
  for (int o = 0; o < NOB; o++)
    {
      double depth = U[at[o]] - gap[o];
      if (c->reach[o] || !(depth > tol))
        continue;
      u->count++;
      u->depth = depth;
      u->h = 1.0;
      u->macro = (size_t) o;
      u->x[0] = at[o];
    }
  return LAC_SUCCESS;
}

static int
widen (void *self, const double *U, double reach, size_t *more)
{
  chain *c = self;
  (void) U;
  (void) reach;
  *more = 0;
  if (!c->may_widen)
    return LAC_SUCCESS;
  for (int o = 0; o < NOB; o++)
    if (!c->reach[o])
      c->reach[o] = 1, (*more)++;
  pair (c);
  c->news = LAC_MODEL_NEW_C;
  return LAC_SUCCESS;
}

static const lac_contact_model_type chain_type =
  { "spring chain", 0, evaluate, linearize, NULL, uncovered, widen };

static void
chain_init (chain *c, int reach2, int may_widen)
{
  lac_triplet *T = lac_triplet_alloc (N, N, 3 * N);
  memset (c, 0, sizeof *c);
  lac_triplet_add (T, 0, 0, 1.0);                   /* u_0 = 0 */
  for (int j = 1; j < N; j++)
    {
      lac_triplet_add (T, (size_t) j, (size_t) j, j + 1 < N ? 200.0 : 100.0);
      if (j + 1 < N)
        {
          lac_triplet_add (T, (size_t) j, (size_t) j + 1, -100.0);
          lac_triplet_add (T, (size_t) j + 1, (size_t) j, -100.0);
        }
      c->F[j] = 1.0;
    }
  c->K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  c->reach[0] = c->reach[1] = 1;
  c->reach[2] = (char) reach2;
  c->may_widen = may_widen;
  c->news = LAC_MODEL_NEW_K;
  pair (c);
}

static int
solve (chain *c, double pen_tol, lac_newton **out)
{
  lac_contact_model m = { &chain_type, c, N, NOB, 1.0, 2, 0 };
  lac_newton_opts o;
  lac_newton_opts_init (&o);
  o.kind = LAC_STRATEGY_SADDLE;
  o.pen_tol = pen_tol;
  *out = lac_newton_alloc (&m, &o);
  return *out ? lac_newton_solve (*out) : LAC_ENOMEM;
}

/* K U - C lambda = F and the signs, on the final columns. */
static void
check_kkt (const char *what, chain *c, const lac_newton *s)
{
  double r[N], lam[NOB], eq = 0;
  for (size_t i = 0; i < c->k; i++)
    lam[i] = s->lambda[c->slot[i]];
  lac_csc_matvec (c->K, s->U, r);
  for (size_t i = 0; i < c->k; i++)
    r[at[c->slot[i]]] -= lam[i];
  for (int j = 0; j < N; j++)
    eq = fmax (eq, fabs (r[j] - c->F[j]));
  check_true (eq <= 1e-10, "%s: equilibrium %.1e", what, eq);
  for (int o = 0; o < NOB; o++)
    {
      double d = gap[o] - s->U[at[o]];
      check_true (d >= -1e-10 && s->lambda[o] <= 1e-12
                  && fabs (s->lambda[o] * d) <= 1e-10,
                  "%s: obstacle %d: gap %.3g, lambda %.3g", what, o, d,
                  s->lambda[o]);
    }
}

static void
chain_free (chain *c)
{
  lac_csc_free (c->K);
  lac_csc_free (c->C);
}

int
main (void)
{
  lac_init ();
  chain c;
  lac_newton *s = NULL, *ref = NULL;

  chain_init (&c, 1, 0);                                        /* 1 */
  check_status (solve (&c, 0, &ref), LAC_SUCCESS, "all paired");
  check_kkt ("all paired", &c, ref);
  check_int ((long) ref->widened, 0, "all paired: not widened");
  chain_free (&c);

  chain_init (&c, 0, 1);                                        /* 2 */
  check_status (solve (&c, 0, &s), LAC_SUCCESS, "widened");
  check_int ((long) s->widened, 1, "widened once");
  check_int ((long) c.k, NOB, "widened: three columns");
  check_kkt ("widened", &c, s);
  for (int o = 0; o < NOB; o++)
    check_abs (s->lambda[o], ref->lambda[o], 1e-10, "widened: lambda_%d", o);
  lac_newton_free (s);
  chain_free (&c);

  chain_init (&c, 0, 0);                                        /* 3 */
  check_status (solve (&c, 0, &s), LAC_EADMISS, "out of reach");
  check_message ("macro-element 2 at (30, 0, 0) has no contact multiplier",
                 "out of reach: names it");
  check_message ("passes", "out of reach: says how deep");
  lac_error_clear ();
  lac_newton_free (s);

  check_status (solve (&c, -1, &s), LAC_SUCCESS, "check off");  /* 4 */
  check_true (s->U[at[2]] > gap[2], "check off: obstacle 2 passed (u = %g)",
              s->U[at[2]]);
  lac_newton_free (s);
  chain_free (&c);
  lac_newton_free (ref);
  lac_finalize ();
  return check_summary ();
}
