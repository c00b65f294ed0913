/* t704: nothing non-finite reaches the output stage: a displacement, a
 * contact multiplier or a stress that is inf or nan stops the run at the
 * post stage with a message naming the node or macro-element  [LAC §2, §5]
 *
 * The runs go through the stages up to the post stage; then one number
 * of a product is spoiled, as an overflow or a silent solver failure
 * would, and the post stage must refuse it.
 */
#include <math.h>
#include <string.h>

#include "check.h"
#include "base/lac_status.h"
#include "run/lac_run.h"

static const char *box =
  "[scene]\nmodel = plane_strain\n"
  "[mesh]\nfile = box.geo\n"
  "[material m]\nE = 1000\nnu = 0.25\n"
  "[dirichlet left]\ngroup = left\nclamp = yes\n"
  "[load pull]\ngroup = right\ntraction = 10 0\n";

/* Run path's scene (or text) up to, not including, the post stage. */
static lac_run *
until_post (const char *text, const char *path, lac_scene **sc)
{
  lac_run_opts o = { NULL, 0, 1, 0, 0, NULL, 0, 0 };
  lac_run *r;
  int st = text ? lac_scene_read_string (text, path, 0, NULL, sc)
                : lac_scene_read (path, 0, NULL, sc);
  check_status (st, LAC_SUCCESS, "%s: scene", path);
  if (st || !(r = lac_run_alloc (*sc, &o)))
    return NULL;
  while (r->stage < LAC_STAGE_POST
         && (st = lac_run_iterate (r)) == LAC_CONTINUE)
    ;
  check_int (r->stage, LAC_STAGE_POST, "%s: up to post", path);
  return r;
}

static void
spoil (const char *text, const char *path, int what, double value,
       const char *words)
{
  lac_scene *sc = NULL;
  lac_run *r = until_post (text, path, &sc);
  if (!r)
    return;
  if (what == 0)
    r->sol.u[3] = value;
  else if (what == 1 && r->sol.newton && r->sol.newton->nslot > 0)
    r->sol.newton->lambda[0] = value;
  else if (what == 2)
    r->mat.E[0] = value;      /* cell 1: its stresses overflow (von Mises) */
  check_status (lac_run_iterate (r), LAC_ESING, "%s: spoiled %d", path,
                what);
  check_message (words, "%s: spoiled %d", path, what);
  check_message ("nothing is written", "%s: spoiled %d", path, what);
  lac_run_free (r);
  lac_scene_free (sc);
}

int
main (int argc, char **argv)
{
  lac_scene *sc = NULL;
  lac_run *r;
  (void) argc;
  (void) argv;
  lac_init ();
  /* The same run unspoiled passes the post stage. */
  if ((r = until_post (box, "tests/bad/t704.scene", &sc)))
    check_status (lac_run_iterate (r), LAC_CONTINUE, "unspoiled");
  lac_run_free (r);
  lac_scene_free (sc);

  spoil (box, "tests/bad/t704.scene", 0, INFINITY,
         "the displacement is not finite: u_y = inf at node");
  spoil (box, "tests/bad/t704.scene", 0, NAN,
         "the displacement is not finite: u_y = nan at node");
  spoil (box, "tests/bad/t704.scene", 2, 1e300,
         "the stresses are not finite: von Mises = inf at node");
  spoil (NULL, "chapters/08-experiments/taylor2d.scene", 1, NAN,
         "the contact multipliers are not finite: lambda = nan for "
         "macro-element 1 of 1");
  lac_finalize ();
  return check_summary ();
}
