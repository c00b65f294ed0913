/* t801: render a 2D mesh to a PNG and look at the pixels
 *
 * A tri6 box mapped onto a quarter annulus 20 <= r <= 40 (curved cells)
 * coloured by a field that spans the colour map, with edges, a title and
 * units: most of the picture is drawn, both ends of the map and the colours
 * in between appear in the picture, the colour bar is a column of map
 * colours on the right; then a grey deformed quad8 mesh without field (no
 * colour bar), the tick helpers and bad requests.
 */
#include <math.h>
#include "check.h"
#include "base/lac_mem.h"
#include "render/lac_render.h"
#include "render/lac_render_internal.h"
#include "base/lac_status.h"
#include "t8-render.h"

/* (x, y) in [0,1]^2 -> quarter annulus, nodes placed exactly on arcs. */
static void
to_annulus (lac_mesh *m)
{
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double r = 20 + 20 * m->x[2 * a], th = m->x[2 * a + 1] * 1.5707963267948966;
      m->x[2 * a] = r * cos (th);
      m->x[2 * a + 1] = r * sin (th);
    }
}

static void
test_annulus (void)
{
  size_t n[2] = { 6, 4 };
  double L[2] = { 1, 1 }, *f;
  lac_mesh *m = NULL;
  lac_render_opts o;
  const char *path = t8_path ("t801-annulus.png");
  unsigned char *img;
  int w, h, bar, rows, bins = 0;

  check_status (lac_mesh_box (LAC_TRI6, n, L, 0, &m), LAC_SUCCESS, "box");
  to_annulus (m);
  f = lac_malloc (m->nnodes * sizeof *f);
  for (size_t a = 0; a < m->nnodes; a++)         /* sigma_rr-like, 0 .. 1 */
    {
      double x = m->x[2 * a], y = m->x[2 * a + 1], r2 = x * x + y * y;
      f[a] = -25 * (1600 / r2 - 1) / 3 + 2 * y / 40;
    }
  lac_render_opts_init (&o);
  o.width = 640;
  o.height = 480;
  o.edges = 1;
  o.title = "t801: quarter annulus, tri6 (curved)";
  o.label = "stress_rr";
  o.units = "MPa";
  check_status (lac_render_mesh (m, NULL, f, &o, path), LAC_SUCCESS,
                "render annulus");

  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (!img)
    goto done;
  check_int (w, 640, "width");
  check_int (h, 480, "height");
  bar = t8_colorbar_column (img, w, h, w / 2, &rows);
  check_true (bar > 3 * w / 4, "colour bar column at x = %d (> %d), %d rows",
              bar, 3 * w / 4, rows);
  check_true (t8_frac_drawn (img, w, 0, w * 3 / 4, 0, h) > 0.30,
              "more than 30%% of the picture drawn: %g",
              t8_frac_drawn (img, w, 0, w * 3 / 4, 0, h));
  /* both ends and the colours between them, in the picture itself */
  check_true (t8_count_map (img, w, 0, w * 3 / 4, 0, h, 0, 0.03, 3) > 50,
              "low end of the map in the picture");
  check_true (t8_count_map (img, w, 0, w * 3 / 4, 0, h, 0.97, 1, 3) > 50,
              "high end of the map in the picture");
  for (int k = 0; k < 10; k++)
    bins += t8_count_map (img, w, 0, w * 3 / 4, 0, h, k / 10.0,
                          (k + 1) / 10.0, 3) > 20;
  check_int (bins, 10, "all ten tenths of the map appear");
  check_true (t8_distinct (img, w, 0, w, 0, h) > 200, "distinct colours");
  /* the corner is background, the title is dark pixels on top */
  check_true (t8_frac_drawn (img, w, 0, 8, h - 8, h) == 0, "corner white");
  check_true (t8_frac_drawn (img, w, w / 4, 3 * w / 4, 0, 40) > 0.02,
              "title drawn");
  free (img);
done:
  lac_free (f);
  lac_mesh_free (m);
}

static void
test_grey_deformed (void)
{
  size_t n[2] = { 4, 2 };
  double L[2] = { 2, 1 }, *u;
  lac_mesh *m = NULL;
  lac_render_opts o;
  const char *path = t8_path ("t801-grey.png");
  unsigned char *img;
  int w, h, rows;

  check_status (lac_mesh_box (LAC_QUAD8, n, L, 0.1, &m), LAC_SUCCESS, "box");
  u = lac_malloc (2 * m->nnodes * sizeof *u);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double x = m->x[2 * a], y = m->x[2 * a + 1];
      u[2 * a] = 0.1 * y * y;
      u[2 * a + 1] = -0.05 * x * x;
    }
  lac_render_opts_init (&o);
  o.width = 400;
  o.height = 300;
  o.scale = 2;
  o.edges = 1;
  check_status (lac_render_mesh (m, u, NULL, &o, path), LAC_SUCCESS,
                "render grey");
  img = t8_read_png (path, &w, &h);
  check_true (img != NULL, "read back %s", path);
  if (img)
    {
      check_true (t8_frac_drawn (img, w, 0, w, 0, h) > 0.30, "drawn");
      check_int (t8_colorbar_column (img, w, h, 0, &rows), -1,
                 "no colour bar without a field");
      check_true (t8_count_map (img, w, 0, w, 0, h, 0, 1, 2) < 50,
                  "no map colour without a field");
      free (img);
    }

  /* bad requests */
  check_status (lac_render_mesh (NULL, NULL, NULL, &o, path), LAC_EINVAL,
                "NULL mesh");
  o.width = 10;
  check_status (lac_render_mesh (m, NULL, NULL, &o, path), LAC_EINVAL,
                "width 10");
  check_message ("image size", "message names the size");
  o.width = 400;
  u[3] = NAN;
  check_status (lac_render_mesh (m, u, NULL, &o, path), LAC_EINVAL, "NaN u");
  check_message ("non-finite", "message for NaN");
  check_status (lac_render_mesh (m, NULL, NULL, &o, "/nonexistent/dir/x.png"),
                LAC_EIO, "unwritable path");
  check_message ("/nonexistent/dir/x.png", "message names the path");
  lac_free (u);
  lac_mesh_free (m);
}

static void
test_ticks (void)
{
  double t[16], step;
  char buf[32];
  size_t n = lac_render_ticks (0, 5, t, 16, &step);
  check_int ((long) n, 6, "ticks of [0, 5]");
  check_abs (step, 1, 1e-15, "step of [0, 5]");
  check_abs (t[5], 5, 1e-12, "last tick");
  n = lac_render_ticks (-26.25, -23.75, t, 16, &step);
  check_abs (step, 0.5, 1e-15, "step of [-26.25, -23.75]");
  check_abs (t[0], -26, 1e-12, "first tick inside");
  lac_render_tick_label (-25, 0.5, 26.25, buf, sizeof buf);
  check_true (!strcmp (buf, "-25.0"), "label '%s'", buf);
  lac_render_tick_label (1.5e-4, 5e-5, 2e-4, buf, sizeof buf);
  check_true (!strcmp (buf, "1.5e-04"), "label '%s'", buf);
  lac_render_tick_label (0, 1e5, 4e5, buf, sizeof buf);
  check_true (!strcmp (buf, "0e+00"), "label '%s'", buf);
  check_int (lac_render_text_width (NULL, "abc", 2), 34, "text width");
  {
    unsigned char c[3];
    lac_render_colormap (0, c);
    check_int (c[0] * 65536 + c[1] * 256 + c[2], 0x440154, "viridis(0)");
    lac_render_colormap (1, c);
    check_int (c[0] * 65536 + c[1] * 256 + c[2], 0xfde725, "viridis(1)");
    lac_render_colormap (0.5, c);
    check_int (c[0] * 65536 + c[1] * 256 + c[2], 0x21918c, "viridis(0.5)");
  }
}

/* Pixels of rows y0..y1-1: those of pure ink (0) and the grey ones between
 * ink and paper (anti-aliased edges: FreeType's glyphs, not the bitmap's). */
static void
ink_and_grey (const unsigned char *img, int w, int y0, int y1, int *ink,
              int *grey)
{
  *ink = *grey = 0;
  for (int y = y0; y < y1; y++)
    for (int x = 0; x < w; x++)
      {
        const unsigned char *p = img + 4 * ((size_t) y * (size_t) w + x);
        *ink += p[0] == 0 && p[1] == 0 && p[2] == 0;
        *grey += p[0] > 0 && p[0] < 255 && p[0] == p[1] && p[1] == p[2];
      }
}

/* The title drawn with FreeType (DejaVu Sans, the default) and with the
 * bitmap font (font ""); a font file that is not there. */
static void
test_font (void)
{
  size_t n[2] = { 2, 2 };
  double L[2] = { 1, 1 };
  lac_mesh *m = NULL;
  lac_render_opts o;
  lac_render_font *f = NULL;
  unsigned char *img[2];
  const char *fonts[2] = { NULL, "" };
  int ink[2], grey[2];

  check_status (lac_mesh_box (LAC_QUAD4, n, L, 0, &m), LAC_SUCCESS, "box");
  lac_render_opts_init (&o);
  o.width = 400;
  o.height = 300;
  o.title = "Title: sigma_rr (MPa), 0123456789";
  for (int k = 0; k < 2; k++)
    {
      o.font = fonts[k];
      img[k] = malloc (4 * 400 * 300);
      check_status (lac_render_mesh_rgba (m, NULL, NULL, &o, img[k]),
                    LAC_SUCCESS, "render with font %d", k);
      ink_and_grey (img[k], 400, 0, 19, &ink[k], &grey[k]);  /* the title */
    }
  check_true (grey[0] > 100 && grey[0] > 5 * ink[0],
              "FreeType's title: %d grey, %d ink pixels", grey[0], ink[0]);
  check_true (grey[1] == 0 && ink[1] > 100,
              "bitmap title: %d grey, %d ink pixels", grey[1], ink[1]);
  free (img[0]);
  free (img[1]);

  o.font = "/nonexistent/font.ttf";
  img[0] = malloc (4 * 400 * 300);
  check_status (lac_render_mesh_rgba (m, NULL, NULL, &o, img[0]), LAC_EIO,
                "missing font file");
  check_message ("/nonexistent/font.ttf", "message names the font file");
  o.font = "tests/unit/t801-render-mesh-2d.c";
  check_status (lac_render_mesh_rgba (m, NULL, NULL, &o, img[0]), LAC_EIO,
                "not a font");
  check_message ("not a font", "message says it is not a font");
  free (img[0]);

  /* proportional glyphs, about the bitmap's size */
  check_status (lac_render_font_open (NULL, &f), LAC_SUCCESS, "open DejaVu");
  check_true (f != NULL, "the default font %s is installed",
              LAC_RENDER_FONT_DEFAULT);
  if (f)
    {
      int wi = lac_render_text_width (f, "iiii", 2),
        wm = lac_render_text_width (f, "MMMM", 2),
        wa = lac_render_text_width (f, "abc", 2);
      check_true (wi < wm / 2, "proportional: iiii %d, MMMM %d", wi, wm);
      check_true (wa > 25 && wa < 45, "abc at scale 2: %d pixels", wa);
      check_int (lac_render_text_width (f, "", 2), 0, "empty text");
    }
  lac_render_font_free (f);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  test_annulus ();
  test_grey_deformed ();
  test_ticks ();
  test_font ();
  return check_summary ();
}
