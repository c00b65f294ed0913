/* lac_render_font.c -- the text of a picture drawn with FreeType
 *
 * A TrueType font (by default Debian's DejaVu Sans, package
 * fonts-dejavu-core) is opened for one picture, then each glyph is rendered
 * anti-aliased (8-bit coverage) and blended into the RGBA pixels in the ink
 * colour.  The size follows the bitmap font of lac_render_text.c, so that
 * the layout is the same with either: 10 pixels per em per text scale
 * (DejaVu's capitals are then about 7 pixels high, as the bitmap's), the
 * baseline 7 rows below the top of the line.  Text is UTF-8; a character
 * the font lacks shows as its missing-glyph box.
 */
#include <ft2build.h>
#include FT_FREETYPE_H
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "render/lac_render_internal.h"

struct lac_render_font
{
  FT_Library lib;
  FT_Face face;
  int px;                   /* the pixel size set last (0: none yet) */
};

int
lac_render_font_open (const char *path, lac_render_font **font)
{
  const char *file = path ? path : LAC_RENDER_FONT_DEFAULT;
  lac_render_font *f;
  FILE *fp;
  *font = NULL;
  if (path && !*path)
    return LAC_SUCCESS;                 /* "": the bitmap font */
  if (!(fp = fopen (file, "rb")))
    {
      if (!path)
        return LAC_SUCCESS;             /* no default font: the bitmap one */
      LAC_ERROR (LAC_EIO, "font file %s: cannot open it", file);
    }
  fclose (fp);
  if (!(f = lac_calloc (1, sizeof *f)))
    LAC_ERROR (LAC_ENOMEM, "out of memory for the font %s", file);
  if (FT_Init_FreeType (&f->lib))
    {
      lac_free (f);
      LAC_ERROR (LAC_EDEP, "FreeType could not start");
    }
  if (FT_New_Face (f->lib, file, 0, &f->face))
    {
      FT_Done_FreeType (f->lib);
      lac_free (f);
      LAC_ERROR (LAC_EIO, "font file %s: not a font FreeType can read", file);
    }
  *font = f;
  return LAC_SUCCESS;
}

void
lac_render_font_free (lac_render_font *f)
{
  if (!f)
    return;
  FT_Done_Face (f->face);
  FT_Done_FreeType (f->lib);
  lac_free (f);
}

/* The next character of the UTF-8 string *s (a bad byte reads as '?'). */
static unsigned long
next_char (const char **s)
{
  const unsigned char *p = (const unsigned char *) *s;
  unsigned long c = p[0];
  int n = c < 0x80 ? 0 : (c & 0xe0) == 0xc0 ? 1 : (c & 0xf0) == 0xe0 ? 2
          : (c & 0xf8) == 0xf0 ? 3 : -1;
  if (n < 0)
    {
      *s += 1;
      return '?';
    }
  c &= n ? 0x3fu >> n : 0x7f;
  for (int k = 1; k <= n; k++)
    {
      if ((p[k] & 0xc0) != 0x80)
        {
          *s += k;
          return '?';
        }
      c = (c << 6) | (p[k] & 0x3f);
    }
  *s += n + 1;
  return c;
}

/* Load (and with render, draw into the glyph slot) character c at scale. */
static int
load (lac_render_font *f, unsigned long c, int scale, int render)
{
  int px = 10 * scale;
  if (px != f->px)
    {
      if (FT_Set_Pixel_Sizes (f->face, 0, (FT_UInt) px))
        return -1;
      f->px = px;
    }
  return FT_Load_Char (f->face, c, FT_LOAD_TARGET_LIGHT
                       | (render ? FT_LOAD_RENDER : 0)) ? -1 : 0;
}

int
lac_render_font_width (lac_render_font *f, const char *s, int scale)
{
  long w = 0;
  while (*s)
    if (!load (f, next_char (&s), scale, 0))
      w += f->face->glyph->advance.x;
  return (int) ((w + 32) >> 6);
}

/* Blend the glyph slot's coverage at (x0, y0) (its top-left pixel). */
static void
blend (const FT_Bitmap *b, unsigned char *rgba, int w, int h, int x0, int y0,
       const unsigned char rgb[3])
{
  for (unsigned j = 0; j < b->rows; j++)
    for (unsigned i = 0; i < b->width; i++)
      {
        int x = x0 + (int) i, y = y0 + (int) j;
        unsigned a = b->buffer[(long) j * b->pitch + i];
        unsigned char *p;
        if (x < 0 || y < 0 || x >= w || y >= h || a == 0)
          continue;
        p = rgba + 4 * ((size_t) y * (size_t) w + (size_t) x);
        for (int k = 0; k < 3; k++)
          p[k] = (unsigned char) ((p[k] * (255 - a) + rgb[k] * a + 127) / 255);
        p[3] = 255;
      }
}

void
lac_render_font_draw (lac_render_font *f, unsigned char *rgba, int w, int h,
                      int x, int y, int scale, const char *s,
                      const unsigned char rgb[3])
{
  long pen = (long) x << 6;
  int base = y + 7 * scale;
  while (*s)
    {
      FT_GlyphSlot g;
      if (load (f, next_char (&s), scale, 1))
        continue;
      g = f->face->glyph;
      if (g->bitmap.pixel_mode == FT_PIXEL_MODE_GRAY)
        blend (&g->bitmap, rgba, w, h, (int) ((pen + 32) >> 6) + g->bitmap_left,
               base - g->bitmap_top, rgb);
      pen += g->advance.x;
    }
}
