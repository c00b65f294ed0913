/* t102-spaces-faces.c -- faces of the reference cells.
 *
 * For every 2D/3D element type and each of its faces, on the reference
 * cell itself:
 *   - the face has the face type's number of nodes, distinct and in range;
 *   - the cell nodes lying on the face's plane (line) are exactly the face
 *     nodes, and all other nodes lie strictly inside (it is a face);
 *   - face node k sits at the face's linear map of the face element's own
 *     reference node k (mid-nodes and centre in the face element's order);
 *   - the normal from lac_map_face is outward: n . (face centroid - cell
 *     centroid) > 0;
 *   - divergence theorem, by face quadrature: sum_f int_f n dS = 0 and
 *     sum_f int_f x.n dS = dim |K| (1e-13); the faces' measures add up to
 *     the surface of K (tri 2+sqrt2, quad 8, tet (3+sqrt3)/2, hex 24,
 *     pyramid 4+4 sqrt2).
 */
#include <math.h>

#include "check.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"

/* Linear counterpart of a face type (its vertices only). */
static const lac_refelem *
linear_face (const lac_refelem *fe)
{
  switch (fe->shape)
    {
    case LAC_SHAPE_LINE: return lac_refelem_get (LAC_SEG2);
    case LAC_SHAPE_TRI: return lac_refelem_get (LAC_TRI3);
    default: return lac_refelem_get (LAC_QUAD4);
    }
}

/* Coordinates of the face's nodes, taken from the reference cell. */
static void
face_coords (const lac_refelem *re, int f, const lac_refelem *fe, double *xf)
{
  int d = re->dim;
  for (int k = 0; k < fe->nnodes; k++)
    for (int i = 0; i < d; i++)
      xf[k * d + i] = re->xi[re->face_node[f][k] * d + i];
}

static void
face_centroid_ref (const lac_refelem *fe, double *c)
{
  c[0] = c[1] = (fe->shape == LAC_SHAPE_TRI) ? 1.0 / 3 : 0;
}

static void
check_face (const lac_refelem *re, int f, double cc[3])
{
  const lac_refelem *fe = lac_refelem_get (re->face_type[f]);
  const lac_refelem *fl = linear_face (fe);
  int d = re->dim;
  double xf[LAC_MAX_FACE_NODES * 3], xfl[4 * 3], c[2], N[4];
  lac_map m;

  /* Node indices: distinct, in range, on the face. */
  int ok = fe->dim == d - 1;
  for (int k = 0; k < fe->nnodes; k++)
    {
      int a = re->face_node[f][k];
      ok &= a >= 0 && a < re->nnodes;
      for (int j = 0; j < k; j++)
        ok &= re->face_node[f][j] != a;
    }
  check_true (ok, "%s face %d: node list", re->name, f);
  if (!ok)
    return;
  face_coords (re, f, fe, xf);
  face_coords (re, f, fl, xfl);

  /* Outward normal at the face centroid. */
  face_centroid_ref (fe, c);
  check_status (lac_map_face (fe, d, xf, c, &m), LAC_SUCCESS,
                "%s face %d: map", re->name, f);
  double s = 0;
  for (int i = 0; i < d; i++)
    s += m.normal[i] * (m.x[i] - cc[i]);
  check_true (s > 0.1, "%s face %d: normal outward (%g)", re->name, f, s);

  /* The nodes on the face's plane are exactly the face nodes. */
  for (int a = 0; a < re->nnodes; a++)
    {
      double h = 0;
      int on = 0;
      for (int i = 0; i < d; i++)
        h += (re->xi[a * d + i] - xf[i]) * m.normal[i];
      for (int k = 0; k < fe->nnodes; k++)
        on |= re->face_node[f][k] == a;
      if (on)
        check_abs (h, 0, 1e-14, "%s face %d: node %d on plane", re->name, f,
                   a);
      else
        check_true (h < -1e-3, "%s face %d: node %d inside (%g)", re->name,
                    f, a, h);
    }

  /* Face node k = linear face map at the face's reference node k. */
  for (int k = 0; k < fe->nnodes; k++)
    {
      lac_refelem_eval (fl, fe->xi + k * fe->dim, N, NULL);
      for (int i = 0; i < d; i++)
        {
          double x = 0;
          for (int v = 0; v < fl->nnodes; v++)
            x += N[v] * xfl[v * d + i];
          check_abs (xf[k * d + i], x, 1e-15, "%s face %d node %d: position",
                     re->name, f, k);
        }
    }
}

/* Divergence theorem on the reference cell. */
static void
check_divergence (const lac_refelem *re, double surface)
{
  int d = re->dim;
  double n[3] = { 0, 0, 0 }, flux = 0, area = 0;
  for (int f = 0; f < re->nfaces; f++)
    {
      const lac_refelem *fe = lac_refelem_get (re->face_type[f]);
      double xf[LAC_MAX_FACE_NODES * 3];
      lac_quad *q = lac_quad_alloc (fe->shape, 4);
      lac_map m;
      face_coords (re, f, fe, xf);
      for (int p = 0; p < q->n; p++)
        {
          lac_map_face (fe, d, xf, q->xi + p * fe->dim, &m);
          double dS = q->w[p] * m.detJ;
          area += dS;
          for (int i = 0; i < d; i++)
            {
              n[i] += m.normal[i] * dS;
              flux += m.x[i] * m.normal[i] * dS;
            }
        }
      lac_quad_free (q);
    }
  for (int i = 0; i < d; i++)
    check_abs (n[i], 0, 1e-13, "%s: sum int n_%d dS", re->name, i);
  check_rel (flux, d * lac_quad_ref_measure (re->shape), 1e-13,
             "%s: int x.n dS = d |K|", re->name);
  check_rel (area, surface, 1e-13, "%s: surface", re->name);
}

int
main (void)
{
  const double r2 = sqrt (2.0), r3 = sqrt (3.0);
  lac_init ();
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    {
      const lac_refelem *re = lac_refelem_get ((lac_elem_type) t);
      double cc[3] = { 0, 0, 0 }, surface = 0;
      if (re->dim == 1)
        {
          check_int (re->nfaces, 0, "%s: no faces", re->name);
          continue;
        }
      for (int a = 0; a < re->nvertices; a++)
        for (int i = 0; i < re->dim; i++)
          cc[i] += re->xi[a * re->dim + i] / re->nvertices;
      for (int f = 0; f < re->nfaces; f++)
        check_face (re, f, cc);
      switch (re->shape)
        {
        case LAC_SHAPE_TRI: surface = 2 + r2; break;
        case LAC_SHAPE_QUAD: surface = 8; break;
        case LAC_SHAPE_TET: surface = 1.5 + r3 / 2; break;
        case LAC_SHAPE_HEX: surface = 24; break;
        case LAC_SHAPE_PYR: surface = 4 + 4 * r2; break;
        default: break;
        }
      check_divergence (re, surface);
    }
  /* The numbering documented in lac_spaces.c. */
  const lac_refelem *hex = lac_refelem_get (LAC_HEX27);
  for (int f = 0; f < 6; f++)
    check_int (hex->face_node[f][8], 20 + f, "hex27 face %d centre", f);
  check_int (lac_refelem_get (LAC_TET4)->face_node[3][0], 1, "tet face 3");
  check_int (lac_refelem_get (LAC_PYR5)->face_type[0], LAC_QUAD4, "pyr base");
  lac_finalize ();
  return check_summary ();
}
