/* t8-render.h -- helpers of the render tests (t80x): read a PNG back with
 * libpng's simplified API and measure it.  Header-only, static functions.
 *
 * Pictures are written to $B/tests/render (in the build directory, kept so
 * that they can be looked at) or to /tmp when B is not set.
 */
#ifndef T8_RENDER_H
#define T8_RENDER_H

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "render/lac_render.h"

/* ${B}/tests/render/NAME, or /tmp/lac-NAME. */
static inline const char *
t8_path (const char *name)
{
  static char buf[4][512];
  static int k;
  const char *b = getenv ("B");
  char *p = buf[k++ % 4];
  if (b && *b)
    {
      snprintf (p, 512, "%s/tests", b);
      mkdir (p, 0777);
      snprintf (p, 512, "%s/tests/render", b);
      mkdir (p, 0777);
      snprintf (p, 512, "%s/tests/render/%s", b, name);
    }
  else
    snprintf (p, 512, "/tmp/lac-%s", name);
  return p;
}

/* The image as RGBA (malloc'ed, top row first), NULL if unreadable. */
static inline unsigned char *
t8_read_png (const char *path, int *w, int *h)
{
  png_image img;
  unsigned char *buf;
  memset (&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file (&img, path))
    return NULL;
  img.format = PNG_FORMAT_RGBA;
  buf = malloc (PNG_IMAGE_SIZE (img));
  if (!buf || !png_image_finish_read (&img, NULL, buf, 0, NULL))
    {
      free (buf);
      png_image_free (&img);
      return NULL;
    }
  *w = (int) img.width;
  *h = (int) img.height;
  return buf;
}

static inline const unsigned char *
t8_px (const unsigned char *img, int w, int x, int y)
{
  return img + 4 * ((size_t) y * (size_t) w + (size_t) x);
}

/* Fraction of the pixels of [x0,x1) x [y0,y1) that are not white. */
static inline double
t8_frac_drawn (const unsigned char *img, int w, int x0, int x1, int y0,
               int y1)
{
  size_t n = 0, tot = 0;
  for (int y = y0; y < y1; y++)
    for (int x = x0; x < x1; x++, tot++)
      {
        const unsigned char *p = t8_px (img, w, x, y);
        n += p[0] < 250 || p[1] < 250 || p[2] < 250;
      }
  return tot ? (double) n / (double) tot : 0;
}

/* The t in [0, 1] whose viridis colour is nearest to p; *dist = the
 * largest channel difference there.  The map is piecewise linear between
 * the 17 colours at k/16: p is projected on each of the 16 pieces. */
static inline double
t8_nearest_t (const unsigned char *p, int *dist)
{
  static double knot[17][3];
  static int ready;
  double best_t = 0, best = 1e30;
  unsigned char c[3];
  if (!ready)
    for (int k = 0; k <= 16; k++)
      {
        lac_render_colormap (k / 16.0, c);
        for (int i = 0; i < 3; i++)
          knot[k][i] = c[i];
      }
  ready = 1;
  for (int k = 0; k < 16; k++)
    {
      double d[3], q[3], dd = 0, dq = 0, s, e = 0;
      for (int i = 0; i < 3; i++)
        {
          d[i] = knot[k + 1][i] - knot[k][i];
          q[i] = p[i] - knot[k][i];
          dd += d[i] * d[i];
          dq += d[i] * q[i];
        }
      s = dd > 0 ? dq / dd : 0;
      s = s < 0 ? 0 : s > 1 ? 1 : s;
      for (int i = 0; i < 3; i++)
        e += (q[i] - s * d[i]) * (q[i] - s * d[i]);
      if (e < best)
        {
          best = e;
          best_t = (k + s) / 16.0;
        }
    }
  lac_render_colormap (best_t, c);
  *dist = 0;
  for (int i = 0; i < 3; i++)
    *dist = abs ((int) c[i] - (int) p[i]) > *dist
            ? abs ((int) c[i] - (int) p[i]) : *dist;
  return best_t;
}

/* Count the pixels of [x0,x1) x [y0,y1) within tol of viridis(t) with t
 * in [t0, t1]. */
static inline size_t
t8_count_map (const unsigned char *img, int w, int x0, int x1, int y0, int y1,
              double t0, double t1, int tol)
{
  size_t n = 0;
  for (int y = y0; y < y1; y++)
    for (int x = x0; x < x1; x++)
      {
        int d;
        double t = t8_nearest_t (t8_px (img, w, x, y), &d);
        n += d <= tol && t >= t0 && t <= t1;
      }
  return n;
}

/* Number of distinct colours (15 bits) in [x0,x1) x [y0,y1). */
static inline size_t
t8_distinct (const unsigned char *img, int w, int x0, int x1, int y0, int y1)
{
  static unsigned char seen[1 << 15];
  size_t n = 0;
  memset (seen, 0, sizeof seen);
  for (int y = y0; y < y1; y++)
    for (int x = x0; x < x1; x++)
      {
        const unsigned char *p = t8_px (img, w, x, y);
        int key = (p[0] >> 3) << 10 | (p[1] >> 3) << 5 | p[2] >> 3;
        n += !seen[key];
        seen[key] = 1;
      }
  return n;
}

/* The colour bar: the rightmost column x >= x0 in which at least half of
 * the rows are viridis colours decreasing from t > 0.97 (top) to t < 0.03
 * (bottom); -1 if none.  *rows: the matched rows. */
static inline int
t8_colorbar_column (const unsigned char *img, int w, int h, int x0, int *rows)
{
  for (int x = w - 1; x >= x0; x--)
    {
      int n = 0, mono = 1, d;
      double tprev = 2, tmax = -1, tmin = 2;
      for (int y = 0; y < h; y++)
        {
          double t = t8_nearest_t (t8_px (img, w, x, y), &d);
          if (d > 3)
            continue;
          n++;
          mono &= t <= tprev + 0.01;
          tprev = t;
          tmax = t > tmax ? t : tmax;
          tmin = t < tmin ? t : tmin;
        }
      if (n >= h / 2 && mono && tmax > 0.97 && tmin < 0.03)
        {
          *rows = n;
          return x;
        }
    }
  *rows = 0;
  return -1;
}

#endif /* T8_RENDER_H */
