/* LAC chapter 15 -- Coulomb friction with LAC averages
 *                                [LAC (16)-(18), Alg. 1; with friction]
 *
 * Build:        make build/chapters/15-friction
 * Sample runs:  build/chapters/15-friction
 * Description:  A 20 x 10 mm block (block-pull.scene) stands on a rigid
 *               flat, pressed by P = 200 N/mm and pulled along x by T,
 *               mu = 0.3.  The loop of [LAC Alg. 1] is run one iteration
 *               at a time (lac_run_iterate) and the status of each of the
 *               4 macro-elements printed after every iteration: S stick,
 *               s slip, . open.  Part 1, T = 50 < mu P = 60: the moment
 *               of T makes the pressure uneven, the block slips between
 *               its ends and sticks at both; the friction force is -T.
 *               Part 2, T = 62 > mu P: every macro-element slips, and no
 *               static solution exists: the run stops with a message that
 *               names the block.
 * Read first:   chapter 07 (the loop), this chapter's sections 1-3.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "io/lac_scene.h"
#include "run/lac_run.h"
#include "solve/lac_friction.h"

// @sect The statuses of a loop, as letters
/* One letter per macro-element of the slave surface into buf (of n
 * bytes): S for stick, s for slip, . for open (solve/lac_friction.h). */
static const char *
statuses (const lac_newton *s, char *buf, size_t n)
{
  size_t k = s->nslot < n - 1 ? s->nslot : n - 1;
  for (size_t i = 0; i < k; i++)
    buf[i] = s->active[i] == LAC_FRICTION_STICK ? 'S'
             : s->active[i] == LAC_FRICTION_SLIP ? 's' : '.';
  buf[k] = 0;
  return buf;
}

// @sect One run, iteration by iteration
/* The scene is read with the traction of its top set to (T/20, -10) (the
 * block is 20 mm wide: a force T per unit length), then run one stage at a
 * time; during the solve stage each call of lac_run_iterate is one
 * iteration of Algorithm 1, after which the statuses and the two
 * multipliers of every macro-element are printed.  Returns the run's
 * status. */
static int
pull (double T)
{
  char set[64], st[64];
  const char *sets[1] = { set };
  lac_scene *sc = NULL;
  snprintf (set, sizeof set, "load.top.traction=%g -10", T / 20);
  int status = lac_scene_read ("chapters/15-friction/block-pull.scene", 1,
                               sets, &sc);
  lac_run_opts o = { NULL, 0, 1, LAC_STRATEGY_AUTO, 0, NULL, 0, 0 };
  lac_run *r = status ? NULL : lac_run_alloc (sc, &o);
  printf ("T = %g, mu P = 60\n  it  statuses  lambda_n (lambda_t) per "
          "macro-element\n", T);
  int it = 0;
  while (r && (status = lac_run_iterate (r)) == LAC_CONTINUE)
    {
      const lac_newton *s = r->sol.newton;
      if (!s || s->nhist == (size_t) it)
        continue;                         /* another stage */
      it = (int) s->nhist;
      printf ("  %2d  %-8s ", it, statuses (s, st, sizeof st));
      for (size_t m = 0; m < s->nslot; m++)
        printf (" %7.2f (%6.2f)", s->lambda[m], s->lambda_t[m]);
      printf ("\n");
    }
  if (status == LAC_SUCCESS)
    printf ("  converged: %s, friction_force = %s\n",
            statuses (r->sol.newton, st, sizeof st),
            lac_run_summary_get (r, "friction_force"));
  else
    printf ("  stopped: %s\n", lac_error_message ());
  lac_run_free (r);
  lac_scene_free (sc);
  return status;
}

// @sect The two parts
/* Below the stick limit the run converges; above it, it must stop. */
int
main (void)
{
  int ok = pull (50) == LAC_SUCCESS;
  int refused = pull (62) != LAC_SUCCESS;
  return ok && refused ? 0 : 1;
}
