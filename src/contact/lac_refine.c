/* lac_refine.c -- local conforming refinement of the first cell layer
 *                                             [LAC §4.4, Fig. 2, Remark 3]
 *
 * In 3D the trace of a tet4, tet10, hex8 or hex20 mesh has no node inside a
 * face, so a face cannot be a macro-element [LAC Hyp. 1].  The cell that
 * owns a slave face is cut so that the face gets interior nodes, while every
 * other face of the cell stays whole: the untouched neighbours see exactly
 * the faces they saw before, and the mesh stays conforming.  The refinement
 * is not unique [LAC Remark 3]; lac uses two templates.
 *
 * 1. Cones from the face centre (linear cells, tet10).  A new node c is put
 *    at the centre of the slave face f (in reference coordinates: the mean
 *    of the face's vertices) and the cell is replaced by the cones with apex
 *    c over each of its other faces: a triangle gives a tetrahedron, a
 *    quadrangle a pyramid, an edge (2D) a triangle.
 *
 *        tet4, face (v0,v1,v2)          hex8, face (v0,v1,v2,v3)
 *                 v2                      v3 ___________ v2
 *                 /\                        |\         /|
 *                /  \                       | \       / |
 *               / c  \     3 tet4:          |  \     /  |    5 pyr5 with
 *              / /  \ \    (e, c) for       |    c      |    apex c: one
 *             //      \\   each other       |  /     \  |    over each
 *            /__________\  face e           | /       \ |    other face
 *          v0            v1                 |/_________\|
 *                                         v0             v1
 *
 *    tet4:  +1 node, 1 -> 3 tet4   (face -> 3 tri3)
 *    tet10: +5 nodes (c, the 3 midpoints c-v_i on the face, the midpoint
 *           of c and the opposite vertex), 1 -> 3 tet10   (face -> 3 tri6)
 *    hex8:  +1 node, 1 -> 5 pyr5   (face -> 4 tri3), code_aster's default
 *    pyr5:  base +1 node, 1 -> 4 tet4; triangular side +1 node,
 *           1 -> 1 pyr5 + 3 tet4  (needed when a hex8 owns several slave
 *           faces: the second face is the base of one of the pyramids)
 *    tri3:  +1 node, 1 -> 2 tri3;  quad4: +1 node, 1 -> 3 tri3  (2D, only
 *           for isolated segments or on request, see lac_macromesh.c)
 *
 * 2. Six hexahedra (hex20; hex8 on request).  There is no pyramid13 in lac,
 *    so a hex20 cannot be coned.  In face-frame coordinates (s,t,u) with
 *    the slave face at u = +1:
 *
 *        slave face u = +1                 section t = 0
 *        T3 _______________ T2             T _________________ T   u = +1
 *          |\             /|                 |\   I_______I   /|
 *          | \           / |                 | \  |       |  / |
 *          |  I3_______I2  |                 |  \ |       | /  |
 *          |  |         |  |                 |   M|_______|M   |   u = 0
 *          |  |         |  |                 |  /           \  |
 *          |  I0_______I1  |                 | /             \ |
 *          | /           \ |                 |/_______________\|
 *          |/_____________\|                 B                 B   u = -1
 *        T0                 T1
 *
 *    T_i, B_i: the parent's vertices (top, bottom); I_i = (+-1/2, +-1/2, 1)
 *    on the slave face; M_i = (+-1/2, +-1/2, 0) at mid-depth.  Cells: the
 *    central hex [-1/2,1/2]^2 x [0,1] (M, I), the bottom hex (B, M) and four
 *    trapezoidal hexes (B_i B_i+1 M_i+1 M_i | T_i T_i+1 I_i+1 I_i).  The
 *    parent's bottom and side faces are faces of one sub-hex each (whole),
 *    the slave face becomes a central square and four trapezoids.
 *    (code_aster puts I_i at +-1/3; with M_i at +-1/2 that tangles a
 *    trapezoidal hex8 when it is cut again in a second round, and +-1/2
 *    for both doubles the worst det J ratio of the sub-cells.)
 *    hex8:  +8 nodes, 1 -> 6 hex8   (face -> 5 quad4, 4 interior nodes)
 *    hex20: +28 nodes (8 vertices and the mid-nodes of the 20 new edges:
 *           4 I-I, 4 T-I, 4 M-M, 4 I-M, 4 B-M), 1 -> 6 hex20
 *           (face -> 5 quad8, 12 interior nodes).
 *    Euler check: 16 vertices - 32 edges + 23 faces - 6 cells = 1.
 *
 * Every template is written once in reference coordinates: a sub-cell is
 * given by its vertices in the parent's reference coordinates, its other
 * nodes follow from the sub-cell's own (linear) reference map, a node that
 * falls on a parent node is that node, the others are new and are placed by
 * the parent's isoparametric map x(xi) = sum_a x_a N_a(xi).  The pieces of
 * each parent face are found by testing which sub-cell faces lie in the
 * parent face's plane (reference faces are planar), so no table of pieces
 * is written by hand.
 *
 * Geometry.  The sub-cells share their inner faces exactly and keep the
 * parent's other faces, so their union has the parent's volume as soon as
 * the pieces tile the slave face: always for simplices (the sub-maps are
 * affine in the parent's reference coordinates, so even a curved tet10 is
 * cut exactly) and for hex8 (a bilinear face, even twisted, encloses the
 * same volume as the 4 triangles of the fan or the 5 bilinear pieces), and
 * for hex20 when the face is planar.  A curved quad8 face is interpolated
 * by its pieces (new nodes on the parent's surface): O(h^3) off.  Inside,
 * sub-cell maps of the six-hex cut interpolate the parent's map.
 *
 * References: code_aster, CREA_MAILLAGE / DECOUPE_LAC (as summarized in
 * chapter 03).
 */
#include "contact/lac_refine.h"

#include <math.h>
#include <string.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* Messages from the static helpers carry the public function's name. */
#define RF_ERRMSG(status, ...) \
  lac_error_set ((status), "lac_refine_cut", __VA_ARGS__)
#define RF_ERROR(status, ...) return RF_ERRMSG ((status), __VA_ARGS__)

#define MAXSUB 6          /* sub-cells of one template (six-hex cut)      */
#define MAXNEW 32         /* new nodes of one template (hex20 cut: 28)    */
#define MAXPIECE 8        /* pieces of one parent face (six-hex cut: 5)   */
#define TOL 1e-10         /* reference-coordinate tolerance               */

/* One template: parent type and cut face -> sub-cells. */
typedef struct tmpl
{
  int state;                            /* 0 not built, 1 built          */
  int nsub;
  lac_elem_type type[MAXSUB];
  int node[MAXSUB][LAC_MAX_NODES];      /* >= 0 parent node, < 0 new -1-k */
  double vx[MAXSUB][8][3];              /* sub-cell vertices, parent xi   */
  int nnew;
  double xi[MAXNEW][3];                 /* new node k, parent xi          */
  int npiece[LAC_MAX_FACES];            /* pieces of parent face g:       */
  int psub[LAC_MAX_FACES][MAXPIECE];    /*   sub-cell                     */
  int pface[LAC_MAX_FACES][MAXPIECE];   /*   and its local face           */
} tmpl;

/* xi of local node a of re, padded to 3 coordinates. */
static void
ref_node (const lac_refelem *re, int a, double *p)
{
  for (int k = 0; k < 3; k++)
    p[k] = k < re->dim ? re->xi[a * re->dim + k] : 0;
}

static int
same_point (const double *p, const double *q)
{
  return fabs (p[0] - q[0]) < TOL && fabs (p[1] - q[1]) < TOL
         && fabs (p[2] - q[2]) < TOL;
}

/* Node id of the point p (parent xi): a parent node, or a new node. */
static int
node_id (tmpl *T, const lac_refelem *rp, const double *p)
{
  double q[3];
  for (int a = 0; a < rp->nnodes; a++)
    {
      ref_node (rp, a, q);
      if (same_point (p, q))
        return a;
    }
  for (int k = 0; k < T->nnew; k++)
    if (same_point (p, T->xi[k]))
      return -1 - k;
  if (T->nnew == MAXNEW)
    return -1 - MAXNEW;                 /* caught by the caller */
  memcpy (T->xi[T->nnew], p, sizeof T->xi[0]);
  return -1 - T->nnew++;
}

/* Append a sub-cell of type st with vertices v (parent xi, in st's vertex
 * order); its other nodes are the images of st's reference nodes under the
 * linear map through v. */
static int
tmpl_add_sub (tmpl *T, const lac_refelem *rp, lac_elem_type st,
              const double v[][3])
{
  const lac_refelem *rs = lac_refelem_get (st);
  const lac_refelem *rl = lac_refelem_get (lac_refelem_linear_type (st));
  int s = T->nsub;

  if (s == MAXSUB)
    RF_ERROR (LAC_ESANITY, "template for %s has more than %d sub-cells",
              rp->name, MAXSUB);
  T->type[s] = st;
  for (int a = 0; a < rs->nnodes; a++)
    {
      double p[3] = { 0, 0, 0 }, N[LAC_MAX_NODES];
      int id;
      if (a < rs->nvertices)
        memcpy (p, v[a], sizeof p);
      else
        {
          lac_refelem_eval (rl, rs->xi + a * rs->dim, N, NULL);
          for (int b = 0; b < rl->nnodes; b++)   /* p = sum_b v_b N_b(xi_a) */
            for (int k = 0; k < 3; k++)
              p[k] += N[b] * v[b][k];
        }
      if (a < rs->nvertices)
        memcpy (T->vx[s][a], p, sizeof p);
      id = node_id (T, rp, p);
      if (id == -1 - MAXNEW)
        RF_ERROR (LAC_ESANITY, "template for %s has more than %d new nodes",
                  rp->name, MAXNEW);
      T->node[s][a] = id;
    }
  T->nsub++;
  return LAC_SUCCESS;
}

/* Does the point q (parent xi) lie in the plane (line) of parent face g? */
static int
on_face (const lac_refelem *rp, int g, const double *q)
{
  double p[3][3] = { { 0 } }, n[3] = { 0, 0, 0 }, a[3], b[3], len, dist = 0;

  for (int i = 0; i < rp->dim; i++)
    ref_node (rp, rp->face_node[g][i], p[i]);
  for (int k = 0; k < 3; k++)
    {
      a[k] = p[1][k] - p[0][k];
      b[k] = rp->dim == 3 ? p[2][k] - p[0][k] : 0;
    }
  if (rp->dim == 2)
    n[0] = -a[1], n[1] = a[0];
  else
    lac_vec_cross (a, b, n);
  len = lac_vec_norm (3, n);
  for (int k = 0; k < 3; k++)
    dist += n[k] * (q[k] - p[0][k]);
  return fabs (dist) <= TOL * len;
}

/* Pieces of every parent face; a face that was not cut must be one piece,
 * and every parent node must survive as a node of some sub-cell. */
static int
tmpl_pieces (tmpl *T, const lac_refelem *rp, int f)
{
  int used[LAC_MAX_NODES] = { 0 };

  for (int g = 0; g < rp->nfaces; g++)
    T->npiece[g] = 0;
  for (int s = 0; s < T->nsub; s++)
    {
      const lac_refelem *rs = lac_refelem_get (T->type[s]);
      for (int a = 0; a < rs->nnodes; a++)
        if (T->node[s][a] >= 0)
          used[T->node[s][a]] = 1;
      for (int h = 0; h < rs->nfaces; h++)
        {
          int nv = lac_refelem_get (rs->face_type[h])->nvertices;
          for (int g = 0; g < rp->nfaces; g++)
            {
              int on = 1;
              for (int i = 0; i < nv && on; i++)
                on = on_face (rp, g, T->vx[s][rs->face_node[h][i]]);
              if (!on)
                continue;
              if (T->npiece[g] == MAXPIECE)
                RF_ERROR (LAC_ESANITY, "%s face %d: more than %d pieces",
                          rp->name, g, MAXPIECE);
              T->psub[g][T->npiece[g]] = s;
              T->pface[g][T->npiece[g]++] = h;
            }
        }
    }
  for (int g = 0; g < rp->nfaces; g++)
    if (g == f ? T->npiece[g] < 2 : T->npiece[g] != 1)
      RF_ERROR (LAC_ESANITY, "template for %s cut on face %d leaves face %d "
                "in %d pieces", rp->name, f, g, T->npiece[g]);
  for (int a = 0; a < rp->nnodes; a++)
    if (!used[a])
      RF_ERROR (LAC_EINVAL, "cutting a %s on face %d would drop its node %d; "
                "this element type cannot be refined", rp->name, f, a);
  return LAC_SUCCESS;
}

/* Template 1: cones from the centre c of face f over the other faces. */
static int
tmpl_cone (tmpl *T, const lac_refelem *rp, int f)
{
  const lac_refelem *rf = lac_refelem_get (rp->face_type[f]);
  double c[3] = { 0, 0, 0 };

  for (int i = 0; i < rf->nvertices; i++)
    {
      double p[3];
      ref_node (rp, rp->face_node[f][i], p);
      for (int k = 0; k < 3; k++)
        c[k] += p[k] / rf->nvertices;            /* c = mean of the vertices */
    }
  for (int g = 0; g < rp->nfaces; g++)
    {
      const lac_refelem *rg = lac_refelem_get (rp->face_type[g]);
      double q[4][3], v[5][3];
      lac_elem_type st;
      int status;
      if (g == f)
        continue;
      for (int i = 0; i < rg->nvertices; i++)
        ref_node (rp, rp->face_node[g][i], q[i]);
      /* Face g turns counter-clockwise seen from outside, i.e. clockwise
       * seen from c: reversed, it is a positive base for the cone. */
      if (rp->dim == 2)
        {
          st = rp->order == 1 ? LAC_TRI3 : LAC_TRI6;   /* (q0, q1, c) */
          memcpy (v[0], q[0], sizeof v[0]);
          memcpy (v[1], q[1], sizeof v[0]);
          memcpy (v[2], c, sizeof v[0]);
        }
      else if (rg->nvertices == 3)
        {
          st = rp->order == 1 ? LAC_TET4 : LAC_TET10;  /* (q0, q2, q1, c) */
          memcpy (v[0], q[0], sizeof v[0]);
          memcpy (v[1], q[2], sizeof v[0]);
          memcpy (v[2], q[1], sizeof v[0]);
          memcpy (v[3], c, sizeof v[0]);
        }
      else
        {
          if (rp->order != 1)
            RF_ERROR (LAC_EINVAL, "cannot cut a %s into pyramids: its "
                      "quadrangular faces are quadratic and lac has no "
                      "pyramid13; use the six-hexahedra cut "
                      "(LAC_MACRO_HEX_SIX)", rp->name);
          st = LAC_PYR5;                           /* (q0, q3, q2, q1, c) */
          memcpy (v[0], q[0], sizeof v[0]);
          memcpy (v[1], q[3], sizeof v[0]);
          memcpy (v[2], q[2], sizeof v[0]);
          memcpy (v[3], q[1], sizeof v[0]);
          memcpy (v[4], c, sizeof v[0]);
        }
      status = tmpl_add_sub (T, rp, st, (const double (*)[3]) v);
      if (status)
        return status;
    }
  return LAC_SUCCESS;
}

/* Face-frame map of a hexahedron: (s,t,u) -> parent xi, the affine symmetry
 * of the cube taking u = +1 to face f (vertices a_i, counter-clockwise from
 * outside, at the corners (-1,-1), (1,-1), (1,1), (-1,1) of (s,t)) and
 * u = -1 to the opposite face (o_i = a_i mirrored). */
static void
hex_frame (const double a[4][3], const double o[4][3], double s, double t,
           double u, double *p)
{
  static const double cs[4] = { -1, 1, 1, -1 }, ct[4] = { -1, -1, 1, 1 };
  p[0] = p[1] = p[2] = 0;
  for (int i = 0; i < 4; i++)
    {
      double Nq = (1 + cs[i] * s) * (1 + ct[i] * t) / 4;
      for (int k = 0; k < 3; k++)
        p[k] += Nq * ((1 + u) / 2 * a[i][k] + (1 - u) / 2 * o[i][k]);
    }
}

/* Template 2: six hexahedra (drawing in the file block). */
static int
tmpl_six (tmpl *T, const lac_refelem *rp, int f)
{
  static const double cs[4] = { -1, 1, 1, -1 }, ct[4] = { -1, -1, 1, 1 };
  const lac_refelem *rs = lac_refelem_get (rp->type);
  double a[4][3], o[4][3], P[4][4][3];   /* P[T,B,I,M][i] */
  int axis = -1;

  if (rp->shape != LAC_SHAPE_HEX)
    RF_ERROR (LAC_EINVAL, "the six-hexahedra cut needs a hexahedron, not "
              "a %s", rp->name);
  for (int i = 0; i < 4; i++)
    ref_node (rp, rp->face_node[f][i], a[i]);
  for (int k = 0; k < 3 && axis < 0; k++)
    if (a[0][k] == a[1][k] && a[0][k] == a[2][k] && a[0][k] == a[3][k])
      axis = k;                          /* the face is xi_axis = +-1 */
  if (axis < 0)
    RF_ERROR (LAC_ESANITY, "%s face %d is not a side of the cube", rp->name,
              f);
  for (int i = 0; i < 4; i++)
    {
      memcpy (o[i], a[i], sizeof o[i]);
      o[i][axis] = -a[i][axis];
    }
  for (int i = 0; i < 4; i++)
    {
      hex_frame (a, o, cs[i], ct[i], 1, P[0][i]);                /* T_i */
      hex_frame (a, o, cs[i], ct[i], -1, P[1][i]);               /* B_i */
      hex_frame (a, o, cs[i] / 2, ct[i] / 2, 1, P[2][i]);        /* I_i */
      hex_frame (a, o, cs[i] / 2, ct[i] / 2, 0, P[3][i]);        /* M_i */
    }
  /* Each sub-hex as C[r][s][w], r, s, w in {0, 1} (- / +), right-handed in
   * (s,t,u); its vertex list then follows the hex's own reference table. */
  for (int h = 0; h < 6; h++)
    {
      double C[2][2][2][3], v[8][3];
      int status;
      for (int r = 0; r < 2; r++)
        for (int s = 0; s < 2; s++)
          for (int w = 0; w < 2; w++)
            {
              int q = s ? (r ? 2 : 3) : (r ? 1 : 0);   /* corner of (r,s) */
              const double *x;
              if (h == 0)                               /* central   */
                x = w ? P[2][q] : P[3][q];
              else if (h == 1)                          /* bottom    */
                x = w ? P[3][q] : P[1][q];
              else
                {                                       /* trapezoid */
                  int k = h - 2, i = r ? (k + 1) % 4 : k;
                  x = s ? (w ? P[2][i] : P[3][i]) : (w ? P[0][i] : P[1][i]);
                }
              memcpy (C[r][s][w], x, sizeof C[r][s][w]);
            }
      for (int j = 0; j < 8; j++)
        {
          const double *xi = rs->xi + 3 * j;
          memcpy (v[j], C[xi[0] > 0][xi[1] > 0][xi[2] > 0], sizeof v[j]);
        }
      status = tmpl_add_sub (T, rp, rp->type, (const double (*)[3]) v);
      if (status)
        return status;
    }
  return LAC_SUCCESS;
}

/* The template for (type of rp, face f), built on first use. */
static int
tmpl_get (tmpl *cache, const lac_refelem *rp, int f,
          const lac_macro_opts *opts, const tmpl **out)
{
  tmpl *T = &cache[(size_t) rp->type * LAC_MAX_FACES + (size_t) f];
  int status, hex_cut = opts ? opts->hex_cut : LAC_MACRO_HEX_DEFAULT;

  if (!T->state)
    {
      memset (T, 0, sizeof *T);
      if (rp->shape == LAC_SHAPE_HEX
          && (hex_cut == LAC_MACRO_HEX_SIX
              || (hex_cut == LAC_MACRO_HEX_DEFAULT && rp->order == 2)))
        status = tmpl_six (T, rp, f);
      else
        status = tmpl_cone (T, rp, f);
      if (!status)
        status = tmpl_pieces (T, rp, f);
      if (status)
        return status;
      T->state = 1;
    }
  *out = T;
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */

void
lac_refine_map_free (lac_refine_map *map)
{
  if (!map)
    return;
  lac_free (map->cptr);
  lac_free (map->fptr);
  lac_free (map->fcell);
  lac_free (map->fface);
  lac_free (map);
}

static lac_refine_map *
map_alloc (size_t ncells, size_t npieces)
{
  lac_refine_map *map = lac_calloc (1, sizeof *map);
  if (!map)
    return NULL;
  map->ncells = ncells;
  map->cptr = lac_malloc ((ncells + 1) * sizeof *map->cptr);
  map->fptr = lac_malloc ((ncells * LAC_MAX_FACES + 1) * sizeof *map->fptr);
  map->fcell = lac_malloc (npieces * sizeof *map->fcell);
  map->fface = lac_malloc (npieces * sizeof *map->fface);
  if (!map->cptr || !map->fptr || !map->fcell || !map->fface)
    {
      lac_refine_map_free (map);
      return NULL;
    }
  return map;
}

/* Copy every group of m into r through the map: cells -> sub-cells, facets
 * -> pieces, node groups unchanged (old nodes keep their indices). */
static int
remap_groups (const lac_mesh *m, const lac_refine_map *map, lac_mesh *r)
{
  int status = LAC_SUCCESS;

  for (size_t gi = 0; gi < m->ngroups && !status; gi++)
    {
      const lac_group *G = &m->group[gi];
      size_t n = 0, *cell = NULL;
      int *face = NULL;

      if (G->dim < m->dim - 1)
        {
          status = lac_mesh_add_node_group (r, G->name, G->dim, G->tag,
                                            G->nnodes, G->node);
          continue;
        }
      for (size_t e = 0; e < G->n; e++)
        {
          size_t c = G->cell[e], q = c * LAC_MAX_FACES + (size_t) G->face[e];
          n += G->dim == m->dim ? map->cptr[c + 1] - map->cptr[c]
                                : map->fptr[q + 1] - map->fptr[q];
        }
      cell = lac_malloc (n * sizeof *cell);
      face = lac_malloc (n * sizeof *face);
      if (!cell || !face)
        status = RF_ERRMSG (LAC_ENOMEM, "group '%s' of %zu entities",
                            G->name, n);
      for (size_t e = 0, j = 0; e < G->n && !status; e++)
        {
          size_t c = G->cell[e], q = c * LAC_MAX_FACES + (size_t) G->face[e];
          if (G->dim == m->dim)
            for (size_t s = map->cptr[c]; s < map->cptr[c + 1]; s++, j++)
              cell[j] = s, face[j] = -1;
          else
            for (size_t p = map->fptr[q]; p < map->fptr[q + 1]; p++, j++)
              cell[j] = map->fcell[p], face[j] = map->fface[p];
        }
      if (!status)
        status = lac_mesh_add_group (r, G->name, G->dim, G->tag, n, cell,
                                     face);
      lac_free (cell);
      lac_free (face);
    }
  return status;
}

/* Sizes of the refined mesh, counted in step 1 of lac_refine_cut. */
typedef struct rsizes
{
  size_t nnew, ncells, nconn, npieces;
} rsizes;

/* Where step 3 of lac_refine_cut writes next: cell, node, connectivity
 * entry and face piece of the new mesh and map. */
typedef struct rcursor
{
  size_t nc, nn, pc, pp;
} rcursor;

/* Step 1 of lac_refine_cut: check cut[] and count the cells, connectivity
 * entries, new nodes and face pieces of the refined mesh (building the
 * templates into the cache). */
static int
refine_sizes (const lac_mesh *m, const int *cut, const lac_macro_opts *opts,
              tmpl *cache, rsizes *z)
{
  memset (z, 0, sizeof *z);
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      const tmpl *T;
      int status;
      if (!re || re->dim != m->dim)
        RF_ERROR (LAC_EINVAL, "cell %zu (tag %zu) is not a %dD cell", c,
                  m->cell_tag[c], m->dim);
      if (cut[c] < 0)
        {
          z->ncells++;
          z->nconn += m->ptr[c + 1] - m->ptr[c];
          z->npieces += (size_t) re->nfaces;
          continue;
        }
      if (cut[c] >= re->nfaces)
        RF_ERROR (LAC_EINVAL, "cell %zu (tag %zu, %s) has no face %d", c,
                  m->cell_tag[c], re->name, cut[c]);
      status = tmpl_get (cache, re, cut[c], opts, &T);
      if (status)
        return status;
      z->nnew += (size_t) T->nnew;
      z->ncells += (size_t) T->nsub;
      for (int s = 0; s < T->nsub; s++)
        z->nconn += (size_t) lac_refelem_get (T->type[s])->nnodes;
      for (int g = 0; g < re->nfaces; g++)
        z->npieces += (size_t) T->npiece[g];
    }
  return LAC_SUCCESS;
}

/* Step 2 of lac_refine_cut: old nodes keep their indices and tags; new
 * tags follow the largest. */
static void
copy_nodes (const lac_mesh *m, lac_mesh *r)
{
  size_t maxtag = 0;
  memcpy (r->x, m->x, m->nnodes * (size_t) m->dim * sizeof *r->x);
  for (size_t i = 0; i < m->nnodes; i++)
    {
      r->node_tag[i] = m->node_tag[i];
      if (m->node_tag[i] > maxtag)
        maxtag = m->node_tag[i];
    }
  for (size_t i = m->nnodes; i < r->nnodes; i++)
    r->node_tag[i] = maxtag + 1 + (i - m->nnodes);
}

/* Step 3, a cell that is not cut: copied, each face its own piece. */
static void
copy_cell (const lac_mesh *m, size_t c, lac_mesh *r, lac_refine_map *mp,
           rcursor *w)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  r->type[w->nc] = m->type[c];
  r->cell_tag[w->nc] = m->cell_tag[c];
  r->body[w->nc] = m->body[c];
  for (size_t k = m->ptr[c]; k < m->ptr[c + 1]; k++)
    r->conn[w->pc++] = m->conn[k];
  r->ptr[++w->nc] = w->pc;
  for (int g = 0; g < LAC_MAX_FACES; g++)
    {
      mp->fptr[c * LAC_MAX_FACES + (size_t) g] = w->pp;
      if (g < re->nfaces)
        mp->fcell[w->pp] = w->nc - 1, mp->fface[w->pp++] = g;
    }
}

/* Step 3, a cut cell: its new nodes placed by the parent's map, its
 * sub-cells, and the pieces of each of its faces. */
static void
cut_cell (const lac_mesh *m, size_t c, const tmpl *T, lac_mesh *r,
          lac_refine_map *mp, rcursor *w)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  double xe[LAC_MAX_NODES * 3], N[LAC_MAX_NODES];
  lac_mesh_cell_coords (m, c, xe);
  for (int k = 0; k < T->nnew; k++)
    {
      double *x = r->x + (w->nn + (size_t) k) * (size_t) m->dim;
      lac_refelem_eval (re, T->xi[k], N, NULL);
      for (int i = 0; i < m->dim; i++)          /* x = sum_a x_a N_a(xi) */
        {
          x[i] = 0;
          for (int a = 0; a < re->nnodes; a++)
            x[i] += xe[a * m->dim + i] * N[a];
        }
    }
  for (int s = 0; s < T->nsub; s++)
    {
      const lac_refelem *rs = lac_refelem_get (T->type[s]);
      r->type[w->nc] = T->type[s];
      r->cell_tag[w->nc] = m->cell_tag[c];
      r->body[w->nc] = m->body[c];
      for (int a = 0; a < rs->nnodes; a++)
        {
          int id = T->node[s][a];
          r->conn[w->pc++] = id >= 0 ? m->conn[m->ptr[c] + (size_t) id]
                                     : (int) (w->nn + (size_t) (-1 - id));
        }
      r->ptr[++w->nc] = w->pc;
    }
  for (int g = 0; g < LAC_MAX_FACES; g++)
    {
      mp->fptr[c * LAC_MAX_FACES + (size_t) g] = w->pp;
      for (int p = 0; g < re->nfaces && p < T->npiece[g]; p++, w->pp++)
        {
          mp->fcell[w->pp] = mp->cptr[c] + (size_t) T->psub[g][p];
          mp->fface[w->pp] = T->pface[g][p];
        }
    }
  w->nn += (size_t) T->nnew;
}

/* lac_refine_cut: one round of local refinement  [LAC §4.4].
 *
 *   Every cell c with cut[c] >= 0 is replaced by the sub-cells of its
 *   template for face cut[c] (file block); other cells are copied.  Old
 *   nodes keep their indices, new nodes follow, placed by the parent's
 *   isoparametric map.  Groups are remapped.
 *
 *   [in]  m     mesh (borrowed, unchanged)
 *   [in]  cut   m->ncells entries: face to cut, or -1
 *   [in]  opts  template choice (NULL: defaults)
 *   [out] out   the new mesh (caller frees), NULL on failure
 *   [out] map   old cells/faces -> new (caller frees), NULL on failure
 *   returns LAC_SUCCESS, LAC_EINVAL (bad face, type that cannot be cut),
 *   LAC_ENOMEM */
int
lac_refine_cut (const lac_mesh *m, const int *cut, const lac_macro_opts *opts,
                lac_mesh **out, lac_refine_map **map)
{
  int status = LAC_SUCCESS;
  tmpl *cache = NULL;                      /* owned, one per (type, face) */
  lac_mesh *r = NULL;
  lac_refine_map *mp = NULL;
  rsizes z;
  rcursor w = { 0, 0, 0, 0 };

  if (!out || !map)
    RF_ERROR (LAC_EINVAL, "no output pointers");
  *out = NULL;
  *map = NULL;
  if (!m || !cut)
    RF_ERROR (LAC_EINVAL, "no mesh or no list of faces to cut");
  cache = lac_calloc ((size_t) LAC_NELEM_TYPES * LAC_MAX_FACES,
                      sizeof *cache);
  if (!cache)
    RF_ERROR (LAC_ENOMEM, "refinement templates");

  /* Step 1: sizes of the new mesh. */
  status = refine_sizes (m, cut, opts, cache, &z);
  if (status)
    goto done;
  r = lac_mesh_alloc (m->dim, m->nnodes + z.nnew, z.ncells, z.nconn);
  mp = map_alloc (m->ncells, z.npieces);
  if (!r || !mp)
    {
      status = RF_ERRMSG (LAC_ENOMEM, "refined mesh of %zu cells", z.ncells);
      goto done;
    }

  /* Step 2: the old nodes. */
  copy_nodes (m, r);

  /* Step 3: cells, new nodes, pieces. */
  w.nn = m->nnodes;
  for (size_t c = 0; c < m->ncells; c++)
    {
      const tmpl *T = NULL;
      mp->cptr[c] = w.nc;
      if (cut[c] < 0)
        copy_cell (m, c, r, mp, &w);
      else
        {
          tmpl_get (cache, lac_refelem_get (m->type[c]), cut[c], opts,
                    &T);                        /* built in step 1 */
          cut_cell (m, c, T, r, mp, &w);
        }
    }
  mp->cptr[m->ncells] = w.nc;
  mp->fptr[m->ncells * LAC_MAX_FACES] = w.pp;
  if (w.nc != z.ncells || w.pc != z.nconn || w.pp != z.npieces
      || w.nn != r->nnodes)
    {
      status = RF_ERRMSG (LAC_ESANITY, "refinement counts disagree");
      goto done;
    }

  /* Step 4: the groups. */
  status = remap_groups (m, mp, r);

done:
  lac_free (cache);
  if (status)
    {
      lac_mesh_free (r);
      lac_refine_map_free (mp);
      return status;
    }
  *out = r;
  *map = mp;
  return LAC_SUCCESS;
}
