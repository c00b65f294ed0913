/* t705: rigid plates in whole runs: the reactions of their supports and
 *       the rigid motions they forbid               [LAC (4), (8), (17)]
 *
 * Run through run/lac_run.h, no files written.
 *   1. tests/loads/disk-plate.scene: a disk pressed on a block through a
 *      rigid plate on its top (540 N/mm), the plate's vertical motion also
 *      fixed at one node of the top (holdx, uy): that condition holds the
 *      whole plate, its reaction is 540 + contact_force (what the load
 *      does not give the contact), and the reactions balance the load
 *      (x and y, to 1e-9 of it).  (The node's own share was printed:
 *      -37.6 for -16.5.)
 *   2. The same disk without its symmetry plane, held in x by a roller
 *      at that node of the plate (ux = 0) and in y by the contact: the
 *      plate forbids the rotation about that node that the roller alone
 *      leaves free, so the run solves (it was refused, "rotation about
 *      ..."), and the reactions balance the load.
 *   3. tests/loads/beam.scene held at its right end through a plate fixed
 *      at one node (clamp at the tip): the plate holds the whole end
 *      (it was refused, a rotation), the displacement is that of the end
 *      clamped (to 1e-12), the support carries the load.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "run/lac_run.h"

/* Run a scene file, or text read as if it were the file `path`, with
 * the overrides set[0..n): the status, the run in *r. */
static int
run (const char *file, const char *text, const char *path, int n,
     const char **set, lac_scene **sc, lac_run **r)
{
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  int st = file ? lac_scene_read (file, (size_t) n, set, sc)
                : lac_scene_read_string (text, path, (size_t) n, set, sc);
  *r = NULL;
  if (!st && !(*r = lac_run_alloc (*sc, &o)))
    st = LAC_ENOMEM;
  return st ? st : lac_run_all (*r);
}

/* The k-th number of summary line `key` (NAN: none). */
static double
num (const lac_run *r, const char *key, int k)
{
  const char *s = r ? lac_run_summary_get (r, key) : NULL;
  char *end;
  double v = NAN;
  for (int j = 0; s && j <= k; j++, s = end)
    {
      v = strtod (s, &end);
      if (end == s)
        return NAN;
    }
  return s ? v : NAN;
}

/* The reactions of the sections plus the load (0, -f): zero. */
static void
balance (const lac_run *r, const char *const *sec, int n, double f,
         const char *what)
{
  double s[2] = { 0, -f };
  for (int k = 0; k < n; k++)
    for (int i = 0; i < 2; i++)
      {
        char key[64];
        snprintf (key, sizeof key, "reaction.%s", sec[k]);
        s[i] += num (r, key, i);
      }
  check_abs (s[0], 0, 1e-9 * f, "%s: reactions balance the load in x",
             what);
  check_abs (s[1], 0, 1e-9 * f, "%s: reactions balance the load in y",
             what);
}

static void
disk (void)
{
  const char *set[] = { "output.reactions=yes" };
  const char *sec[] = { "disk_axis", "block_axis", "holdx", "bottom" };
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  check_status (run ("tests/loads/disk-plate.scene", NULL, NULL, 1, set,
                     &sc, &r), LAC_SUCCESS, "disk-plate");
  check_abs (num (r, "reaction.holdx", 1), 540 + num (r, "contact_force", 0),
             1e-9 * 540, "the plate's support takes what the contact does "
             "not");
  check_true (num (r, "contact_force", 0) < -541, "the plate pushed further "
              "than 540 (%g)", num (r, "contact_force", 0));
  balance (r, sec, 4, 540, "disk-plate");
  lac_run_free (r);
  lac_scene_free (sc);
}

/* The disk held in x only by a roller at one node of its plate. */
static const char *rolled =
  "[scene]\nmodel = plane_strain\nelement = quad8\n"
  "[mesh]\nfile = disk-plate.geo\nlevel = 1\n"
  "[material steel]\nE = 200000\nnu = 0.3\n"
  "[dirichlet block_axis]\ngroup = block_axis\nsymmetry = x\n"
  "[load top]\ngroup = top\ntotal_force = 0 -540\nplate = yes\n"
  "[dirichlet holdx]\ngroup = topcorner\nux = 0\n"
  "[dirichlet bottom]\ngroup = bottom\nuy = 0\n"
  "[contact interface]\nslave = arc\nmaster = face\ngap_bound = 0.5\n"
  "[output]\nreactions = yes\n";

static void
disk_rolled (void)
{
  const char *sec[] = { "block_axis", "holdx", "bottom" };
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  check_status (run (NULL, rolled, "tests/loads/rolled.scene", 0, NULL, &sc,
                     &r), LAC_SUCCESS, "disk on a roller of its plate");
  check_rel (num (r, "contact_force", 0), -540, 1e-9, "rolled: the contact "
             "carries the load");
  balance (r, sec, 3, 540, "rolled");
  lac_run_free (r);
  lac_scene_free (sc);
}

/* The beam, its right end clamped or held by a plate pinned at the tip. */
static const char *beam =
  "[scene]\nmodel = plane_strain\nelement = quad8\n"
  "[mesh]\nfile = beam.geo\n"
  "[material steel]\ngroup = body\nE = 1000\nnu = 0.3\n"
  "[load top]\ngroup = top\npressure = 1\n"
  "[output]\nreactions = yes\n";

static void
beam_end (void)
{
  char plate[1024], clamp[1024];
  lac_scene *sp = NULL, *sc = NULL;
  lac_run *rp = NULL, *rc = NULL;
  snprintf (plate, sizeof plate, "%s[load end]\ngroup = right\n"
            "total_force = 0 0\nplate = yes\n[dirichlet pin]\ngroup = tip\n"
            "clamp = yes\n", beam);
  snprintf (clamp, sizeof clamp, "%s[dirichlet pin]\ngroup = right\n"
            "clamp = yes\n", beam);
  check_status (run (NULL, plate, "tests/loads/plate.scene", 0, NULL, &sp,
                     &rp), LAC_SUCCESS, "beam held by a pinned plate");
  check_status (run (NULL, clamp, "tests/loads/clamp.scene", 0, NULL, &sc,
                     &rc), LAC_SUCCESS, "beam clamped");
  check_rel (num (rp, "max_u", 0), num (rc, "max_u", 0), 1e-12,
             "a pinned plate clamps the end");
  check_abs (num (rp, "reaction.pin", 0), 0, 1e-9, "pinned plate: x");
  check_rel (num (rp, "reaction.pin", 1), 10, 1e-9, "pinned plate: the "
             "support carries the pressure on the top (10)");
  lac_run_free (rp);
  lac_scene_free (sp);
  lac_run_free (rc);
  lac_scene_free (sc);
}

int
main (void)
{
  lac_init ();
  disk ();
  disk_rolled ();
  beam_end ();
  lac_finalize ();
  return check_summary ();
}
