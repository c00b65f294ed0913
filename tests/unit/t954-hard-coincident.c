/* t954: hard case -- coincident and nearly coincident nodes across the
 *       interface                        [LAC §4.6, §5.1; issue 6 item 3]
 *
 * The Taylor patch test (t95-hard.h) with matching interface meshes (the
 * same cells on both sides: every slave node on a master node, every
 * intersection a whole facet or empty), then with the upper block shifted
 * by 1e-12 h: tangentially (slivers of relative width 1e-12 appear next to
 * every facet end and must be integrated or skipped consistently) and
 * normally (an initial gap or penetration of 1e-12 h, rounding level of
 * the coordinates 50 + 1e-11).  h = 12.5 (2D), 16.7 (3D).
 *
 * Expected: exactly the patch-test solution: at most 2 active-set
 * iterations (measured: 1 everywhere, also for the gap of 1e-12 h, whose
 * mean gaps are rounding-level), U, lambda finite, lambda = sigma_vv = -25
 * to 1e-10 (measured 2.5e-12 with the tangential shift, 1e-14 without),
 * beta_h >= 0.4 (2D), 0.2 (hex8, hex20), 0.1 (tet4: 0.125, the tet4
 * refinement of the slave face).
 */
#include "t95-hard.h"

static void
coincident (const char *name, lac_elem_type t, size_t n, double dx,
            double dn, double beta_min)
{
  int dim = lac_refelem_get (t)->dim;
  size_t nn[3] = { n, n, n };
  hard_spec sp;
  hard_taylor (&sp, name, t, nn, t, nn, 0);
  double h = 50.0 / (double) n;
  sp.up.shift[0] += dx * h;
  if (dim == 3)
    sp.up.shift[1] += dx * h;
  sp.up.shift[dim - 1] += dn * h;
  hard_check_taylor (&sp, 2, 1e-10, beta_min);
}

int
main (void)
{
  lac_init ();
  coincident ("matching, quad4", LAC_QUAD4, 4, 0, 0, 0.4);
  coincident ("matching, tri3", LAC_TRI3, 4, 0, 0, 0.4);
  coincident ("matching, quad8", LAC_QUAD8, 4, 0, 0, 0.4);
  coincident ("matching, hex8", LAC_HEX8, 3, 0, 0, 0.2);
  coincident ("matching, tet4", LAC_TET4, 3, 0, 0, 0.1);
  coincident ("matching, hex20", LAC_HEX20, 2, 0, 0, 0.2);
  coincident ("shift 1e-12 h tangential, quad4", LAC_QUAD4, 4, 1e-12, 0, 0.4);
  coincident ("shift 1e-12 h tangential, tri6", LAC_TRI6, 4, 1e-12, 0, 0.4);
  coincident ("shift 1e-12 h tangential, hex8", LAC_HEX8, 3, 1e-12, 0, 0.2);
  coincident ("shift 1e-12 h tangential, tet4", LAC_TET4, 3, 1e-12, 0, 0.1);
  coincident ("shift -1e-12 h tangential, quad4", LAC_QUAD4, 4, -1e-12, 0, 0.4);
  coincident ("shift -1e-12 h tangential, hex8", LAC_HEX8, 3, -1e-12, 0, 0.2);
  coincident ("gap 1e-12 h, quad4", LAC_QUAD4, 4, 0, 1e-12, 0.4);
  coincident ("penetration 1e-12 h, quad4", LAC_QUAD4, 4, 0, -1e-12, 0.4);
  coincident ("gap 1e-12 h, tet4", LAC_TET4, 3, 0, 1e-12, 0.1);
  coincident ("penetration 1e-12 h, hex8", LAC_HEX8, 3, 0, -1e-12, 0.2);
  lac_finalize ();
  return check_summary ();
}
