/* t950: hard case -- mesh-size ratios 1:10 and 10:1 across the interface
 *                                        [LAC §5.1, Thm. 1; issue 6 item 3]
 *
 * The Taylor patch test (t95-hard.h) with a slave trace ten times finer
 * than the master trace, and ten times coarser.  Every intersection of the
 * two interface meshes is integrated exactly and the constant multiplier
 * is in X^h, so lambda = sigma_vv = -25 stays exact to rounding (1e-12),
 * one active-set iteration (all closed from the start).
 *
 * beta_h (H1 norm, dense path) stays bounded below, but a coarse master
 * lowers it: in 2D quad4 with n slave cells against 4 master cells it
 * settles at 0.441 (n = 30, 40, 80: 0.4454, 0.4430, 0.4408) instead of
 * 0.623 for matching meshes -- the ratio is sqrt(2): a fine master shares
 * the jump [v_N] of an oscillating pattern half and half between two equal
 * bodies (half the H1 norm squared), a coarse master cannot follow the
 * pattern and the slave body carries it alone.  A coarse slave has few
 * multipliers and a large beta_h.  3D hex8 10 x 10 slave cells: 0.163
 * with 1 x 1 or 10 x 10 master cells.  Bounds asserted: 0.4 (2D), 0.1
 * (3D); the table is in chapters/11-infsup/README.md, "Hard cases".
 */
#include "t95-hard.h"

static void
ratio (const char *name, lac_elem_type t, size_t nlo, size_t nup, int swap,
       double beta_min)
{
  size_t lo[3] = { nlo, nlo, nlo }, up[3] = { nup, nup, nup };
  if (nlo > 10)
    lo[2] = 3;             /* a fine master block, thin cells (time) */
  hard_spec sp;
  hard_taylor (&sp, name, t, lo, t, up, swap);
  hard_check_taylor (&sp, 1, 1e-12, beta_min);
}

int
main (void)
{
  lac_init ();
  /* slave = upper bottom; swap = 1: slave = lower top */
  ratio ("ratio 10:1 quad4 (slave fine)", LAC_QUAD4, 4, 40, 0, 0.4);
  ratio ("ratio 1:10 quad4 (slave coarse)", LAC_QUAD4, 40, 4, 0, 0.4);
  ratio ("ratio 10:1 tri6 (slave fine)", LAC_TRI6, 2, 20, 0, 0.4);
  ratio ("ratio 1:10 tri6 (slave coarse)", LAC_TRI6, 20, 2, 0, 0.4);
  ratio ("ratio 10:1 quad8 (slave fine, lower)", LAC_QUAD8, 20, 2, 1, 0.4);
  ratio ("ratio 10:1 hex8 (slave fine)", LAC_HEX8, 1, 10, 0, 0.1);
  ratio ("ratio 1:10 hex8 (slave coarse)", LAC_HEX8, 20, 2, 0, 0.1);
  ratio ("ratio 10:1 tet4 (slave fine)", LAC_TET4, 1, 10, 0, 0.1);
  lac_finalize ();
  return check_summary ();
}
