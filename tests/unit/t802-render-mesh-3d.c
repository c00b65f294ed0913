/* t802: render the boundary surface of 3D meshes
 *
 * A hex20 box coloured by a curved field (oblique view, lit): the picture
 * is mostly drawn, has many colours and the colour bar; the boundary faces
 * found by hashing are exactly the faces of the box surface for every 3D
 * element type; a hex20 shell octant (curved faces) drawn grey shows
 * several grey levels (lighting); tet10 and views from other directions
 * render too.
 */
#include <math.h>
#include "check.h"
#include "base/lac_mem.h"
#include "render/lac_render.h"
#include "render/lac_render_internal.h"
#include "base/lac_status.h"
#include "t8-render.h"

static void
test_box_field (void)
{
  size_t n[3] = { 4, 3, 2 };
  double L[3] = { 2, 1.5, 1 }, *f, *u;
  lac_mesh *m = NULL;
  lac_render_opts o;
  const char *path = t8_path ("t802-hex20.png");
  unsigned char *img;
  int w, h, bar, rows;

  check_status (lac_mesh_box (LAC_HEX20, n, L, 0, &m), LAC_SUCCESS, "box");
  f = lac_malloc (m->nnodes * sizeof *f);
  u = lac_malloc (3 * m->nnodes * sizeof *u);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double x = m->x[3 * a], y = m->x[3 * a + 1], z = m->x[3 * a + 2];
      f[a] = sin (1.5 * x) * cos (2 * y) + z * z;
      u[3 * a] = 0;
      u[3 * a + 1] = 0;
      u[3 * a + 2] = -0.1 * x * x;          /* bending: curved faces */
    }
  lac_render_opts_init (&o);
  o.edges = 1;
  o.scale = 1;
  o.title = "t802: hex20 box, bent";
  o.label = "f";
  check_status (lac_render_mesh (m, u, f, &o, path), LAC_SUCCESS, "render");
  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (img)
    {
      check_int (w, 800, "default width");
      check_int (h, 600, "default height");
      bar = t8_colorbar_column (img, w, h, w / 2, &rows);
      check_true (bar > 3 * w / 4, "colour bar at x = %d", bar);
      check_true (t8_frac_drawn (img, w, 0, 3 * w / 4, 0, h) > 0.30,
                  "drawn: %g", t8_frac_drawn (img, w, 0, 3 * w / 4, 0, h));
      check_true (t8_distinct (img, w, 0, 3 * w / 4, 0, h) > 200,
                  "distinct colours in the picture: %zu",
                  t8_distinct (img, w, 0, 3 * w / 4, 0, h));
      free (img);
    }
  lac_free (f);
  lac_free (u);
  lac_mesh_free (m);
}

/* The boundary of an n0 x n1 x n2 box has 2 (n0 n1 + n1 n2 + n0 n2)
 * squares: that many quads, or twice as many triangles. */
static void
test_boundary_counts (void)
{
  static const lac_elem_type types[] = { LAC_TET4, LAC_TET10, LAC_HEX8,
                                         LAC_HEX20, LAC_HEX27 };
  size_t n[3] = { 3, 2, 2 };
  double L[3] = { 1, 1, 1 };
  size_t squares = 2 * (3 * 2 + 2 * 2 + 3 * 2);
  for (size_t t = 0; t < sizeof types / sizeof *types; t++)
    {
      lac_mesh *m = NULL;
      size_t nf = 0, *cell = NULL;
      int *face = NULL;
      const lac_refelem *re = lac_refelem_get (types[t]);
      if (lac_mesh_box (types[t], n, L, 0.1, &m))
        {
          check_true (0, "%s box", re->name);
          continue;
        }
      check_status (lac_render_boundary_faces (m, &nf, &cell, &face),
                    LAC_SUCCESS, "%s boundary", re->name);
      check_int ((long) nf, (long) (re->shape == LAC_SHAPE_TET ? 2 * squares
                                    : squares), "%s boundary faces",
                 re->name);
      lac_free (cell);
      lac_free (face);
      lac_mesh_free (m);
    }
}

/* (x, y, z) of [0,1]^3 -> part of the shell 20 <= R <= 40 (0 <= phi <= 60 deg). */
static void
to_shell (lac_mesh *m)
{
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double *x = m->x + 3 * a, R = 20 + 20 * x[0],
        th = x[1] * 1.5707963267948966, ph = x[2] * 1.0471975511965976;
      x[0] = R * cos (th) * cos (ph);
      x[1] = R * sin (th) * cos (ph);
      x[2] = R * sin (ph);
    }
}

static void
test_shell (void)
{
  size_t n[3] = { 2, 4, 4 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  lac_render_opts o;
  unsigned char *img;
  int w, h, rows;
  const char *path = t8_path ("t802-shell.png");

  check_status (lac_mesh_box (LAC_HEX20, n, L, 0, &m), LAC_SUCCESS, "box");
  to_shell (m);
  lac_render_opts_init (&o);
  o.width = 480;
  o.height = 400;
  o.edges = 1;
  o.title = "hex20 shell octant";
  check_status (lac_render_mesh (m, NULL, NULL, &o, path), LAC_SUCCESS,
                "render shell");
  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (img)
    {
      size_t levels = 0;
      static char seen[256];
      for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
          {
            const unsigned char *p = t8_px (img, w, x, y);
            if (p[0] == p[1] && p[1] == p[2] && p[0] > 60 && p[0] < 250)
              {
                levels += !seen[p[0]];
                seen[p[0]] = 1;
              }
          }
      check_true (levels > 20, "lit surface: %zu grey levels", levels);
      check_int (t8_colorbar_column (img, w, h, 0, &rows), -1, "no bar");
      check_true (t8_frac_drawn (img, w, 0, w, 0, h) > 0.20, "drawn");
      free (img);
    }

  /* other views and element types */
  lac_mesh_free (m);
  m = NULL;
  check_status (lac_mesh_box (LAC_TET10, n, L, 0.1, &m), LAC_SUCCESS, "tet10");
  to_shell (m);
  o.azimuth = -120;
  o.elevation = 60;
  o.title = "tet10 shell octant, az -120 el 60";
  check_status (lac_render_mesh (m, NULL, m->x, &o, t8_path ("t802-tet10.png")),
                LAC_SUCCESS, "tet10 view");
  o.elevation = 90;
  check_status (lac_render_mesh (m, NULL, NULL, &o,
                                 t8_path ("t802-top.png")), LAC_SUCCESS,
                "view from the top");
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  test_box_field ();
  test_boundary_counts ();
  test_shell ();
  return check_summary ();
}
