/* t501: the active-set iteration solves a small contact problem exactly
 *       and every back end agrees                     [LAC (18), Alg. 1]
 *
 * A chain of n springs (stiffness k_s) fixed at dof 0 and pulled by a force
 * at the free end, with obstacles at some dofs: u_j <= g_j, i.e. C(:,i) =
 * e_j, G_i = g_j.  The solution must satisfy the KKT conditions of
 * lac_newton.h: K U - C lambda = F, d = G - C^T U >= 0, lambda <= 0,
 * lambda_i d_i = 0, and the three back ends must agree to 1e-10.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_newton.h"
#include "base/lac_status.h"

enum { N = 40, KC = 6 };

static void
build (lac_csc **K, double *F, lac_csc **C, double *G)
{
  lac_triplet *T = lac_triplet_alloc (N, N, 3 * N);
  for (int j = 0; j < N; j++)
    {
      double diag = j == 0 ? 1.0 : (j == N - 1 ? 1.0 : 2.0);
      if (j == 0)
        {
          lac_triplet_add (T, 0, 0, 1.0);                  /* u_0 = 0 (fixed) */
          continue;
        }
      lac_triplet_add (T, j, j, 100.0 * diag);
      if (j + 1 < N)
        {
          lac_triplet_add (T, j, j + 1, -100.0);
          lac_triplet_add (T, j + 1, j, -100.0);
        }
    }
  *K = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  for (int j = 0; j < N; j++)
    F[j] = j == 0 ? 0.0 : 1.0;                             /* pushes right */
  /* obstacles at 6 dofs, some binding, some not */
  static const int dof[KC] = { 5, 12, 20, 27, 33, 39 };
  static const double gap[KC] = { 10.0, 0.3, 2.0, 0.9, 5.0, 1.2 };
  T = lac_triplet_alloc (N, KC, KC);
  for (int i = 0; i < KC; i++)
    {
      lac_triplet_add (T, dof[i], i, 1.0);
      G[i] = gap[i];
    }
  *C = lac_csc_from_triplet (T);
  lac_triplet_free (T);
}

int
main (void)
{
  lac_init ();
  lac_csc *K, *C;
  double F[N], G[KC], Uref[N], Lref[KC];
  build (&K, F, &C, G);
  lac_contact_system sys = { K, F, C, G, NULL, 0, NULL, NULL, NULL };
  const lac_strategy_kind kinds[4] = { LAC_STRATEGY_DENSE, LAC_STRATEGY_SADDLE,
                                          LAC_STRATEGY_SCHUR, LAC_STRATEGY_AUGMENTED };
  for (int b = 0; b < 4; b++)
    {
      lac_newton *s = NULL;
      int st = lac_newton_solve_system (kinds[b], &sys, 20, 1e-10, &s);
      check_status (st, LAC_SUCCESS, "%s: solve", lac_strategy_name (kinds[b]));
      check_true (s->nhist <= 6, "%s: %zu iterations", lac_strategy_name (kinds[b]), s->nhist);
      /* KKT conditions */
      double r[N];
      lac_csc_matvec (K, s->U, r);
      for (int i = 0; i < KC; i++)
        for (int p = C->p[i]; p < C->p[i + 1]; p++)
          r[C->i[p]] -= C->x[p] * s->lambda[i];
      double rmax = 0;
      for (int j = 0; j < N; j++)
        rmax = fmax (rmax, fabs (r[j] - F[j]));
      check_abs (rmax, 0, 1e-10, "%s: K U - C lambda = F", lac_strategy_name (kinds[b]));
      for (int i = 0; i < KC; i++)
        {
          check_true (s->d[i] >= -1e-12, "%s: d_%d = %g >= 0", lac_strategy_name (kinds[b]), i, s->d[i]);
          check_true (s->lambda[i] <= 1e-12, "%s: lambda_%d = %g <= 0", lac_strategy_name (kinds[b]), i, s->lambda[i]);
          check_abs (s->lambda[i] * s->d[i], 0, 1e-10, "%s: complementarity %d", lac_strategy_name (kinds[b]), i);
        }
      /* the nearest binding obstacle (dof 12, gap 0.3) must be active */
      check_true (s->active[1] && s->lambda[1] < 0, "%s: obstacle at dof 12 active", lac_strategy_name (kinds[b]));
      if (b == 0)
        {
          for (int j = 0; j < N; j++) Uref[j] = s->U[j];
          for (int i = 0; i < KC; i++) Lref[i] = s->lambda[i];
        }
      else
        {
          for (int j = 0; j < N; j++)
            check_abs (s->U[j], Uref[j], 1e-10 * (1 + fabs (Uref[j])), "%s: U[%d] vs dense", lac_strategy_name (kinds[b]), j);
          for (int i = 0; i < KC; i++)
            check_abs (s->lambda[i], Lref[i], 1e-10 * (1 + fabs (Lref[i])), "%s: lambda[%d] vs dense", lac_strategy_name (kinds[b]), i);
        }
      lac_newton_free (s);
    }
  /* no contact at all: gaps far away -> no multiplier active, U = K^{-1} F */
  double Gfar[KC];
  for (int i = 0; i < KC; i++) Gfar[i] = 1e6;
  lac_contact_system far = { K, F, C, Gfar, NULL, 0, NULL, NULL, NULL };
  lac_newton *s = NULL;
  check_status (lac_newton_solve_system (LAC_STRATEGY_SADDLE, &far, 10, 1e-10, &s), LAC_SUCCESS, "no contact");
  check_int ((long) lac_newton_nactive (s), 0, "no contact: active set empty");
  check_int ((long) s->nhist, 1, "no contact: one iteration");
  lac_newton_free (s);
  /* two identical constraints: the Schur complement is singular -> clear error */
  lac_triplet *T = lac_triplet_alloc (N, 2, 2);
  lac_triplet_add (T, 12, 0, 1.0);
  lac_triplet_add (T, 12, 1, 1.0);
  lac_csc *C2 = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  double G2[2] = { 0.1, 0.1 };
  lac_contact_system dup = { K, F, C2, G2, NULL, 0, NULL, NULL, NULL };
  s = NULL;
  check_status (lac_newton_solve_system (LAC_STRATEGY_SCHUR, &dup, 10, 1e-10, &s), LAC_ESING, "dependent constraints");
  check_message ("linearly dependent", "dependent constraints message");
  lac_newton_free (s);
  lac_csc_free (C2);
  lac_csc_free (K);
  lac_csc_free (C);
  lac_finalize ();
  return check_summary ();
}
