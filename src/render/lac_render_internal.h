/* lac_render_internal.h -- what the lac_render*.c files share (not public)
 *
 * A picture is built in two steps: geometry (lac_render_geom.c) turns the
 * mesh into lists of triangles and lines in space, each vertex carrying a
 * value (NaN: no value, drawn grey or dark); drawing (lac_render.c) projects
 * them, colours them and hands them to OSMesa, then lac_render_text.c writes
 * the colour bar and the text into the pixels.
 *
 * Ownership: the arrays of the lists are owned by the lac_render_geom and
 * freed by lac_render_geom_free.
 */
#ifndef LAC_RENDER_INTERNAL_H
#define LAC_RENDER_INTERNAL_H

#include <stddef.h>
#include "fem/lac_mesh.h"
#include "render/lac_render.h"

/* Triangles: vertex k of triangle t is x[9t+3k..], normal nrm[9t+3k..]
 * (not normalized; zero in 2D), value v[3t+k]. */
typedef struct lac_render_tris
{
  size_t n, cap;
  double *x, *nrm, *v;   /* owned */
} lac_render_tris;

/* Segments: end k of segment s is x[6s+3k..], value v[2s+k]. */
typedef struct lac_render_lines
{
  size_t n, cap;
  double *x, *v;         /* owned */
} lac_render_lines;

typedef struct lac_render_geom
{
  int dim;                  /* 2: the plane z = 0, no lighting; 3          */
  lac_render_tris body;     /* the surface, depth tested                   */
  lac_render_tris overlay;  /* discs: drawn after the body, seen through it */
  lac_render_lines edges;   /* thin dark lines (cell edges)                */
  lac_render_lines thick;   /* thick coloured lines (2D facets)            */
  double grey;              /* grey level of triangles without a value     */
} lac_render_geom;

/* ---- lac_render_geom.c ---- */
void lac_render_geom_free (lac_render_geom *g);   /* frees the lists only */

/* The faces of exactly one cell of a 3D mesh, as (cell, local face),
 * in cell order.  *cell and *face are allocated with lac_malloc. */
int lac_render_boundary_faces (const lac_mesh *m, size_t *nf, size_t **cell,
                               int **face);

/* Add the cells (2D) or boundary faces (3D) of m, deformed by scale*u
 * (u may be NULL), with nodal values field (NULL: no value). */
int lac_render_geom_mesh (lac_render_geom *g, const lac_mesh *m,
                          const double *u, double scale, const double *field,
                          int subdiv, int edges);

/* Add the facets (cell[k], face[k]) with the constant value[k]: triangles
 * in 3D, thick lines in 2D. */
int lac_render_geom_facets (lac_render_geom *g, const lac_mesh *m,
                            const double *u, double scale, size_t n,
                            const size_t *cell, const int *face,
                            const double *value, int subdiv, int edges);

/* Add n discs (overlay) at xyz with radius (NULL: automatic) and value. */
int lac_render_geom_discs (lac_render_geom *g, size_t n, const double *xyz,
                           const double *radius, const double *value);

/* ---- lac_render_font.c ---- */
#define LAC_RENDER_FONT_DEFAULT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

/* A TrueType font opened with FreeType for one picture (not shared). */
typedef struct lac_render_font lac_render_font;

/* Open path (NULL: LAC_RENDER_FONT_DEFAULT) into *font.  *font is NULL,
 * with success, for path "" and for a missing default file: the text is
 * then drawn with the bitmap font.  A given path that cannot be opened or
 * read: LAC_EIO naming it. */
int lac_render_font_open (const char *path, lac_render_font **font);
void lac_render_font_free (lac_render_font *f);          /* NULL allowed */
/* Width of the UTF-8 string s in pixels, and s drawn with its line's top
 * at y (baseline 7 * scale lower), at 10 * scale pixels per em. */
int lac_render_font_width (lac_render_font *f, const char *s, int scale);
void lac_render_font_draw (lac_render_font *f, unsigned char *rgba, int w,
                           int h, int x, int y, int scale, const char *s,
                           const unsigned char rgb[3]);

/* ---- lac_render_text.c ---- */
#define LAC_FONT_W 5        /* glyph cell: 5 x 9 (7 above the baseline)  */
#define LAC_FONT_H 9
#define LAC_FONT_ADVANCE 6
#define LAC_FONT_LINE 11

/* With font NULL the bitmap font, otherwise FreeType's glyphs. */
int lac_render_text_width (lac_render_font *font, const char *s, int scale);
/* Write s with its top-left corner at (x, y) (top-down pixel rows),
 * clipped to the image. */
void lac_render_text (lac_render_font *font, unsigned char *rgba, int w,
                      int h, int x, int y, int scale, const char *s,
                      const unsigned char rgb[3]);

/* Nice ticks (1, 2, 5 x 10^k) inside [vmin, vmax]; returns their number
 * (at most max) and the step. */
size_t lac_render_ticks (double vmin, double vmax, double *tick, size_t max,
                         double *step);
/* A tick label: fixed or exponent notation chosen from the step. */
void lac_render_tick_label (double v, double step, double vabs,
                            char *buf, size_t len);

/* The words over the colour bar for a field's key (von_mises: "von Mises
 * stress", radial_stress: "radial stress", stress_yy: "stress sigma_yy",
 * ...); BUF (SIZE bytes) may hold them.  NULL for NULL. */
const char *lac_render_field_words (const char *key, char *buf, size_t size);

/* Width in pixels the colour bar needs right of the bar (ticks, labels). */
int lac_render_colorbar_width (lac_render_font *font, double vmin,
                               double vmax, int scale);
/* Draw the bar with its top-left corner at (x, y), bar width bw and
 * height bh, ticks and labels to its right, label/units above it. */
void lac_render_colorbar (lac_render_font *font, unsigned char *rgba, int w,
                          int h, int x, int y, int bw, int bh, double vmin,
                          double vmax, const char *label, const char *units,
                          int scale);

#endif /* LAC_RENDER_INTERNAL_H */
