/* t612: pairing the facet groups of two box meshes (lac_mesh_box): the
 * top of a lower block against the bottom of an upper one, non-matching,
 * every element family; two meshes, groups as facet lists  [LAC §4.6] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "fem/lac_mesh.h"
#include "contact/lac_pairing.h"
#include "base/lac_status.h"

/* Lower block of type tl (nl cells), upper block of type tu (nu cells)
 * lifted by its height plus `gap`; slave: the lower block's top. */
static void
run (int dim, lac_elem_type tl, const size_t *nl, lac_elem_type tu,
     const size_t *nu, double gap, const char *what)
{
  double L[3] = { 2, 1.5, 1 };
  lac_mesh *lo = NULL, *up = NULL;
  lac_pairing *P = NULL;
  const char *top = dim == 2 ? "ymax" : "zmax", *bot = dim == 2 ? "ymin" : "zmin";
  check_status (lac_mesh_box (tl, nl, L, 0.2, &lo), LAC_SUCCESS, "%s: lower", what);
  check_status (lac_mesh_box (tu, nu, L, 0.2, &up), LAC_SUCCESS, "%s: upper", what);
  if (!lo || !up)
    goto done;
  for (size_t i = 0; i < up->nnodes; i++)
    up->x[(size_t) dim * i + (size_t) dim - 1] += L[dim - 1] + gap;
  lac_pairing_facets fs = lac_pairing_facets_of (lo, lac_mesh_group (lo, top));
  lac_pairing_facets fm = lac_pairing_facets_of (up, lac_mesh_group (up, bot));
  check_true (fs.n > 0 && fm.n > 0, "%s: groups %s, %s", what, top, bot);
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_SUCCESS,
                "%s: build", what);
  if (!P)
    goto done;
  double area = dim == 2 ? L[0] : L[0] * L[1], gmax = 0;
  for (size_t s = 0; s < fs.n; s++)
    {
      check_rel (P->covered[s], P->measure[s], 1e-12, "%s: facet %zu", what, s);
      for (size_t p = P->ptr[s]; p < P->ptr[s + 1]; p++)
        gmax = fmax (gmax, fabs (P->gap[p] - gap));
    }
  check_rel (lac_pairing_total (P), area, 1e-12, "%s: total", what);
  check_abs (gmax, 0, 1e-13, "%s: gaps", what);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: %zu/%zu facets, %zu pairs, %zu points\n", what, fs.n, fm.n,
            P->npairs, P->npoints);
done:
  lac_pairing_free (P);
  lac_mesh_free (lo), lac_mesh_free (up);
}

int
main (void)
{
  size_t a[3] = { 4, 3, 2 }, b[3] = { 5, 4, 2 }, c[3] = { 3, 5, 1 };
  lac_init ();
  run (3, LAC_HEX8, a, LAC_TET4, b, 0, "hex8 / tet4");
  run (3, LAC_TET4, b, LAC_HEX8, a, 0, "tet4 / hex8");
  run (3, LAC_HEX27, c, LAC_TET10, a, 0.01, "hex27 / tet10, gap 0.01");
  run (3, LAC_HEX20, b, LAC_HEX27, c, 0, "hex20 / hex27");
  run (3, LAC_TET10, c, LAC_HEX20, b, 0, "tet10 / hex20");
  run (2, LAC_QUAD4, a, LAC_TRI6, b, 0, "quad4 / tri6 (2D)");
  run (2, LAC_TRI3, b, LAC_QUAD9, c, 0.02, "tri3 / quad9 (2D), gap 0.02");
  run (2, LAC_QUAD8, c, LAC_TRI3, a, 0, "quad8 / tri3 (2D)");
  return check_summary ();
}
