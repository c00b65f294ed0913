/* t506: the reach of the pairing, whole runs    [LAC §4.6, Alg. 1, (18)]
 *
 * chapters/07-newton/two-columns.scene: two columns pushed down by 6 mm
 * onto a stiff base, column A standing on it, column B 5 mm above it
 * (from level 2 on, farther than the pairing of the reference shape
 * reaches).  Run through run/lac_run.h, no files written.  Checked:
 *   1. one pair per column (two-columns-pairs.scene) does what the shared
 *      pair does: the pair of column B starts with nothing in reach, the
 *      loop pairs again once, and the contact force is the shared pair's
 *      (to 1e-10), -E / (1 - nu^2) 6 (6 + 1) / 20 to 1e-3;
 *   2. the same with node-to-segment (method = nts): the slave nodes of
 *      column B are checked too; the loop pairs again and the force is
 *      the uniaxial one to 1e-3 (without the check B passed into the
 *      base: 14 % of the force missing);
 *   3. a widening of the pairing leaves the pair's own reach (gap_bound,
 *      popts.dist_abs) as it was and keeps the reach it added apart;
 *   4. large deformation, B pushed 3 mm into the base (uy = -8) at level
 *      2, deeper than a facet of the base: the loop finds it after the
 *      step that pushed it there (no silent penetration: every slot
 *      active), and gap_bound = 4 reaches it at once (the model keeps the
 *      pair's gap_bound), with the same contact force to 1e-8;
 *   5. node-to-segment, a slave node whose projection misses the master
 *      in the reference shape and ends inside it
 *      (tests/bad/nts-overhang.scene): LAC_EADMISS naming the node.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "run/lac_run.h"

#define COLUMNS "chapters/07-newton/two-columns.scene"
#define PAIRS "chapters/07-newton/two-columns-pairs.scene"

/* The uniaxial contact force of the two columns (a rigid base). */
static const double want = -2000 / (1 - 0.09) * 6 * 7 / 20;

/* Run `scene` with the overrides set[0..n): the status, the run in *r. */
static int
run (const char *scene, int n, const char **set, lac_scene **sc,
     lac_run **r)
{
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  int st = lac_scene_read (scene, (size_t) n, set, sc);
  *r = NULL;
  if (!st && !(*r = lac_run_alloc (*sc, &o)))
    st = LAC_ENOMEM;
  return st ? st : lac_run_all (*r);
}

/* The summary's number `key` (NAN: no run, or no such key). */
static double
value (const lac_run *r, const char *key)
{
  return r ? check_run_value (r, key) : NAN;
}

static void
done (lac_run *r, lac_scene *sc)
{
  lac_run_free (r);
  lac_scene_free (sc);
}

/* 1. and 2.: per column, node-to-segment, against the shared pair. */
static void
same_answers (void)
{
  const char *l2[] = { "level=2" };
  const char *nts[] = { "level=2", "contact.bottoms.method=nts" };
  lac_scene *sc = NULL;
  lac_run *r = check_run_scene (COLUMNS, 1, l2, &sc);
  double f = value (r, "contact_force");
  check_rel (value (r, "pairing_widened"), 1, 0, "shared pair "
             "widened");
  check_run_done (r, sc);
  r = check_run_scene (PAIRS, 1, l2, &sc);
  check_rel (value (r, "contact_force"), f, 1e-10, "a pair per "
             "column: the shared pair's force");
  check_rel (value (r, "contact_force"), want, 1e-3,
             "a pair per column: the uniaxial force");
  check_rel (value (r, "pairing_widened"), 1, 0, "a pair per "
             "column: paired again once");
  check_run_done (r, sc);
  r = check_run_scene (COLUMNS, 2, nts, &sc);
  check_rel (value (r, "contact_force"), want, 1e-3,
             "node-to-segment: column B held");
  check_rel (value (r, "pairing_widened"), 1, 0,
             "node-to-segment: paired again once");
  check_run_done (r, sc);
}

/* 3. the pair's own reach after a widening. */
static void
reach_kept (void)
{
  const char *set[] = { "level=2", "contact.bottoms.gap_bound=0.5" };
  lac_scene *sc = NULL;
  lac_run *r = check_run_scene (COLUMNS, 2, set, &sc);
  if (!r)
    return;
  const lac_contact_pair *p = &r->setup.pair[0];
  check_rel (value (r, "pairing_widened"), 1, 0,
             "gap_bound 0.5: widened");
  check_rel (p->popts.dist_abs, 0.5, 0, "gap_bound kept after widening");
  check_true (p->widened > 0, "the widened reach apart: %g", p->widened);
  check_run_done (r, sc);
}

/* 4. large deformation: B deeper than a facet, found; gap_bound kept. */
static void
large (void)
{
  const char *set[] = { "level=2", "dirichlet.tops.uy=-8",
                        "scene.large_deformation=yes",
                        "contact.bottoms.gap_bound=4" };
  lac_scene *sc = NULL;
  lac_run *r = check_run_scene (COLUMNS, 3, set, &sc);
  double f = value (r, "contact_force");
  check_rel (value (r, "active"), 12, 0, "large: B found (every "
             "slot active)");
  check_run_done (r, sc);
  r = check_run_scene (COLUMNS, 4, set, &sc);
  check_rel (value (r, "contact_force"), f, 1e-8,
             "large, gap_bound 4: the same force");
  check_rel (value (r, "active"), 12, 0, "large, gap_bound 4: "
             "every slot active");
  check_true (r && isnan (value (r, "pairing_widened")),
              "large, gap_bound 4: in reach from the start");
  if (r)
    check_rel (r->nl.model->pair[0].popts.dist_abs, 4, 0,
               "large: the model pairs within gap_bound");
  check_run_done (r, sc);
}

/* 5. node-to-segment: a node off the master, then inside it. */
static void
overhang (void)
{
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  check_status (run ("tests/bad/nts-overhang.scene", 0, NULL, &sc, &r),
                LAC_EADMISS, "nts overhang: refused");
  check_message ("node-to-segment cannot hold it", "nts overhang: why");
  check_message ("slave node", "nts overhang: which");
  done (r, sc);
}

int
main (void)
{
  lac_init ();
  same_answers ();
  reach_kept ();
  large ();
  overhang ();
  lac_finalize ();
  return check_summary ();
}
