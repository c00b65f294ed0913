/* lac_mesh_jacobian.c -- det J in the cells of a mesh: the measure of
 *                        the domain, and the sign of det J in every cell
 *                        (inverted cells are mirrored by a node
 *                        permutation or rejected)    (see lac_mesh.h)
 *                                                          [LAC §3.1]
 */
#include "fem/lac_mesh.h"

#include <math.h>

#include "base/lac_mem.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

/* ---------------------------------------------------------------------- */
/* det J, measure                                                          */
/* ---------------------------------------------------------------------- */

/* det J of the map of a cell at xi (no sign check, unlike lac_map_cell). */
static double
cell_detJ (const lac_refelem *re, int dim, const double *xe, const double *xi)
{
  double dN[LAC_MAX_NODES * 3], J[9] = { 0 };

  lac_refelem_eval (re, xi, NULL, dN);
  for (int a = 0; a < re->nnodes; a++)
    for (int i = 0; i < dim; i++)
      for (int k = 0; k < dim; k++)
        J[i * dim + k] += xe[a * dim + i] * dN[a * dim + k];   /* dx_i/dxi_k */
  if (dim == 2)
    return J[0] * J[3] - J[1] * J[2];
  return J[0] * (J[4] * J[8] - J[5] * J[7])
         - J[1] * (J[3] * J[8] - J[5] * J[6])
         + J[2] * (J[3] * J[7] - J[4] * J[6]);
}

/* Total degree of det J for an order-k geometry: simplices (k-1)*dim; on
 * quadrangles and hexahedra det J has degree dim*k-1 in each variable, and
 * the tensor Gauss rule asked for that degree integrates it. */
static int
detJ_degree (const lac_refelem *re)
{
  switch (re->shape)
    {
    case LAC_SHAPE_TRI:
    case LAC_SHAPE_TET:
      return (re->order - 1) * re->dim;
    case LAC_SHAPE_QUAD:
    case LAC_SHAPE_HEX:
      return re->dim * re->order - 1;
    default:
      return 4;
    }
}

/* The rule for cells of type re (made once per type, kept in rule[]). */
static const lac_quad *
rule_for (lac_quad **rule, const lac_refelem *re, int min_degree)
{
  if (!rule[re->type])
    {
      int deg = detJ_degree (re);
      if (deg < min_degree)
        deg = min_degree;
      rule[re->type] = lac_quad_alloc (re->shape, deg);
    }
  return rule[re->type];
}

static void
rules_free (lac_quad **rule)
{
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    lac_quad_free (rule[t]);
}

/* The reference element of cell c, checked against the space dimension. */
static const lac_refelem *
cell_refelem (const lac_mesh *m, size_t c)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  if (!re)
    LAC_ERROR_NULL (LAC_EINVAL, "cell %zu (tag %zu) has no valid type", c,
                    m->cell_tag[c]);
  if (re->dim != m->dim)
    LAC_ERROR_NULL (LAC_EINVAL, "cell %zu (tag %zu) is a %s in a %dD mesh", c,
                    m->cell_tag[c], re->name, m->dim);
  return re;
}

/* lac_mesh_measure: sum over cells of int_T 1 dx = sum_q w_q det J(xi_q)
 * (plain areas in 2D).  Returns NAN with a message on failure. */
double
lac_mesh_measure (const lac_mesh *m)
{
  lac_quad *rule[LAC_NELEM_TYPES] = { 0 };
  double xe[LAC_MAX_NODES * 3], sum = 0;

  if (!m)
    {
      LAC_ERRMSG (LAC_EINVAL, "no mesh");
      return NAN;
    }
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = cell_refelem (m, c);
      const lac_quad *q = re ? rule_for (rule, re, 0) : NULL;
      if (!q)
        {
          sum = NAN;
          break;
        }
      lac_mesh_cell_coords (m, c, xe);
      for (int k = 0; k < q->n; k++)
        sum += q->w[k] * cell_detJ (re, m->dim, xe, q->xi + k * q->dim);
    }
  rules_free (rule);
  return sum;
}

/* ---------------------------------------------------------------------- */
/* orientation                                                             */
/* ---------------------------------------------------------------------- */

/* The node of re at the mirror image of node a, or -1: the mirror swaps
 * xi_0 and xi_1 (xi -> -xi on a line).  Swapping two reference
 * coordinates maps every reference domain here onto itself and reverses
 * det J. */
static int
mirror_node (const lac_refelem *re, int a)
{
  int d = re->dim;
  const double *xa = re->xi + a * d;
  double t[3];
  for (int k = 0; k < d; k++)
    t[k] = xa[k];
  if (d == 1)
    t[0] = -xa[0];
  else
    {
      t[0] = xa[1];
      t[1] = xa[0];
    }
  for (int b = 0; b < re->nnodes; b++)
    {
      double dist = 0;
      for (int k = 0; k < d; k++)
        dist += fabs (re->xi[b * d + k] - t[k]);
      if (dist < 1e-12)
        return b;
    }
  return -1;
}

/* The local face of re whose vertices are the images by perm of those of
 * face f, or -1. */
static int
mirror_face (const lac_refelem *re, const int *perm, int f)
{
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  for (int g = 0; g < re->nfaces; g++)
    {
      int found = 0;
      if (lac_refelem_get (re->face_type[g])->nvertices != nv)
        continue;
      for (int i = 0; i < nv; i++)
        for (int j = 0; j < nv; j++)
          found += perm[re->face_node[f][i]] == re->face_node[g][j];
      if (found == nv)
        return g;
    }
  return -1;
}

/* The mirror of a reference element: node a of the mirrored cell is node
 * perm[a] of the original, and fmap[f] is the local face of the mirrored
 * cell that holds the global nodes of face f of the original. */
static int
flip_maps (const lac_refelem *re, int *perm, int *fmap)
{
  for (int a = 0; a < re->nnodes; a++)
    if ((perm[a] = mirror_node (re, a)) < 0)
      LAC_ERROR (LAC_ESANITY, "%s: node %d has no mirror image", re->name,
                 a);
  for (int f = 0; f < re->nfaces; f++)
    if ((fmap[f] = mirror_face (re, perm, f)) < 0)
      LAC_ERROR (LAC_ESANITY, "%s: face %d has no mirror image", re->name,
                 f);
  return LAC_SUCCESS;
}

enum { CELL_OK, CELL_INVERTED, CELL_BAD };

/* Said of a tangled hexahedron: the usual cause is gmsh's all-hex mesh of a
 * curved body (tetrahedra subdivided into hexahedra, tests/bad/ball-hex.geo),
 * whose cells fold near the surface. */
static const char hex_hint[] =
  "; an all-hex mesh made by subdividing tetrahedra tangles cells near a "
  "curved surface: cut the body into blocks of six four-sided faces and "
  "make them transfinite (chapter 10, 'Hertz contact', hertz-sphere-hex.geo)";

/* Sign of det J at the nodes (but a pyramid's apex) and at the points of
 * q: all positive, all negative, or mixed/vanishing. */
static int
cell_sign (const lac_refelem *re, int dim, const double *xe,
           const lac_quad *q)
{
  double det[LAC_MAX_NODES + 512], scale = 0;
  int n = 0, pos = 0, neg = 0;

  for (int a = 0; a < re->nnodes; a++)
    if (re->shape != LAC_SHAPE_PYR || re->xi[a * dim + 2] < 1 - 1e-12)
      det[n++] = cell_detJ (re, dim, xe, re->xi + a * dim);
  for (int k = 0; k < q->n && n < LAC_MAX_NODES + 512; k++)
    det[n++] = cell_detJ (re, dim, xe, q->xi + k * q->dim);
  for (int i = 0; i < n; i++)
    scale = fmax (scale, fabs (det[i]));
  for (int i = 0; i < n; i++)
    {
      pos += det[i] > 1e-12 * scale;
      neg += det[i] < -1e-12 * scale;
    }
  if (scale > 0 && pos == n)
    return CELL_OK;
  if (scale > 0 && neg == n)
    return CELL_INVERTED;
  return CELL_BAD;
}

/* Mirror cell c: conn <- conn o perm. */
static void
flip_cell (lac_mesh *m, size_t c, const int *perm)
{
  int tmp[LAC_MAX_NODES];
  int *cn = m->conn + m->ptr[c];
  int nn = (int) (m->ptr[c + 1] - m->ptr[c]);
  for (int a = 0; a < nn; a++)
    tmp[a] = cn[a];
  for (int a = 0; a < nn; a++)
    cn[a] = tmp[perm[a]];
}

/* Facets of groups that sit on mirrored cells get their new local face. */
static void
remap_group_faces (lac_mesh *m, const unsigned char *flipped,
                   int fmap[][LAC_MAX_FACES])
{
  for (size_t g = 0; g < m->ngroups; g++)
    {
      lac_group *G = &m->group[g];
      if (G->dim != m->dim - 1)
        continue;
      for (size_t e = 0; e < G->n; e++)
        if (flipped[G->cell[e]])
          G->face[e] = fmap[m->type[G->cell[e]]][G->face[e]];
    }
}

/* lac_mesh_check_orientation: check the sign of det J at the nodes and
 * quadrature points of every cell.  A cell with det J < 0 everywhere is
 * mirrored (flip != 0; its facets in groups follow) or rejected with
 * LAC_EINVAL; a cell where det J changes sign or vanishes is rejected with
 * LAC_ESING.  Messages name the cell index and its tag. */
int
lac_mesh_check_orientation (lac_mesh *m, int flip, size_t *nflipped)
{
  lac_quad *rule[LAC_NELEM_TYPES] = { 0 };
  int perm[LAC_NELEM_TYPES][LAC_MAX_NODES];
  int fmap[LAC_NELEM_TYPES][LAC_MAX_FACES];
  unsigned char have[LAC_NELEM_TYPES] = { 0 }, *flipped = NULL;
  double xe[LAC_MAX_NODES * 3];
  size_t count = 0;
  int status = LAC_SUCCESS;

  if (nflipped)
    *nflipped = 0;
  if (!m)
    LAC_ERROR (LAC_EINVAL, "no mesh");
  flipped = lac_calloc (m->ncells, 1);
  if (!flipped)
    LAC_ERROR (LAC_ENOMEM, "flags for %zu cells", m->ncells);
  for (size_t c = 0; c < m->ncells && !status; c++)
    {
      const lac_refelem *re = cell_refelem (m, c);
      const lac_quad *q = re ? rule_for (rule, re, 2) : NULL;
      int sign;
      if (!q)
        {
          status = re ? LAC_ENOMEM : LAC_EINVAL;
          break;
        }
      lac_mesh_cell_coords (m, c, xe);
      sign = cell_sign (re, m->dim, xe, q);
      if (sign == CELL_BAD)
        status = LAC_ERRMSG (LAC_ESING, "cell %zu (tag %zu, %s) is degenerate "
                             "or tangled: det J vanishes or changes sign%s",
                             c, m->cell_tag[c], re->name,
                             re->shape == LAC_SHAPE_HEX ? hex_hint : "");
      else if (sign == CELL_INVERTED && !flip)
        status = LAC_ERRMSG (LAC_EINVAL, "cell %zu (tag %zu, %s) is inverted "
                             "(det J < 0): its nodes turn clockwise; reverse "
                             "the curve loop or surface, or flip inverted "
                             "cells", c, m->cell_tag[c], re->name);
      else if (sign == CELL_INVERTED)
        {
          if (!have[re->type])
            {
              status = flip_maps (re, perm[re->type], fmap[re->type]);
              have[re->type] = 1;
            }
          if (!status)
            {
              flip_cell (m, c, perm[re->type]);
              flipped[c] = 1;
              count++;
            }
        }
    }
  if (!status && count > 0)
    remap_group_faces (m, flipped, fmap);
  if (nflipped)
    *nflipped = count;
  lac_free (flipped);
  rules_free (rule);
  return status;
}
