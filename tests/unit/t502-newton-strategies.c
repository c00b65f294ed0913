/* t502: the strategies of solve/lac_strategy.h give the same U and lambda
 *                                       [LAC (17), Alg. 1 line 21; ch. 07]
 *
 * Whole runs of chapter scenes through every strategy that applies: the
 * displacement and the multipliers must agree with the saddle strategy
 * (UMFPACK's LU of the whole system, the reference) to 1e-10 relative
 * (max |x - x_ref| / max |x_ref|), with the same statuses:
 *   - Taylor 2D quad8 and 3D hex8 (level 1, slave and master swapped):
 *     the upper body is held by contact alone; dense, augmented, split;
 *     schur is refused with a message before anything is factorized;
 *   - Taylor 3D hex8 with 12^3 / 11^3 cells (6591 and 5184 unknowns):
 *     augmented, split (its two factorizations made side by side,
 *     linalg/lac_tasks.h);
 *   - the self-included spheres, axisymmetric quad8 and 3D tet10 (every
 *     body held by symmetry conditions): dense, schur, augmented; split
 *     is refused (no body held by contact alone);
 *   - the cylinder on a rigid flat of chapter 07 (level 3: several
 *     active-set iterations): dense, schur, augmented.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "base/lac_status.h"
#include "solve/lac_strategy.h"

/* Run `scene` with the overrides and the strategy; NULL (status checked)
 * if the run fails. */
static lac_run *
run (const char *scene, size_t nset, const char *const *set, int strategy,
     lac_scene **sc, int *st)
{
  lac_run_opts o = { NULL, 0, 1, strategy, 0, NULL, 0, 0 };
  lac_run *r = NULL;
  *st = lac_scene_read (scene, nset, set, sc);
  if (!*st && !(r = lac_run_alloc (*sc, &o)))
    *st = LAC_ENOMEM;
  if (!*st)
    *st = lac_run_all (r);
  return r;
}

static double
rel_diff (size_t n, const double *x, const double *ref)
{
  double d = 0, m = 0;
  for (size_t i = 0; i < n; i++)
    {
      d = fmax (d, fabs (x[i] - ref[i]));
      m = fmax (m, fabs (ref[i]));
    }
  return m > 0 ? d / m : d;
}

/* Every strategy in `kinds` (terminated by LAC_STRATEGY_AUTO) against the
 * saddle strategy. */
static void
compare (const char *what, const char *scene, size_t nset,
         const char *const *set, const int *kinds)
{
  lac_scene *s0 = NULL, *s1 = NULL;
  int st;
  lac_run *ref = run (scene, nset, set, LAC_STRATEGY_SADDLE, &s0, &st);
  check_status (st, LAC_SUCCESS, "%s: saddle", what);
  for (int k = 0; !st && kinds[k] != LAC_STRATEGY_AUTO; k++)
    {
      const char *kn = lac_strategy_name ((lac_strategy_kind) kinds[k]);
      lac_run *r = run (scene, nset, set, kinds[k], &s1, &st);
      check_status (st, LAC_SUCCESS, "%s: %s", what, kn);
      if (!st)
        {
          const lac_newton *a = r->sol.newton, *b = ref->sol.newton;
          check_abs (rel_diff (r->sys.ndof, r->sol.u, ref->sol.u), 0, 1e-10,
                     "%s: U, %s vs saddle", what, kn);
          check_abs (rel_diff (a->nslot, a->lambda, b->lambda), 0, 1e-10,
                     "%s: lambda, %s vs saddle", what, kn);
          check_true (memcmp (a->active, b->active, a->nslot) == 0,
                      "%s: the same statuses (%s)", what, kn);
          check_true ((int) lac_strategy_kind_of (a->strategy) == kinds[k],
                      "%s: %s was used", what, kn);
        }
      lac_run_free (r);
      lac_scene_free (s1);
      st = 0;
    }
  lac_run_free (ref);
  lac_scene_free (s0);
}

int
main (void)
{
  lac_init ();
  const int floating[] = { LAC_STRATEGY_DENSE, LAC_STRATEGY_AUGMENTED,
                           LAC_STRATEGY_SPLIT, 0 };
  const int held[] = { LAC_STRATEGY_DENSE, LAC_STRATEGY_SCHUR,
                       LAC_STRATEGY_AUGMENTED, 0 };
  const int held_big[] = { LAC_STRATEGY_SCHUR, LAC_STRATEGY_AUGMENTED, 0 };
  const char *t2[] = { "element=quad8" };
  const char *t3[] = { "element=hex8", "level=1",
                       "contact.interface.slave=lower_top",
                       "contact.interface.master=upper_bottom" };
  const int floating_big[] = { LAC_STRATEGY_AUGMENTED, LAC_STRATEGY_SPLIT,
                               0 };
  const char *t3n[] = { "element=hex8", "mesh.numbers=n=12" };
  const char *sa[] = { "element=quad8" };
  const char *s3[] = { "element=tet10" };
  const char *cy[] = { "level=3" };
  compare ("taylor2d", "chapters/08-experiments/taylor2d.scene", 1, t2,
           floating);
  compare ("taylor3d", "chapters/08-experiments/taylor3d.scene", 4, t3,
           floating);
  compare ("taylor3d n=12", "chapters/08-experiments/taylor3d.scene", 2, t3n,
           floating_big);
  compare ("spheres-axi", "chapters/09-spheres-rates/spheres-axi.scene", 1, sa,
           held);
  compare ("spheres3d", "chapters/09-spheres-rates/spheres3d.scene", 1, s3,
           held_big);
  compare ("cylinder", "chapters/07-newton/cylinder-flat.scene", 1, cy,
           held);

  /* schur on a body held by contact alone: refused, with the reason */
  lac_scene *sc = NULL;
  int st;
  lac_run *r = run ("chapters/08-experiments/taylor2d.scene", 1, t2,
                    LAC_STRATEGY_SCHUR, &sc, &st);
  check_status (st, LAC_EINVAL, "taylor2d: schur refused");
  check_message ("held by contact alone", "taylor2d: schur's message");
  lac_run_free (r);
  lac_scene_free (sc);

  /* split on bodies all held by their Dirichlet conditions: refused */
  sc = NULL;
  r = run ("chapters/09-spheres-rates/spheres-axi.scene", 1, sa,
           LAC_STRATEGY_SPLIT, &sc, &st);
  check_status (st, LAC_EINVAL, "spheres-axi: split refused");
  check_message ("needs a body held by contact alone",
                 "spheres-axi: split's message");
  lac_run_free (r);
  lac_scene_free (sc);
  lac_finalize ();
  return check_summary ();
}
