/* lac_render.h -- offscreen pictures of meshes and fields (OSMesa, PNG)
 *
 * Draws a 2D mesh, or the boundary surface of a 3D mesh, optionally
 * deformed (x + scale u), coloured by a nodal scalar field through the
 * viridis colour map, with the cell edges, a colour bar with numeric ticks,
 * a title line and units; and two views of the contact data: the slave
 * facets coloured by one value per facet (lambda per macro-element,
 * piecewise constant), and discs at given points (macro-element centroids)
 * coloured by one value each over the grey body.
 *
 * How: the cells (2D) or the boundary faces (3D: faces of exactly one cell,
 * found by hashing their sorted vertices) are cut into triangles in the
 * reference element -- quadratic ones finely, through lac_refelem_eval, so
 * that curved faces look curved -- and drawn by OSMesa (software OpenGL,
 * no display needed) with Gouraud-interpolated vertex colours.  The camera
 * is orthographic: the plane itself in 2D; in 3D an oblique view from
 * azimuth/elevation (z up; azimuth 0 looks along +y, positive azimuth turns
 * the camera towards +x), with a light near the eye so that faces read as
 * a solid.  The frame is rendered at `supersample` times the size and
 * averaged down (anti-aliasing); text and the colour bar are then written
 * into the pixels with FreeType and a TrueType font (DejaVu Sans), or
 * with an embedded 5x7 bitmap font.
 *
 * Images are RGBA, 8 bits per channel, top row first (as in a PNG file).
 *
 * Results can be read back from the VTU files lac writes (lac_output.h)
 * with lac_render_result_read, so that `lac render` works on a result
 * directory without the scene.
 *
 * Ownership: everything passed in is borrowed; a lac_render_result is owned
 * by the caller and freed with lac_render_result_free.
 *
 * References: viridis: S. van der Walt and N. Smith, matplotlib colour map
 * "viridis" (2015), here sampled at 17 equally spaced points and
 * interpolated linearly; OSMesa: Mesa 3D's off-screen interface; libpng's
 * simplified API (png.h, "SIMPLIFIED API").
 */
#ifndef LAC_RENDER_H
#define LAC_RENDER_H

#include <stddef.h>
#include "fem/lac_mesh.h"

typedef struct lac_render_opts
{
  int width, height;         /* image size in pixels (800 x 600)            */
  double scale;              /* displacement magnification; 0: undeformed  */
  int edges;                 /* 1: draw the cell edges (not the subdivision) */
  double azimuth, elevation; /* 3D view direction in degrees (35, 25)       */
  const char *title;         /* borrowed: top line, or NULL                 */
  const char *label;         /* borrowed: name over the colour bar, or NULL */
  const char *units;         /* borrowed: "(units)" after the label, or NULL */
  int fixed_range;           /* 1: colours span [vmin, vmax]; 0: the data's */
  double vmin, vmax;
  int fixed_box;             /* 1: the camera frames the box [box_lo, box_hi]
                                (model coordinates, 2D: z ignored) with the
                                drawing: one box for several pictures gives
                                them one scale and position             */
  double box_lo[3], box_hi[3];
  int colorbar;              /* 1: draw the colour bar when there is a field */
  int subdiv;                /* sub-segments per edge of a quadratic face (4) */
  int supersample;           /* anti-aliasing factor 1..4 (2)               */
  const char *font;          /* borrowed: TrueType file of the text; NULL:
                                DejaVu Sans (fonts-dejavu-core), or the 5x7
                                bitmap font if it is not installed; "": the
                                bitmap font; a file that cannot be read:
                                LAC_EIO                                     */
} lac_render_opts;

/* Defaults in parentheses above; scale 0, edges 0, colorbar 1. */
void lac_render_opts_init (lac_render_opts *o);

/* compute: draw into rgba (width*height*4 bytes, top row first) */

/* The mesh (2D cells, or the boundary faces of 3D cells), deformed by
 * scale*u when u != NULL (nnodes*dim, dof = dim*node + i), coloured by the
 * nodal field (nnodes values) or plain grey when field == NULL.
 * Returns LAC_EINVAL (bad sizes, empty mesh, non-finite coordinates),
 * LAC_ENOMEM, LAC_EDEP (OSMesa failed). */
int lac_render_mesh_rgba (const lac_mesh *m, const double *u,
                          const double *field, const lac_render_opts *o,
                          unsigned char *rgba);

/* The n facets (cell[k], face[k]) -- a facet group, or the sub-facets of
 * the macro-elements -- each coloured by value[k] (piecewise constant).
 * In 3D only the facets are drawn (lit surfaces); in 2D the facets are
 * thick coloured lines over the mesh drawn in light grey. */
int lac_render_facets_rgba (const lac_mesh *m, const double *u, size_t n,
                            const size_t *cell, const int *face,
                            const double *value, const lac_render_opts *o,
                            unsigned char *rgba);

/* The body in light grey (m may be NULL: the discs alone) and, seen
 * through it, n discs centred at xyz[3k..3k+2] (displaced like the body:
 * pass the displaced centroids), of radius radius[k] (NULL: 0.45 x the
 * distance to the nearest other point; given radii are cut to half that
 * distance, so that discs do not overlap), coloured by value[k] (NaN:
 * grey).  In 3D each disc lies in the plane fitted to its neighbours (the
 * contact surface); in 2D discs are circles. */
int lac_render_points_rgba (const lac_mesh *m, const double *u, size_t n,
                            const double *xyz, const double *radius,
                            const double *value, const lac_render_opts *o,
                            unsigned char *rgba);

/* The same, written to a PNG file (an existing file is replaced). */
int lac_render_mesh (const lac_mesh *m, const double *u, const double *field,
                     const lac_render_opts *o, const char *png_path);
int lac_render_facets (const lac_mesh *m, const double *u, size_t n,
                       const size_t *cell, const int *face,
                       const double *value, const lac_render_opts *o,
                       const char *png_path);
int lac_render_points (const lac_mesh *m, const double *u, size_t n,
                       const double *xyz, const double *radius,
                       const double *value, const lac_render_opts *o,
                       const char *png_path);

/* Write an RGBA image (top row first) as an 8-bit RGBA PNG. */
int lac_render_write_png (const char *path, int width, int height,
                          const unsigned char *rgba);

/* query */
/* The viridis colour of t in [0, 1] (clamped; NaN gives grey). */
void lac_render_colormap (double t, unsigned char rgb[3]);

/* ---- results read back from a VTU file ------------------------------- */

typedef struct lac_render_result
{
  lac_mesh *mesh;      /* owned: dim 2 when every cell is 2D (z dropped)  */
  int axisymmetric;    /* the stresses are named rr, zz, tt, rz           */
  size_t narrays;      /* point-data arrays                               */
  char **name;         /* owned, narrays                                  */
  int *ncomp;          /* owned, narrays                                  */
  double **value;      /* owned, narrays: nnodes*ncomp[k] values          */
} lac_render_result;

/* Read a VTU file as lac_output_vtu writes it (ASCII UnstructuredGrid,
 * one piece; VTK cell types mapped back to lac types through vtk_perm; the
 * cell data "body" into mesh->body).  Errors name the file and the line. */
int lac_render_result_read (const char *path, lac_render_result **out);
void lac_render_result_free (lac_render_result *r);   /* NULL allowed */

/* The point-data array `name` (and its number of components), or NULL. */
const double *lac_render_result_array (const lac_render_result *r,
                                       const char *name, int *ncomp);

/* The displacement as nnodes*dim values (dof = dim*node + i); returns
 * LAC_EINVAL if the file has no "displacement" array. */
int lac_render_result_displacement (const lac_render_result *r, double *u);

/* A nodal scalar field by name (nnodes values into out):
 *   any one-component array (von_mises, stress_xx, ...);
 *   NAME_x, NAME_y, NAME_z and NAME_magnitude of a vector array
 *     (displacement_x, displacement_magnitude, ...);
 *   displacement_error: |u - u_exact| (when the exact one was written);
 *   x, y, z (r, z in the axisymmetric model): the coordinates;
 *   radial_stress: n.sigma.n with n = x/|x| in the plane of a 2D model
 *     (cylindrical radius; spherical radius R in the (r, z) plane of an
 *     axisymmetric one) or in space in 3D.
 * Aliases: vm; u, |u|; u_x (ux); s_xx (sxx, sigma_xx) and the
 * nodes.csv column names.  An unknown name gives LAC_EINVAL and a message
 * listing the available fields. */
int lac_render_result_scalar (const lac_render_result *r, const char *name,
                              double *out);

/* The available scalar field names, separated by ", " (truncated to len). */
void lac_render_result_list (const lac_render_result *r, char *buf,
                             size_t len);

#endif /* LAC_RENDER_H */
