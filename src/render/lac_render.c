/* lac_render.c -- drawing with OSMesa, layout, PNG (see lac_render.h)
 *
 * Steps of one picture:
 *   1. geometry: triangles and lines in space (lac_render_geom.c);
 *   2. colour range: fixed, or the range of the values (a constant field
 *      gets +-5% around its value so that it shows the middle colour);
 *   3. camera: orthographic; in 3D the view basis (right, up, eye) from
 *      azimuth and elevation, z up;
 *   4. layout: the title on top, the colour bar on the right, the picture
 *      fitted (same scale in x and y) into what is left;
 *   5. OSMesa draws into an RGBA buffer `supersample` times larger (row 0
 *      at the bottom), which is averaged into the caller's image (row 0 at
 *      the top);
 *   6. the colour bar and the text are written into the pixels.
 *
 * Link with -lOSMesa only, never -lGL: glvnd's libGL would shadow OSMesa's
 * gl* entry points and leave the buffer black (deps.md, OSMesa gotchas).
 */
#include <unistd.h>
#include <errno.h>
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "render/lac_render_internal.h"
#include "base/lac_status.h"

static const double DEG = 3.14159265358979323846 / 180.0;
static const unsigned char INK[3] = { 0, 0, 0 };

/* The defaults of lac_render.h, the one place they are written; the
 * fields not named are 0 (NULL). */
static const lac_render_opts DEFAULTS = {
  .width = 800, .height = 600, .azimuth = 35, .elevation = 25,
  .colorbar = 1, .subdiv = 4, .supersample = 2
};

void
lac_render_opts_init (lac_render_opts *o)
{
  *o = DEFAULTS;
}

/* ---- camera and layout ------------------------------------------------- */

typedef struct view
{
  double r[3], up[3], e[3];   /* view basis: right, up, towards the eye    */
  double k, cx, cy, ox, oy;   /* pixel = o + k (v - c), GL pixels (y up)   */
  double zmid, zhalf;         /* depth normalisation                        */
  double vmin, vmax;          /* colour range                               */
  int dim, ss;
  int thick;                  /* width of thick lines, final pixels         */
} view;

static void
view_basis (view *V, int dim, double az, double el)
{
  double ca = cos (az * DEG), sa = sin (az * DEG), ce = cos (el * DEG),
    se = sin (el * DEG);
  if (dim == 2)
    {
      double r[3] = { 1, 0, 0 }, up[3] = { 0, 1, 0 }, e[3] = { 0, 0, 1 };
      memcpy (V->r, r, sizeof r);
      memcpy (V->up, up, sizeof up);
      memcpy (V->e, e, sizeof e);
      return;
    }
  /* eye direction e; right = z x e normalised (= (ca, sa, 0)); up = e x r */
  V->e[0] = sa * ce;
  V->e[1] = -ca * ce;
  V->e[2] = se;
  V->r[0] = ca;
  V->r[1] = sa;
  V->r[2] = 0;
  V->up[0] = V->e[1] * V->r[2] - V->e[2] * V->r[1];
  V->up[1] = V->e[2] * V->r[0] - V->e[0] * V->r[2];
  V->up[2] = V->e[0] * V->r[1] - V->e[1] * V->r[0];
}

static void
project (const view *V, const double *x, double *p)
{
  p[0] = V->r[0] * x[0] + V->r[1] * x[1] + V->r[2] * x[2];
  p[1] = V->up[0] * x[0] + V->up[1] * x[1] + V->up[2] * x[2];
  p[2] = V->e[0] * x[0] + V->e[1] * x[1] + V->e[2] * x[2];
}

/* Bounding box of the projected vertices; LAC_EINVAL if one is not finite. */
static int
bbox_points (const view *V, const double *x, size_t n, double *lo, double *hi)
{
  for (size_t i = 0; i < n; i++)
    {
      double p[3];
      project (V, x + 3 * i, p);
      for (int k = 0; k < 3; k++)
        {
          if (!isfinite (p[k]))
            LAC_ERROR (LAC_EINVAL, "vertex %zu to draw has a non-finite "
                       "coordinate (a NaN in the mesh or the displacement?)",
                       i);
          lo[k] = fmin (lo[k], p[k]);
          hi[k] = fmax (hi[k], p[k]);
        }
    }
  return LAC_SUCCESS;
}

static void
range_values (const double *v, size_t n, double *lo, double *hi)
{
  for (size_t i = 0; i < n; i++)
    if (!isnan (v[i]))
      {
        *lo = fmin (*lo, v[i]);
        *hi = fmax (*hi, v[i]);
      }
}

/* The colour range [vmin, vmax]; 0 if there is no value at all. */
static int
colour_range (const lac_render_geom *g, const lac_render_opts *o, double *vmin,
              double *vmax)
{
  double lo = INFINITY, hi = -INFINITY, v, d;
  range_values (g->body.v, 3 * g->body.n, &lo, &hi);
  range_values (g->overlay.v, 3 * g->overlay.n, &lo, &hi);
  range_values (g->thick.v, 2 * g->thick.n, &lo, &hi);
  if (!(lo <= hi))
    return 0;
  if (o->fixed_range && o->vmax > o->vmin)
    lo = o->vmin, hi = o->vmax;
  if (!(hi - lo > 1e-9 * fmax (fabs (lo), fabs (hi))))
    {
      v = 0.5 * (lo + hi);
      d = fabs (v) > 0 ? 0.05 * fabs (v) : 1.0;
      lo = v - d;
      hi = v + d;
    }
  *vmin = lo;
  *vmax = hi;
  return 1;
}

typedef struct layout
{
  int ts, margin;             /* text scale, margin (final pixels)          */
  int x0, x1, y0, y1;         /* picture area, top-down final pixels        */
  int bar, bx, by, bw, bh;    /* colour bar: drawn?, corner, size           */
} layout;

static void
make_layout (const lac_render_opts *o, lac_render_font *font, int has_field,
             double vmin, double vmax, layout *L)
{
  int W = o->width, H = o->height, ts, m, top, line;
  ts = ((W < H ? W : H) + 125) / 250;     /* 2 at 480 to 624 pixels */
  ts = ts < 1 ? 1 : ts;
  L->ts = ts;
  L->margin = m = 8 * ts;
  line = LAC_FONT_LINE * ts;
  top = o->title && *o->title ? m + line + m / 2 : m;
  L->x0 = m;
  L->x1 = W - m;
  L->y0 = top;
  L->y1 = H - m;
  L->bar = has_field && o->colorbar;
  if (!L->bar)
    return;
  L->bw = 5 * ts + W / 100;
  L->bx = W - m - lac_render_colorbar_width (font, vmin, vmax, ts) - L->bw;
  L->by = top + line + 6 * ts;
  L->bh = H - L->by - m - 4 * ts;
  if (L->bh > (H - top) * 3 / 4)
    {
      int extra = L->bh - (H - top) * 3 / 4;
      L->bh -= extra;
      L->by += extra / 2;
    }
  L->x1 = L->bx - 3 * m;
  L->y0 = top + line;
}

/* With o->fixed_box, the eight corners of the box join the bounding box
 * (2D: the four corners of its z = 0 face). */
static int
bbox_box (const view *V, const lac_render_opts *o, double *lo, double *hi)
{
  double c[24];
  int nc = V->dim == 3 ? 8 : 4;
  if (!o->fixed_box)
    return LAC_SUCCESS;
  for (int k = 0; k < nc; k++)
    for (int d = 0; d < 3; d++)
      c[3 * k + d] = d == 2 && V->dim != 3 ? 0.0
                     : (k >> d) & 1 ? o->box_hi[d] : o->box_lo[d];
  return bbox_points (V, c, (size_t) nc, lo, hi);
}

/* Fit the bounding box [lo, hi] into the picture area. */
static void
fit_view (view *V, const layout *L, const lac_render_opts *o,
          const double *lo, const double *hi)
{
  double aw = (double) (L->x1 - L->x0), ah = (double) (L->y1 - L->y0),
    bw = hi[0] - lo[0], bh = hi[1] - lo[1], k;
  aw = aw < 10 ? 10 : aw;
  ah = ah < 10 ? 10 : ah;
  k = bw > 0 && bh > 0 ? fmin (aw / bw, ah / bh) : bw > 0 ? aw / bw
      : bh > 0 ? ah / bh : 1.0;
  V->k = 0.96 * k * V->ss;
  V->cx = 0.5 * (lo[0] + hi[0]);
  V->cy = 0.5 * (lo[1] + hi[1]);
  V->ox = 0.5 * (L->x0 + L->x1) * V->ss;
  V->oy = (o->height - 0.5 * (L->y0 + L->y1)) * V->ss;   /* GL: y up */
  V->zmid = 0.5 * (lo[2] + hi[2]);
  V->zhalf = hi[2] > lo[2] ? 0.5 * (hi[2] - lo[2]) : 1.0;
}

/* ---- colours and GL arrays ---------------------------------------------- */

/* Colour of a vertex: the map (or grey) times a shade from its normal. */
static void
vertex_colour (const view *V, double v, const double *nrm, double grey,
               unsigned char *c)
{
  /* light from just above the eye (unit, view frame): the top, front and
   * side faces of a box seen from az 35, el 25 get n.L = 0.73, 0.56, 0.39 */
  static const double L[3] = { 0.0, 0.371, 0.9286 };
  double s = 1.0, n[3], len;
  if (isnan (v))
    c[0] = c[1] = c[2] = (unsigned char) lround (255 * grey);
  else
    lac_render_colormap ((v - V->vmin) / (V->vmax - V->vmin), c);
  c[3] = 255;
  if (V->dim == 3 && nrm)
    {
      project (V, nrm, n);
      len = sqrt (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (len > 0)
        {
          double ndl = (n[2] < 0 ? -1 : 1) * (n[0] * L[0] + n[1] * L[1]
                                              + n[2] * L[2]) / len;
          ndl = ndl > 0 ? ndl : 0;
          s = isnan (v) ? 0.35 + 0.65 * ndl : 0.6 + 0.4 * ndl;
        }
    }
  for (int i = 0; i < 3; i++)
    c[i] = (unsigned char) lround (c[i] * s);
}

static void
to_gl (const view *V, const double *x, float *p)
{
  double q[3];
  project (V, x, q);
  p[0] = (float) (V->ox + V->k * (q[0] - V->cx));
  p[1] = (float) (V->oy + V->k * (q[1] - V->cy));
  p[2] = (float) (0.9 * (q[2] - V->zmid) / V->zhalf);
}

/* Draw nv vertices (x: 3 each, values v, normals nrm or NULL) as
 * primitives `mode`; ink != NULL: that colour instead of the values. */
static int
draw_arrays (const view *V, GLenum mode, const double *x, const double *nrm,
             const double *v, size_t nv, double grey, const unsigned char *ink)
{
  float *p = lac_malloc ((nv + 1) * 3 * sizeof *p);
  unsigned char *c = lac_malloc ((nv + 1) * 4);
  if (!p || !c)
    {
      lac_free (p);
      lac_free (c);
      LAC_ERROR (LAC_ENOMEM, "cannot allocate %zu vertices to draw", nv);
    }
  for (size_t i = 0; i < nv; i++)
    {
      to_gl (V, x + 3 * i, p + 3 * i);
      if (ink && isnan (v[i]))
        {
          memcpy (c + 4 * i, ink, 3);
          c[4 * i + 3] = 255;
        }
      else
        vertex_colour (V, v[i], nrm ? nrm + 3 * i : NULL, grey, c + 4 * i);
    }
  glVertexPointer (3, GL_FLOAT, 0, p);
  glColorPointer (4, GL_UNSIGNED_BYTE, 0, c);
  glDrawArrays (mode, 0, (GLsizei) nv);
  glFinish ();
  lac_free (p);
  lac_free (c);
  return LAC_SUCCESS;
}

static int
draw_all (const lac_render_geom *g, const view *V)
{
  static const unsigned char edge_ink[3] = { 30, 30, 30 };
  int ss = V->ss, status;
  glEnableClientState (GL_VERTEX_ARRAY);
  glEnableClientState (GL_COLOR_ARRAY);
  if (g->dim == 3)
    glEnable (GL_DEPTH_TEST);
  glEnable (GL_POLYGON_OFFSET_FILL);     /* edges win over their faces */
  glPolygonOffset (1.0f, 1.0f);
  if ((status = draw_arrays (V, GL_TRIANGLES, g->body.x, g->body.nrm,
                             g->body.v, 3 * g->body.n, g->grey, NULL)))
    return status;
  glDisable (GL_POLYGON_OFFSET_FILL);
  glLineWidth ((float) ss);
  if ((status = draw_arrays (V, GL_LINES, g->edges.x, NULL, g->edges.v,
                             2 * g->edges.n, g->grey, edge_ink)))
    return status;
  glDisable (GL_DEPTH_TEST);
  if (g->thick.n)              /* a dark border under each thick line */
    {
      double *nanv = lac_malloc (2 * g->thick.n * sizeof *nanv);
      if (!nanv)
        LAC_ERROR (LAC_ENOMEM, "out of memory");
      for (size_t i = 0; i < 2 * g->thick.n; i++)
        nanv[i] = NAN;
      glLineWidth ((float) ((V->thick + 3) * ss));
      status = draw_arrays (V, GL_LINES, g->thick.x, NULL, nanv,
                            2 * g->thick.n, g->grey, edge_ink);
      lac_free (nanv);
      glLineWidth ((float) (V->thick * ss));
      if (!status)
        status = draw_arrays (V, GL_LINES, g->thick.x, NULL, g->thick.v,
                              2 * g->thick.n, g->grey, NULL);
      if (status)
        return status;
    }
  glClear (GL_DEPTH_BUFFER_BIT);         /* discs: seen through the body */
  if (g->dim == 3)
    glEnable (GL_DEPTH_TEST);
  status = draw_arrays (V, GL_TRIANGLES, g->overlay.x, g->overlay.nrm,
                        g->overlay.v, 3 * g->overlay.n, g->grey, NULL);
  glDisableClientState (GL_VERTEX_ARRAY);
  glDisableClientState (GL_COLOR_ARRAY);
  return status;
}

/* ---- OSMesa ------------------------------------------------------------ */

/* Average ss x ss blocks of buf (W*ss x H*ss, row 0 at the bottom) into
 * rgba (W x H, row 0 at the top). */
static void
downsample (const unsigned char *buf, int W, int H, int ss,
            unsigned char *rgba)
{
  size_t W2 = (size_t) W * (size_t) ss;
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++)
      {
        unsigned sum[4] = { 0, 0, 0, 0 };
        for (int j = 0; j < ss; j++)
          {
            size_t row = (size_t) (H - 1 - y) * (size_t) ss + (size_t) j;
            const unsigned char *p = buf + 4 * (row * W2 + (size_t) x
                                                * (size_t) ss);
            for (int i = 0; i < ss; i++)
              for (int k = 0; k < 4; k++)
                sum[k] += p[4 * i + k];
          }
        for (int k = 0; k < 4; k++)
          rgba[4 * ((size_t) y * (size_t) W + (size_t) x) + (size_t) k] =
            (unsigned char) ((sum[k] + (unsigned) (ss * ss) / 2)
                             / (unsigned) (ss * ss));
      }
}

static int
draw_gl (const lac_render_geom *g, const view *V, int W, int H,
         unsigned char *rgba)
{
  int ss = V->ss, status;
  size_t W2 = (size_t) W * (size_t) ss, H2 = (size_t) H * (size_t) ss;
  unsigned char *buf = lac_malloc (W2 * H2 * 4);
  OSMesaContext ctx;
  GLenum err;
  if (!buf)
    LAC_ERROR (LAC_ENOMEM, "cannot allocate a %zu x %zu image", W2, H2);
  ctx = OSMesaCreateContextExt (OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx)
    {
      lac_free (buf);
      LAC_ERROR (LAC_EDEP, "OSMesa could not create a context (is "
                 "libOSMesa installed, and the program linked without -lGL?)");
    }
  if (!OSMesaMakeCurrent (ctx, buf, GL_UNSIGNED_BYTE, (GLsizei) W2,
                          (GLsizei) H2))
    {
      OSMesaDestroyContext (ctx);
      lac_free (buf);
      LAC_ERROR (LAC_EDEP, "OSMesa could not draw into a %zu x %zu buffer",
                 W2, H2);
    }
  glViewport (0, 0, (GLsizei) W2, (GLsizei) H2);
  glMatrixMode (GL_PROJECTION);
  glLoadIdentity ();
  glOrtho (0, (double) W2, 0, (double) H2, -1, 1);
  glMatrixMode (GL_MODELVIEW);
  glLoadIdentity ();
  glClearColor (1, 1, 1, 1);
  glClearDepth (1);
  glClear (GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDepthFunc (GL_LEQUAL);
  status = draw_all (g, V);
  glFinish ();
  if (!status && (err = glGetError ()) != GL_NO_ERROR)
    status = LAC_ERRMSG (LAC_EDEP, "OpenGL error 0x%x while drawing",
                         (unsigned) err);
  if (!status)
    downsample (buf, W, H, ss, rgba);
  OSMesaDestroyContext (ctx);
  lac_free (buf);
  return status;
}

/* ---- one picture ------------------------------------------------------- */

static int
check_opts (const lac_render_opts *o)
{
  if (o->width < 32 || o->height < 32 || o->width > 8192 || o->height > 8192)
    LAC_ERROR (LAC_EINVAL, "image size %d x %d: expected 32 to 8192 pixels",
               o->width, o->height);
  if (o->supersample < 0 || o->supersample > 4)
    LAC_ERROR (LAC_EINVAL, "supersample %d: expected 1 to 4", o->supersample);
  if (o->subdiv < 0 || o->subdiv > 16)
    LAC_ERROR (LAC_EINVAL, "subdiv %d: expected 1 to 16", o->subdiv);
  if (!isfinite (o->scale) || !isfinite (o->azimuth)
      || !isfinite (o->elevation))
    LAC_ERROR (LAC_EINVAL, "scale, azimuth and elevation must be finite");
  return LAC_SUCCESS;
}

/* The title centred on top; one size smaller, then cut with "...", if it
 * is too wide. */
static void
draw_title (lac_render_font *font, unsigned char *rgba,
            const lac_render_opts *o, const layout *L)
{
  char buf[256];
  int ts = L->ts, avail = o->width - 2 * L->margin, tw;
  size_t n;
  snprintf (buf, sizeof buf, "%s", o->title);
  if (ts > 2 && lac_render_text_width (font, buf, ts) > avail)
    ts--;                                  /* one size smaller at most */
  n = strlen (buf);
  while (n > 3 && lac_render_text_width (font, buf, ts) > avail)
    memcpy (buf + --n - 3, "...", 4);
  tw = lac_render_text_width (font, buf, ts);
  lac_render_text (font, rgba, o->width, o->height, (o->width - tw) / 2,
                   L->margin + (L->ts - ts) * LAC_FONT_H / 2, ts, buf, INK);
}

static int
render_geom (const lac_render_geom *g, const lac_render_opts *o,
             unsigned char *rgba)
{
  view V;
  layout L;
  double lo[3] = { INFINITY, INFINITY, INFINITY },
    hi[3] = { -INFINITY, -INFINITY, -INFINITY };
  int has_field, status;
  lac_render_font *font = NULL;
  memset (&V, 0, sizeof V);
  V.dim = g->dim;
  V.ss = o->supersample;
  has_field = colour_range (g, o, &V.vmin, &V.vmax);
  view_basis (&V, g->dim, o->azimuth, o->elevation);
  if ((status = bbox_points (&V, g->body.x, 3 * g->body.n, lo, hi))
      || (status = bbox_points (&V, g->overlay.x, 3 * g->overlay.n, lo, hi))
      || (status = bbox_points (&V, g->edges.x, 2 * g->edges.n, lo, hi))
      || (status = bbox_points (&V, g->thick.x, 2 * g->thick.n, lo, hi))
      || (status = bbox_box (&V, o, lo, hi)))
    return status;
  if (!(lo[0] <= hi[0]))
    LAC_ERROR (LAC_EINVAL, "nothing to draw (no cell, face or point)");
  if ((status = lac_render_font_open (o->font, &font)))
    return status;
  make_layout (o, font, has_field, V.vmin, V.vmax, &L);
  V.thick = 2 + 2 * L.ts;
  fit_view (&V, &L, o, lo, hi);
  if (!(status = draw_gl (g, &V, o->width, o->height, rgba)))
    {
      if (o->title && *o->title)
        draw_title (font, rgba, o, &L);
      if (L.bar)
        lac_render_colorbar (font, rgba, o->width, o->height, L.bx, L.by,
                             L.bw, L.bh, V.vmin, V.vmax, o->label, o->units,
                             L.ts);
    }
  lac_render_font_free (font);
  return status;
}

/* Resolve the options (NULL: defaults; 0 supersample, subdiv: defaults)
 * into *def, check them and the mesh; an empty g with the grey level of
 * the triangles without a value. */
static int
prologue (const lac_mesh *m, int need_mesh, double grey,
          const lac_render_opts **o, lac_render_opts *def,
          unsigned char *rgba, lac_render_geom *g)
{
  memset (g, 0, sizeof *g);
  g->dim = m ? m->dim : 3;
  g->grey = grey;
  *def = *o ? **o : DEFAULTS;
  if (!def->supersample)
    def->supersample = DEFAULTS.supersample;
  if (!def->subdiv)
    def->subdiv = DEFAULTS.subdiv;
  *o = def;
  if (!rgba)
    LAC_ERROR (LAC_EINVAL, "no image buffer");
  if (need_mesh && (!m || m->ncells == 0))
    LAC_ERROR (LAC_EINVAL, "no mesh to draw (NULL or no cells)");
  if (m && m->dim != 2 && m->dim != 3)
    LAC_ERROR (LAC_EINVAL, "mesh of dimension %d", m->dim);
  return check_opts (*o);
}

/* Draw g into rgba if status is LAC_SUCCESS; free the lists of g. */
static int
epilogue (lac_render_geom *g, const lac_render_opts *o, int status,
          unsigned char *rgba)
{
  if (!status)
    status = render_geom (g, o, rgba);
  lac_render_geom_free (g);
  return status;
}

int
lac_render_mesh_rgba (const lac_mesh *m, const double *u, const double *field,
                      const lac_render_opts *o, unsigned char *rgba)
{
  lac_render_opts def;
  lac_render_geom g;
  int status = prologue (m, 1, 0.80, &o, &def, rgba, &g);
  if (status)
    return status;
  status = lac_render_geom_mesh (&g, m, u, o->scale, field, o->subdiv,
                                 o->edges);
  return epilogue (&g, o, status, rgba);
}

int
lac_render_facets_rgba (const lac_mesh *m, const double *u, size_t n,
                        const size_t *cell, const int *face,
                        const double *value, const lac_render_opts *o,
                        unsigned char *rgba)
{
  lac_render_opts def;
  lac_render_geom g;
  int status = prologue (m, 1, 0.88, &o, &def, rgba, &g);
  if (status)
    return status;
  if (n && (!cell || !face || !value))
    LAC_ERROR (LAC_EINVAL, "%zu facets but no cell, face or value array", n);
  if (m->dim == 2)                 /* the mesh in light grey under them */
    status = lac_render_geom_mesh (&g, m, u, o->scale, NULL, o->subdiv,
                                   o->edges);
  if (!status)
    status = lac_render_geom_facets (&g, m, u, o->scale, n, cell, face,
                                     value, o->subdiv, o->edges);
  return epilogue (&g, o, status, rgba);
}

int
lac_render_points_rgba (const lac_mesh *m, const double *u, size_t n,
                        const double *xyz, const double *radius,
                        const double *value, const lac_render_opts *o,
                        unsigned char *rgba)
{
  lac_render_opts def;
  lac_render_geom g;
  int status = prologue (m, 0, 0.90, &o, &def, rgba, &g);
  if (status)
    return status;
  if (n && (!xyz || !value))
    LAC_ERROR (LAC_EINVAL, "%zu points but no coordinates or values", n);
  if (m)                           /* the body in light grey behind them */
    status = lac_render_geom_mesh (&g, m, u, o->scale, NULL, o->subdiv,
                                   o->edges);
  if (!status)
    status = lac_render_geom_discs (&g, n, xyz, radius, value);
  return epilogue (&g, o, status, rgba);
}

/* ---- PNG --------------------------------------------------------------- */

/* The picture goes to a temporary file beside path, renamed to path when
 * it is whole: a failed write (libpng removes the file it was writing)
 * leaves an earlier picture of that name as it was. */
int
lac_render_write_png (const char *path, int width, int height,
                      const unsigned char *rgba)
{
  png_image img;
  char tmp[4200];
  const char *slash;
  if (!path || !rgba || width <= 0 || height <= 0)
    LAC_ERROR (LAC_EINVAL, "no path, no image or bad size %d x %d", width,
               height);
  slash = strrchr (path, '/');
  if ((size_t) snprintf (tmp, sizeof tmp, "%.*s.%s.lac-tmp-%ld",
                         slash ? (int) (slash + 1 - path) : 0, path,
                         slash ? slash + 1 : path, (long) getpid ())
      >= sizeof tmp)
    LAC_ERROR (LAC_EINVAL, "'%s': path too long", path);
  memset (&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  img.width = (png_uint_32) width;
  img.height = (png_uint_32) height;
  img.format = PNG_FORMAT_RGBA;
  if (!png_image_write_to_file (&img, tmp, 0, rgba, 0, NULL))
    {
      int status = LAC_ERRMSG (LAC_EIO, "cannot write '%s': %s", path,
                               img.message);
      png_image_free (&img);
      unlink (tmp);
      return status;
    }
  if (rename (tmp, path) != 0)
    {
      int status = LAC_ERRMSG (LAC_EIO, "cannot write '%s' (%s)", path,
                               strerror (errno));
      unlink (tmp);
      return status;
    }
  return LAC_SUCCESS;
}

static int
alloc_image (const lac_render_opts *o, unsigned char **rgba)
{
  int status;
  *rgba = NULL;
  if (!o)
    o = &DEFAULTS;
  if ((status = check_opts (o)))
    return status;
  *rgba = lac_malloc ((size_t) o->width * (size_t) o->height * 4);
  if (!*rgba)
    LAC_ERROR (LAC_ENOMEM, "cannot allocate a %d x %d image", o->width,
               o->height);
  return LAC_SUCCESS;
}

static int
finish_png (const lac_render_opts *o, int status, unsigned char *rgba,
            const char *path)
{
  if (!o)
    o = &DEFAULTS;
  if (!status)
    status = lac_render_write_png (path, o->width, o->height, rgba);
  lac_free (rgba);
  return status;
}

int
lac_render_mesh (const lac_mesh *m, const double *u, const double *field,
                 const lac_render_opts *o, const char *png_path)
{
  unsigned char *rgba;
  int status = alloc_image (o, &rgba);
  if (status)
    return status;
  return finish_png (o, lac_render_mesh_rgba (m, u, field, o, rgba), rgba,
                     png_path);
}

int
lac_render_facets (const lac_mesh *m, const double *u, size_t n,
                   const size_t *cell, const int *face, const double *value,
                   const lac_render_opts *o, const char *png_path)
{
  unsigned char *rgba;
  int status = alloc_image (o, &rgba);
  if (status)
    return status;
  return finish_png (o, lac_render_facets_rgba (m, u, n, cell, face, value, o,
                                                rgba), rgba, png_path);
}

int
lac_render_points (const lac_mesh *m, const double *u, size_t n,
                   const double *xyz, const double *radius,
                   const double *value, const lac_render_opts *o,
                   const char *png_path)
{
  unsigned char *rgba;
  int status = alloc_image (o, &rgba);
  if (status)
    return status;
  return finish_png (o, lac_render_points_rgba (m, u, n, xyz, radius, value,
                                                o, rgba), rgba, png_path);
}
