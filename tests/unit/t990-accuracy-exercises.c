/* t990-accuracy-exercises.c -- the answers of
 * chapters/12-accuracy-cost/exercises.md                  [LAC §5.3; ch. 12]
 *
 * Everything is computed here from small runs of the chapter 09 scenes
 * (no files written); nothing depends on time, so the answers hold on any
 * machine (the times of the chapter come from bench/accuracy-cost.sh).
 *
 * Exercise 1 (fewest dofs to a target): manufactured2d, tri3 quad4 tri6
 *   quad8 at levels 0-3: the first run with a relative L2 error of u
 *   <= 1e-3 is quad8 level 1 (450 dofs; tri6 needs 578); no linear element
 *   gets there by level 3 (quad4: 1.098e-3 at 2178 dofs); quad4 needs level
 *   4 (8450 dofs, 19 times quad8's).
 * Exercise 2 (rates in dofs): quad4 levels 2 -> 3: log(err_u) falls like
 *   log(dofs) times -1.00 +- 0.05 (rate 2 in h, d = 2); quad8: -1.5 +- 0.1.
 * Exercise 3 (lambda at equal dofs): quad4 level 3 (2178 dofs) and quad8
 *   level 2 (1666 dofs) have the same 16 macro-elements and the same L2
 *   error of lambda within 2 %, while quad8's error in u is 29 times
 *   smaller; at the same level quad8 has twice the macro-elements and half
 *   the error of lambda (within 5 %).
 * Exercise 4 (nonzeros per row): manufactured3d level 1: nnz(K)/dofs is
 *   about 31 (tet4), 48 (hex8), 68 (tet10), 148 (hex27): hex27 more than
 *   twice tet10.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "run/lac_run.h"
#include "io/lac_scene.h"
#include "base/lac_status.h"

typedef struct res
{
  double dofs, err_u, err_lam, macro, nnz;
} res;

/* Run SCENE with element and level; the numbers of its summary. */
static res
run (const char *scene, const char *element, int level)
{
  char s1[64], s2[64];
  const char *set[2] = { s1, s2 };
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  res x = { NAN, NAN, NAN, NAN, NAN };
  snprintf (s1, sizeof s1, "element=%s", element);
  snprintf (s2, sizeof s2, "level=%d", level);
  int st = lac_scene_read (scene, 2, set, &sc);
  if (!st && !(r = lac_run_alloc (sc, &o)))
    st = LAC_ENOMEM;
  if (!st)
    st = lac_run_all (r);
  check_status (st, LAC_SUCCESS, "%s %s level %d", scene, element, level);
  if (!st)
    {
      const char *v;
      x.dofs = (v = lac_run_summary_get (r, "dofs")) ? atof (v) : NAN;
      x.err_u = (v = lac_run_summary_get (r, "rel_l2_err_u")) ? atof (v) : NAN;
      x.err_lam = (v = lac_run_summary_get (r, "l2_err_lambda")) ? atof (v) : NAN;
      x.macro = (v = lac_run_summary_get (r, "macro_elements")) ? atof (v) : NAN;
      x.nnz = (v = lac_run_summary_get (r, "nnz_K")) ? atof (v) : NAN;
    }
  lac_run_free (r);
  lac_scene_free (sc);
  return x;
}

#define M2D "chapters/09-spheres-rates/manufactured2d.scene"
#define M3D "chapters/09-spheres-rates/manufactured3d.scene"

static res q4[5], q8[4];

static void
exercise1 (void)
{
  const char *el[4] = { "tri3", "quad4", "tri6", "quad8" };
  const char *best = NULL;
  double best_dofs = INFINITY, tri6_dofs = NAN;
  int best_level = -1;
  for (int e = 0; e < 4; e++)
    for (int l = 0; l <= 3; l++)
      {
        res x = run (M2D, el[e], l);
        if (e == 1)
          q4[l] = x;
        if (e == 3)
          q8[l] = x;
        if (x.err_u <= 1e-3)
          {
            if (e == 2 && isnan (tri6_dofs))
              tri6_dofs = x.dofs;
            if (x.dofs < best_dofs)
              {
                best_dofs = x.dofs;
                best = el[e];
                best_level = l;
              }
          }
        if (e < 2)
          check_true (x.err_u > 1e-3, "ex1: %s level %d does not reach 1e-3 "
                      "(err_u = %g)", el[e], l, x.err_u);
      }
  check_true (best && strcmp (best, "quad8") == 0, "ex1: the cheapest is "
              "quad8 (got %s)", best ? best : "none");
  check_int (best_level, 1, "ex1: quad8 level 1");
  check_int ((long) best_dofs, 450, "ex1: 450 dofs");
  check_int ((long) tri6_dofs, 578, "ex1: tri6 needs 578 dofs");
  check_rel (q4[3].err_u, 1.098e-3, 2e-3, "ex1: quad4 level 3 misses, 1.098e-3");
  q4[4] = run (M2D, "quad4", 4);
  check_true (q4[4].err_u <= 1e-3, "ex1: quad4 level 4 reaches 1e-3 (%g)", q4[4].err_u);
  check_int ((long) q4[4].dofs, 8450, "ex1: quad4 level 4 has 8450 dofs");
  check_rel (q4[4].dofs / best_dofs, 18.8, 0.01, "ex1: 19 times quad8's dofs");
}

static double
slope (res a, res b)
{
  return log (b.err_u / a.err_u) / log (b.dofs / a.dofs);
}

static void
exercise2 (void)
{
  check_abs (slope (q4[2], q4[3]), -1.0, 0.05, "ex2: quad4 slope in dofs -1");
  check_abs (slope (q8[2], q8[3]), -1.5, 0.1, "ex2: quad8 slope in dofs -3/2");
}

static void
exercise3 (void)
{
  check_int ((long) q4[3].macro, 16, "ex3: quad4 level 3, 16 macro-elements");
  check_int ((long) q8[2].macro, 16, "ex3: quad8 level 2, 16 macro-elements");
  check_rel (q4[3].err_lam, q8[2].err_lam, 0.02, "ex3: same lambda error");
  check_rel (q4[3].err_u / q8[2].err_u, 29.3, 0.05, "ex3: u error 29 times smaller");
  check_rel (q8[3].macro, 2 * q4[3].macro, 1e-12, "ex3: twice the macro-elements");
  check_rel (q4[3].err_lam / q8[3].err_lam, 2.0, 0.05, "ex3: half the lambda error");
}

static void
exercise4 (void)
{
  const char *el[4] = { "tet4", "hex8", "tet10", "hex27" };
  const double want[4] = { 31, 48, 68, 148 };
  double per[4];
  for (int e = 0; e < 4; e++)
    {
      res x = run (M3D, el[e], 1);
      per[e] = x.nnz / x.dofs;
      check_abs (per[e], want[e], 1.0, "ex4: %s nnz per row", el[e]);
    }
  check_true (per[3] > 2 * per[2], "ex4: hex27 has more than twice tet10's "
              "nonzeros per row (%g, %g)", per[3], per[2]);
}

int
main (void)
{
  exercise1 ();
  exercise2 ();
  exercise3 ();
  exercise4 ();
  return check_summary ();
}
