/* t804: the contact views -- facets coloured one value each, discs
 *
 * 3D: the facet group zmax of a hex20 box seen from above, one value per
 * facet spanning the map: as many colours as facets, the colour bar.  2D:
 * the facet group ymax of a quad8 box as thick lines over the grey mesh:
 * both ends of the map appear, unshaded.  Discs at the facet centroids of
 * a 3D box (seen through the grey body) and of a 2D box.  Bad requests.
 */
#include <math.h>
#include "check.h"
#include "base/lac_mem.h"
#include "render/lac_render.h"
#include "base/lac_status.h"
#include "t8-render.h"

static void
test_facets_3d (void)
{
  size_t n[3] = { 4, 3, 2 };
  double L[3] = { 4, 3, 1 }, *v;
  lac_mesh *m = NULL;
  const lac_group *g;
  lac_render_opts o;
  const char *path = t8_path ("t804-facets-3d.png");
  unsigned char *img;
  int w, h, rows;
  check_status (lac_mesh_box (LAC_HEX20, n, L, 0, &m), LAC_SUCCESS, "box");
  g = lac_mesh_group (m, "zmax");
  check_true (g && g->n == 12, "group zmax of 12 facets");
  if (!g)
    {
      lac_mesh_free (m);
      return;
    }
  v = lac_malloc (g->n * sizeof *v);
  for (size_t k = 0; k < g->n; k++)
    v[k] = -25.0 + (double) k;
  lac_render_opts_init (&o);
  o.elevation = 90;
  o.azimuth = 0;
  o.edges = 1;
  o.title = "t804: lambda per facet (top view)";
  o.label = "lambda";
  o.units = "MPa";
  check_status (lac_render_facets (m, NULL, g->n, g->cell, g->face, v, &o,
                                   path), LAC_SUCCESS, "facets 3D");
  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (img)
    {
      check_true (t8_colorbar_column (img, w, h, w / 2, &rows) > 3 * w / 4,
                  "colour bar");
      check_true (t8_frac_drawn (img, w, 0, 3 * w / 4, 0, h) > 0.30,
                  "drawn: %g", t8_frac_drawn (img, w, 0, 3 * w / 4, 0, h));
      check_true (t8_distinct (img, w, 0, 3 * w / 4, 60, h) >= 12,
                  "one colour per facet at least");
      free (img);
    }
  /* the same group drawn obliquely, displaced */
  o.elevation = 35;
  o.azimuth = 30;
  check_status (lac_render_facets (m, m->x, g->n, g->cell, g->face, v, &o,
                                   t8_path ("t804-facets-3d-oblique.png")),
                LAC_SUCCESS, "facets 3D oblique");
  /* bad requests */
  check_status (lac_render_facets (m, NULL, g->n, NULL, g->face, v, &o,
                                   path), LAC_EINVAL, "no cell array");
  {
    int bad = 9;
    size_t c = 0;
    check_status (lac_render_facets (m, NULL, 1, &c, &bad, v, &o, path),
                  LAC_EINVAL, "face 9");
  }
  lac_free (v);
  lac_mesh_free (m);
}

static void
test_facets_2d (void)
{
  size_t n[2] = { 6, 2 };
  double L[2] = { 3, 1 }, *v;
  lac_mesh *m = NULL;
  const lac_group *g;
  lac_render_opts o;
  const char *path = t8_path ("t804-facets-2d.png");
  unsigned char *img;
  int w, h, rows;
  check_status (lac_mesh_box (LAC_QUAD8, n, L, 0.15, &m), LAC_SUCCESS,
                "box");
  g = lac_mesh_group (m, "ymax");
  check_true (g && g->n == 6, "group ymax of 6 facets");
  if (!g)
    {
      lac_mesh_free (m);
      return;
    }
  v = lac_malloc (g->n * sizeof *v);
  for (size_t k = 0; k < g->n; k++)
    v[k] = (double) (g->cell[k] % 6);
  lac_render_opts_init (&o);
  o.width = 600;
  o.height = 300;
  o.edges = 1;
  o.label = "lambda";
  check_status (lac_render_facets (m, NULL, g->n, g->cell, g->face, v, &o,
                                   path), LAC_SUCCESS, "facets 2D");
  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (img)
    {
      int bar = t8_colorbar_column (img, w, h, w / 2, &rows);
      check_true (bar > w / 2, "colour bar");
      check_true (t8_count_map (img, w, 0, bar - 20, 0, h, 0, 0.02, 2)
                  > 20, "low end on the lines");
      check_true (t8_count_map (img, w, 0, bar - 20, 0, h, 0.98, 1, 2)
                  > 20, "high end on the lines");
      check_true (t8_frac_drawn (img, w, 0, w / 2, 0, h) > 0.30, "drawn");
      free (img);
    }
  lac_free (v);
  lac_mesh_free (m);
}

/* Discs at the centroids of the facets of group `name`. */
static void
discs (lac_elem_type t, const char *name, const char *file)
{
  size_t n[3] = { 4, 4, 2 };
  double L[3] = { 4, 4, 2 }, *xyz, *v;
  lac_mesh *m = NULL;
  const lac_group *g;
  lac_render_opts o;
  const char *path = t8_path (file);
  unsigned char *img;
  int w, h, rows, nodes[LAC_MAX_NODES];
  check_status (lac_mesh_box (t, n, L, 0, &m), LAC_SUCCESS, "%s box", file);
  g = m ? lac_mesh_group (m, name) : NULL;
  if (!g)
    {
      check_true (0, "%s: group %s", file, name);
      lac_mesh_free (m);
      return;
    }
  xyz = lac_calloc (3 * g->n, sizeof *xyz);
  v = lac_malloc (g->n * sizeof *v);
  for (size_t k = 0; k < g->n; k++)
    {
      lac_elem_type ft;
      int nv, nn = lac_mesh_facet_nodes (m, g->cell[k], g->face[k], nodes,
                                         &ft);
      nv = lac_refelem_get (ft)->nvertices;
      for (int a = 0; a < nv && nn > 0; a++)
        for (int i = 0; i < m->dim; i++)
          xyz[3 * k + (size_t) i] += m->x[(size_t) nodes[a]
                                          * (size_t) m->dim + (size_t) i] / nv;
      v[k] = xyz[3 * k] + xyz[3 * k + 1];
    }
  lac_render_opts_init (&o);
  o.width = 500;
  o.height = 400;
  o.edges = 1;
  o.label = "lambda";
  check_status (lac_render_points (m, NULL, g->n, xyz, NULL, v, &o, path),
                LAC_SUCCESS, "%s: discs", file);
  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (img)
    {
      check_true (t8_colorbar_column (img, w, h, w / 2, &rows) > w / 2,
                  "%s: colour bar", file);
      check_true (t8_distinct (img, w, 0, w / 2, 0, h) > 10,
                  "%s: disc colours", file);
      free (img);
    }
  check_status (lac_render_points (NULL, NULL, g->n, xyz, NULL, v, &o,
                                   t8_path ("t804-discs-alone.png")),
                LAC_SUCCESS, "%s: discs without the mesh", file);
  check_status (lac_render_points (m, NULL, g->n, NULL, NULL, v, &o, path),
                LAC_EINVAL, "%s: no coordinates", file);
  lac_free (xyz);
  lac_free (v);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  test_facets_3d ();
  test_facets_2d ();
  discs (LAC_HEX8, "zmax", "t804-discs-3d.png");
  discs (LAC_TRI3, "ymax", "t804-discs-2d.png");
  return check_summary ();
}
