/* lac_render_text.c -- colour map, bitmap font, ticks and the colour bar
 *
 * The text of a picture (title, colour bar labels) is written straight into
 * the RGBA pixels after OSMesa has drawn the mesh, with a TrueType font
 * through FreeType (lac_render_font.c) or, without one, with a 5x7 bitmap
 * font (printable ASCII, descenders on two extra rows) magnified by an
 * integer factor.  The glyphs were drawn for this file in the style of the
 * classic 5x7 dot-matrix character sets.
 *
 * The colour map is viridis (van der Walt and Smith, 2015): its published
 * 8-bit colours at t = k/16, k = 0..16, interpolated linearly in sRGB (the
 * error against the 256-entry table is about one level per channel).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "render/lac_render_internal.h"

/* ---- colour map -------------------------------------------------------- */

static const unsigned char viridis17[17][3] = {
  { 0x44, 0x01, 0x54 }, { 0x48, 0x18, 0x6a }, { 0x47, 0x2d, 0x7b },
  { 0x42, 0x40, 0x86 }, { 0x3b, 0x52, 0x8b }, { 0x33, 0x63, 0x8d },
  { 0x2c, 0x72, 0x8e }, { 0x26, 0x82, 0x8e }, { 0x21, 0x91, 0x8c },
  { 0x1f, 0xa0, 0x88 }, { 0x28, 0xae, 0x80 }, { 0x3f, 0xbc, 0x73 },
  { 0x5e, 0xc9, 0x62 }, { 0x84, 0xd4, 0x4b }, { 0xad, 0xdc, 0x30 },
  { 0xd8, 0xe2, 0x19 }, { 0xfd, 0xe7, 0x25 }
};

void
lac_render_colormap (double t, unsigned char rgb[3])
{
  double s;
  int k;
  if (isnan (t))
    {
      rgb[0] = rgb[1] = rgb[2] = 160;
      return;
    }
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  s = t * 16.0;
  k = (int) s;
  if (k > 15)
    k = 15;
  s -= k;                               /* weight of entry k+1 */
  for (int i = 0; i < 3; i++)
    rgb[i] = (unsigned char) lround ((1 - s) * viridis17[k][i]
                                     + s * viridis17[k + 1][i]);
}

/* ---- font -------------------------------------------------------------- */

/* Rows top to bottom, bit 4 = left column; row 6 is the baseline row,
 * rows 7-8 the descenders.  Characters 32..126. */
static const unsigned char bitmap[95][LAC_FONT_H] = {
  { 0, 0, 0, 0, 0, 0, 0, 0, 0 },                               /* ' ' */
  { 0x04, 0x04, 0x04, 0x04, 0x04, 0x00, 0x04, 0, 0 },          /* !  */
  { 0x0a, 0x0a, 0x0a, 0x00, 0x00, 0x00, 0x00, 0, 0 },          /* "  */
  { 0x0a, 0x0a, 0x1f, 0x0a, 0x1f, 0x0a, 0x0a, 0, 0 },          /* #  */
  { 0x04, 0x0f, 0x14, 0x0e, 0x05, 0x1e, 0x04, 0, 0 },          /* $  */
  { 0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03, 0, 0 },          /* %  */
  { 0x0c, 0x12, 0x14, 0x08, 0x15, 0x12, 0x0d, 0, 0 },          /* &  */
  { 0x04, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00, 0, 0 },          /* '  */
  { 0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02, 0, 0 },          /* (  */
  { 0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08, 0, 0 },          /* )  */
  { 0x00, 0x04, 0x15, 0x0e, 0x15, 0x04, 0x00, 0, 0 },          /* *  */
  { 0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00, 0, 0 },          /* +  */
  { 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x04, 0x08 },    /* ,  */
  { 0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00, 0, 0 },          /* -  */
  { 0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c, 0, 0 },          /* .  */
  { 0x01, 0x01, 0x02, 0x04, 0x08, 0x10, 0x10, 0, 0 },          /* /  */
  { 0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e, 0, 0 },          /* 0  */
  { 0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e, 0, 0 },          /* 1  */
  { 0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f, 0, 0 },          /* 2  */
  { 0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e, 0, 0 },          /* 3  */
  { 0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02, 0, 0 },          /* 4  */
  { 0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e, 0, 0 },          /* 5  */
  { 0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e, 0, 0 },          /* 6  */
  { 0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08, 0, 0 },          /* 7  */
  { 0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e, 0, 0 },          /* 8  */
  { 0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c, 0, 0 },          /* 9  */
  { 0x00, 0x0c, 0x0c, 0x00, 0x0c, 0x0c, 0x00, 0, 0 },          /* :  */
  { 0x00, 0x0c, 0x0c, 0x00, 0x00, 0x00, 0x0c, 0x04, 0x08 },    /* ;  */
  { 0x02, 0x04, 0x08, 0x10, 0x08, 0x04, 0x02, 0, 0 },          /* <  */
  { 0x00, 0x00, 0x1f, 0x00, 0x1f, 0x00, 0x00, 0, 0 },          /* =  */
  { 0x08, 0x04, 0x02, 0x01, 0x02, 0x04, 0x08, 0, 0 },          /* >  */
  { 0x0e, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04, 0, 0 },          /* ?  */
  { 0x0e, 0x11, 0x01, 0x0d, 0x15, 0x15, 0x0e, 0, 0 },          /* @  */
  { 0x0e, 0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0, 0 },          /* A  */
  { 0x1e, 0x11, 0x11, 0x1e, 0x11, 0x11, 0x1e, 0, 0 },          /* B  */
  { 0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e, 0, 0 },          /* C  */
  { 0x1c, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1c, 0, 0 },          /* D  */
  { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f, 0, 0 },          /* E  */
  { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10, 0, 0 },          /* F  */
  { 0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f, 0, 0 },          /* G  */
  { 0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11, 0, 0 },          /* H  */
  { 0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e, 0, 0 },          /* I  */
  { 0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0c, 0, 0 },          /* J  */
  { 0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11, 0, 0 },          /* K  */
  { 0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f, 0, 0 },          /* L  */
  { 0x11, 0x1b, 0x15, 0x15, 0x11, 0x11, 0x11, 0, 0 },          /* M  */
  { 0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0, 0 },          /* N  */
  { 0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e, 0, 0 },          /* O  */
  { 0x1e, 0x11, 0x11, 0x1e, 0x10, 0x10, 0x10, 0, 0 },          /* P  */
  { 0x0e, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0d, 0, 0 },          /* Q  */
  { 0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11, 0, 0 },          /* R  */
  { 0x0f, 0x10, 0x10, 0x0e, 0x01, 0x01, 0x1e, 0, 0 },          /* S  */
  { 0x1f, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0, 0 },          /* T  */
  { 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e, 0, 0 },          /* U  */
  { 0x11, 0x11, 0x11, 0x11, 0x11, 0x0a, 0x04, 0, 0 },          /* V  */
  { 0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0a, 0, 0 },          /* W  */
  { 0x11, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0x11, 0, 0 },          /* X  */
  { 0x11, 0x11, 0x11, 0x0a, 0x04, 0x04, 0x04, 0, 0 },          /* Y  */
  { 0x1f, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1f, 0, 0 },          /* Z  */
  { 0x0e, 0x08, 0x08, 0x08, 0x08, 0x08, 0x0e, 0, 0 },          /* [  */
  { 0x10, 0x10, 0x08, 0x04, 0x02, 0x01, 0x01, 0, 0 },          /* \  */
  { 0x0e, 0x02, 0x02, 0x02, 0x02, 0x02, 0x0e, 0, 0 },          /* ]  */
  { 0x04, 0x0a, 0x11, 0x00, 0x00, 0x00, 0x00, 0, 0 },          /* ^  */
  { 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1f, 0 },       /* _  */
  { 0x08, 0x04, 0x02, 0x00, 0x00, 0x00, 0x00, 0, 0 },          /* `  */
  { 0x00, 0x00, 0x0e, 0x01, 0x0f, 0x11, 0x0f, 0, 0 },          /* a  */
  { 0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1e, 0, 0 },          /* b  */
  { 0x00, 0x00, 0x0e, 0x10, 0x10, 0x11, 0x0e, 0, 0 },          /* c  */
  { 0x01, 0x01, 0x0d, 0x13, 0x11, 0x11, 0x0f, 0, 0 },          /* d  */
  { 0x00, 0x00, 0x0e, 0x11, 0x1f, 0x10, 0x0e, 0, 0 },          /* e  */
  { 0x06, 0x09, 0x08, 0x1c, 0x08, 0x08, 0x08, 0, 0 },          /* f  */
  { 0x00, 0x00, 0x0f, 0x11, 0x11, 0x11, 0x0f, 0x01, 0x0e },    /* g  */
  { 0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11, 0, 0 },          /* h  */
  { 0x04, 0x00, 0x0c, 0x04, 0x04, 0x04, 0x0e, 0, 0 },          /* i  */
  { 0x02, 0x00, 0x06, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0c },    /* j  */
  { 0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12, 0, 0 },          /* k  */
  { 0x0c, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e, 0, 0 },          /* l  */
  { 0x00, 0x00, 0x1a, 0x15, 0x15, 0x11, 0x11, 0, 0 },          /* m  */
  { 0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11, 0, 0 },          /* n  */
  { 0x00, 0x00, 0x0e, 0x11, 0x11, 0x11, 0x0e, 0, 0 },          /* o  */
  { 0x00, 0x00, 0x1e, 0x11, 0x11, 0x11, 0x1e, 0x10, 0x10 },    /* p  */
  { 0x00, 0x00, 0x0f, 0x11, 0x11, 0x11, 0x0f, 0x01, 0x01 },    /* q  */
  { 0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10, 0, 0 },          /* r  */
  { 0x00, 0x00, 0x0f, 0x10, 0x0e, 0x01, 0x1e, 0, 0 },          /* s  */
  { 0x08, 0x08, 0x1c, 0x08, 0x08, 0x09, 0x06, 0, 0 },          /* t  */
  { 0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0d, 0, 0 },          /* u  */
  { 0x00, 0x00, 0x11, 0x11, 0x11, 0x0a, 0x04, 0, 0 },          /* v  */
  { 0x00, 0x00, 0x11, 0x11, 0x15, 0x15, 0x0a, 0, 0 },          /* w  */
  { 0x00, 0x00, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0, 0 },          /* x  */
  { 0x00, 0x00, 0x11, 0x11, 0x11, 0x11, 0x0f, 0x01, 0x0e },    /* y  */
  { 0x00, 0x00, 0x1f, 0x02, 0x04, 0x08, 0x1f, 0, 0 },          /* z  */
  { 0x02, 0x04, 0x04, 0x08, 0x04, 0x04, 0x02, 0, 0 },          /* {  */
  { 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0, 0 },          /* |  */
  { 0x08, 0x04, 0x04, 0x02, 0x04, 0x04, 0x08, 0, 0 },          /* }  */
  { 0x00, 0x00, 0x08, 0x15, 0x02, 0x00, 0x00, 0, 0 }           /* ~  */
};

int
lac_render_text_width (lac_render_font *font, const char *s, int scale)
{
  size_t n = strlen (s);
  if (font)
    return lac_render_font_width (font, s, scale);
  return n ? (int) n * LAC_FONT_ADVANCE * scale - scale : 0;
}

static void
put_pixel (unsigned char *rgba, int w, int h, int x, int y,
           const unsigned char rgb[3])
{
  unsigned char *p;
  if (x < 0 || y < 0 || x >= w || y >= h)
    return;
  p = rgba + 4 * ((size_t) y * (size_t) w + (size_t) x);
  p[0] = rgb[0];
  p[1] = rgb[1];
  p[2] = rgb[2];
  p[3] = 255;
}

static void
fill_rect (unsigned char *rgba, int w, int h, int x, int y, int rw, int rh,
           const unsigned char rgb[3])
{
  for (int j = 0; j < rh; j++)
    for (int i = 0; i < rw; i++)
      put_pixel (rgba, w, h, x + i, y + j, rgb);
}

void
lac_render_text (lac_render_font *font, unsigned char *rgba, int w, int h,
                 int x, int y, int scale, const char *s,
                 const unsigned char rgb[3])
{
  if (font)
    {
      lac_render_font_draw (font, rgba, w, h, x, y, scale, s, rgb);
      return;
    }
  for (; *s; s++, x += LAC_FONT_ADVANCE * scale)
    {
      int c = (unsigned char) *s;
      const unsigned char *g = bitmap[(c < 32 || c > 126 ? '?' : c) - 32];
      for (int r = 0; r < LAC_FONT_H; r++)
        for (int k = 0; k < LAC_FONT_W; k++)
          if (g[r] & (0x10 >> k))
            fill_rect (rgba, w, h, x + k * scale, y + r * scale, scale,
                       scale, rgb);
    }
}

/* ---- ticks ------------------------------------------------------------- */

size_t
lac_render_ticks (double vmin, double vmax, double *tick, size_t max,
                  double *step)
{
  double raw = (vmax - vmin) / 5, mag, s, t0;
  size_t n = 0;
  if (!(raw > 0) || !isfinite (raw))
    {
      *step = 1;
      if (max > 0)
        tick[n++] = vmin;
      return n;
    }
  mag = pow (10.0, floor (log10 (raw)));
  s = raw / mag;
  s = (s < 1.5 ? 1 : s < 3.5 ? 2 : s < 7.5 ? 5 : 10) * mag;
  *step = s;
  t0 = ceil (vmin / s - 1e-9) * s;
  for (double t = t0; t <= vmax + 1e-9 * s && n < max; t = t0 + (double) n * s)
    tick[n++] = fabs (t) < 1e-9 * s ? 0.0 : t;
  return n;
}

/* vabs: the largest |value| of the range, to choose the notation. */
void
lac_render_tick_label (double v, double step, double vabs, char *buf,
                       size_t len)
{
  int es = (int) floor (log10 (step) + 1e-9);
  int em = vabs > 0 ? (int) floor (log10 (vabs)) : 0;
  if (em >= 5 || em <= -4)
    {
      int d = em - es;
      snprintf (buf, len, "%.*e", d < 0 ? 0 : d > 6 ? 6 : d, v);
    }
  else
    snprintf (buf, len, "%.*f", es >= 0 ? 0 : -es > 8 ? 8 : -es, v);
}

/* ---- colour bar -------------------------------------------------------- */

static int
labels_width (lac_render_font *font, double vmin, double vmax, int scale)
{
  double tick[16], step, vabs = fmax (fabs (vmin), fabs (vmax));
  size_t n = lac_render_ticks (vmin, vmax, tick, 16, &step);
  char buf[48];
  int wmax = 0;
  for (size_t k = 0; k < n; k++)
    {
      int tw;
      lac_render_tick_label (tick[k], step, vabs, buf, sizeof buf);
      tw = lac_render_text_width (font, buf, scale);
      wmax = tw > wmax ? tw : wmax;
    }
  return wmax;
}

int
lac_render_colorbar_width (lac_render_font *font, double vmin, double vmax,
                           int scale)
{
  return 4 * scale + labels_width (font, vmin, vmax, scale);
}

/* The words over the colour bar for a field's key: the VTU / summary key
 * names of lac (von_mises, radial_stress, displacement_x, stress_yy,
 * lambda, ...) in words, any other key with its underscores as blanks. */
const char *
lac_render_field_words (const char *key, char *buf, size_t size)
{
  static const char *const words[][2] = {
    { "von_mises", "von Mises stress" }, { "vm", "von Mises stress" },
    { "radial_stress", "radial stress" },
    { "displacement_magnitude", "displacement |u|" },
    { "u", "displacement |u|" }, { "displacement", "displacement |u|" },
    { "displacement_error", "error |u - u_exact|" },
    { "u_R", "radial displacement u_R" }, { "u_r", "displacement u_r" },
    { "lambda", "contact pressure lambda" }, { "gap", "mean gap" },
    { "body", "body" }
  };
  if (!key)
    return NULL;
  for (size_t k = 0; k < sizeof words / sizeof *words; k++)
    if (!strcmp (key, words[k][0]))
      return words[k][1];
  if (!strncmp (key, "displacement_", 13) && strlen (key) == 14)
    snprintf (buf, size, "displacement u_%s", key + 13);
  else if (!strncmp (key, "stress_", 7))
    snprintf (buf, size, "stress sigma_%s", key + 7);
  else if (!strncmp (key, "s_", 2) && strlen (key) == 4)
    snprintf (buf, size, "stress sigma_%s", key + 2);
  else
    {
      snprintf (buf, size, "%s", key);
      for (char *c = buf; *c; c++)
        if (*c == '_')
          *c = ' ';
    }
  return buf;
}

void
lac_render_colorbar (lac_render_font *font, unsigned char *rgba, int w, int h,
                     int x, int y, int bw, int bh, double vmin, double vmax,
                     const char *label, const char *units, int scale)
{
  static const unsigned char ink[3] = { 0, 0, 0 };
  double tick[16], step, vabs = fmax (fabs (vmin), fabs (vmax));
  size_t n = lac_render_ticks (vmin, vmax, tick, 16, &step);
  char buf[128];
  unsigned char rgb[3];

  /* The bar: top = vmax, bottom = vmin, a one-pixel frame around it. */
  for (int j = 0; j < bh; j++)
    {
      lac_render_colormap (bh > 1 ? 1.0 - (double) j / (bh - 1) : 0.5, rgb);
      fill_rect (rgba, w, h, x, y + j, bw, 1, rgb);
    }
  fill_rect (rgba, w, h, x - 1, y - 1, bw + 2, 1, ink);
  fill_rect (rgba, w, h, x - 1, y + bh, bw + 2, 1, ink);
  fill_rect (rgba, w, h, x - 1, y - 1, 1, bh + 2, ink);
  fill_rect (rgba, w, h, x + bw, y - 1, 1, bh + 2, ink);

  /* Ticks and their labels, vertically centred on the tick. */
  for (size_t k = 0; k < n && vmax > vmin; k++)
    {
      int ty = y + (int) lround ((vmax - tick[k]) / (vmax - vmin) * (bh - 1));
      /* the tick inside the bar, so that it cannot read as a minus sign */
      fill_rect (rgba, w, h, x + bw - 3 * scale, ty - scale / 2, 3 * scale,
                 scale, ink);
      lac_render_tick_label (tick[k], step, vabs, buf, sizeof buf);
      lac_render_text (font, rgba, w, h, x + bw + 4 * scale, ty - 3 * scale,
                       scale, buf, ink);
    }

  /* "label (units)" above the bar, right-aligned with the labels; the
   * label in words (lac_render_field_words). */
  char wbuf[64];
  label = lac_render_field_words (label, wbuf, sizeof wbuf);
  if ((label && *label) || (units && *units))
    {
      int tw, right = x + bw + 4 * scale
                      + labels_width (font, vmin, vmax, scale);
      snprintf (buf, sizeof buf, "%s%s%s%s", label ? label : "",
                units && *units ? (label && *label ? " (" : "(") : "",
                units && *units ? units : "", units && *units ? ")" : "");
      tw = lac_render_text_width (font, buf, scale);
      lac_render_text (font, rgba, w, h, right - tw < 2 ? 2 : right - tw,
                       y - 6 * scale - LAC_FONT_LINE * scale, scale, buf,
                       ink);
    }
}
