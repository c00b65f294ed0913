/* lac_mesh_box.c -- structured box meshes built in code (no gmsh)
 *
 * lac_mesh_box (declared in lac_mesh.h): [0,L0]x[0,L1](x[0,L2]) cut into
 * n0 x n1 (x n2) boxes, each one cell (quad/hex) or split into simplices
 * (tri: along a diagonal; tet: the 6-tetrahedra Kuhn split, so that
 * neighbouring faces match).  Used by tests, examples and benchmarks.
 *
 * Box meshes: simplices come from the Kuhn (Freudenthal) split of every
 * square into 2 triangles along its (0,0)-(1,1) diagonal and of every cube
 * into 6 tetrahedra around its (0,0,0)-(1,1,1) diagonal; the same split in
 * every box makes the mesh conforming.  Nodes of order-2 meshes live on a
 * lattice of half steps, which numbers them once for all cells.
 *   H. W. Kuhn, Some combinatorial lemmas in topology, IBM J. Res. Dev. 4
 *   (1960) 518-524.
 */
#include "fem/lac_mesh.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

typedef struct box
{
  int d;              /* dimension                                       */
  int p;              /* order: nodes on a lattice of step h/p           */
  int simplex;        /* tri/tet (Kuhn split) or quad/hex                */
  size_t n[3];        /* boxes per direction (1 in unused directions)    */
  size_t m[3];        /* lattice points per direction: p*n + 1           */
  double h[3];        /* box sizes                                       */
  double distort;
} box;

/* A pseudo-random number in [0, 1) from an integer key (splitmix64). */
static double
hash_unit (uint64_t key)
{
  uint64_t z = key + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (double) (z >> 11) * 0x1.0p-53;
}

/* Position of the box vertex with integer coordinates v[]: on the grid,
 * moved by up to distort*h_k in each direction if it is interior. */
static void
box_vertex (const box *B, const size_t *v, double *x)
{
  int interior = 1;
  uint64_t key = 0;
  for (int k = B->d - 1; k >= 0; k--)
    {
      interior = interior && v[k] > 0 && v[k] < B->n[k];
      key = key * (uint64_t) (B->n[k] + 1) + v[k];
    }
  for (int k = 0; k < B->d; k++)
    {
      x[k] = (double) v[k] * B->h[k];
      if (interior && B->distort > 0)
        x[k] += B->distort * B->h[k]
                * (2 * hash_unit (3 * key + (uint64_t) k) - 1);
    }
}

/* Position of the lattice point g (p = 2: odd coordinates are half steps).
 * Quadrangles/hexahedra: mean of the 2^s box vertices around it (s = number
 * of odd coordinates), i.e. the multilinear map at the edge, face or cell
 * centre.  Simplices: midpoint of the Kuhn edge from g rounded down to g
 * rounded up (every Kuhn edge joins a to b with b - a in {0,1}^d). */
static void
box_node (const box *B, const size_t *g, double *x)
{
  size_t odd[3], s = 0, v[3];
  double y[3];

  for (int k = 0; k < B->d; k++)
    if (B->p == 2 && g[k] % 2)
      odd[s++] = (size_t) k;
  for (int k = 0; k < B->d; k++)
    x[k] = 0;
  for (size_t corner = 0; corner < ((size_t) 1 << s); corner++)
    {
      if (B->simplex && corner != 0 && corner + 1 != ((size_t) 1 << s))
        continue;   /* simplices: only the all-down and all-up ends */
      for (int k = 0; k < B->d; k++)
        v[k] = g[k] / (size_t) B->p;
      for (size_t j = 0; j < s; j++)
        v[odd[j]] += (corner >> j) & 1;
      box_vertex (B, v, y);
      for (int k = 0; k < B->d; k++)
        x[k] += y[k];
    }
  for (int k = 0; k < B->d; k++)
    x[k] /= (double) (B->simplex ? (s ? 2 : 1) : ((size_t) 1 << s));
}

/* The vertices (in {0,1}^d) of sub-simplex s of a box: 2 triangles along
 * the (0,0)-(1,1) diagonal, or the 6 Kuhn tetrahedra 0, e_a, e_a+e_b,
 * (1,1,1) for the permutations (a,b,c) of the axes, positively oriented. */
static void
kuhn_simplex (int d, int s, int v[4][3])
{
  static const int tri[2][3][2] = { { { 0, 0 }, { 1, 0 }, { 1, 1 } },
                                    { { 0, 0 }, { 1, 1 }, { 0, 1 } } };
  static const int perm[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 },
                                  { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  memset (v, 0, 4 * sizeof v[0]);
  if (d == 2)
    {
      for (int a = 0; a < 3; a++)
        for (int k = 0; k < 2; k++)
          v[a][k] = tri[s][a][k];
      return;
    }
  v[1][perm[s][0]] = 1;
  v[2][perm[s][0]] = v[2][perm[s][1]] = 1;
  v[3][0] = v[3][1] = v[3][2] = 1;
  {
    int a = v[1][0], b = v[1][1], c = v[1][2];   /* v0 = 0: det [v1 v2 v3] */
    int det = a * (v[2][1] - v[2][2]) - b * (v[2][0] - v[2][2])
              + c * (v[2][0] - v[2][1]);
    if (det < 0)
      for (int k = 0; k < 3; k++)
        {
          int t = v[1][k];
          v[1][k] = v[2][k];
          v[2][k] = t;
        }
  }
}

/* Lattice offsets (0..p per direction) of the nodes of sub-cell s. */
static void
box_offsets (const box *B, const lac_refelem *re, int s,
             size_t off[LAC_MAX_NODES][3])
{
  int v[4][3];
  int d = B->d;

  if (B->simplex)
    kuhn_simplex (d, s, v);
  for (int a = 0; a < re->nnodes; a++)
    for (int k = 0; k < 3; k++)
      {
        const double *xi = re->xi + a * d;
        double t = 0;
        if (k >= d)
          t = 0;
        else if (!B->simplex)
          t = (xi[k] + 1) / 2;                   /* [-1,1] -> [0,1] */
        else
          {
            t = v[0][k];                         /* v0 + sum xi_j (v_j - v0) */
            for (int j = 0; j < d; j++)
              t += xi[j] * (v[j + 1][k] - v[0][k]);
          }
        off[a][k] = (size_t) lround (t * B->p);
      }
}

static size_t
lattice_id (const box *B, const size_t *g)
{
  return g[0] + B->m[0] * (g[1] + B->m[1] * g[2]);
}

static void
lattice_coords (const box *B, size_t id, size_t *g)
{
  g[0] = id % B->m[0];
  g[1] = id / B->m[0] % B->m[1];
  g[2] = id / B->m[0] / B->m[1];
}

/* Connectivity (lattice ids first, node indices after numbering the used
 * lattice points lexicographically) and coordinates.  node_lid[i] is the
 * lattice id of node i. */
static int
box_cells (const box *B, const lac_refelem *re, size_t nsub, lac_mesh **out,
           size_t **node_lid)
{
  size_t nl = B->m[0] * B->m[1] * B->m[2], nbox = B->n[0] * B->n[1] * B->n[2];
  size_t ncells = nbox * nsub, nn = (size_t) re->nnodes, nnodes = 0, c = 0;
  size_t *lid = lac_malloc (ncells * nn * sizeof *lid);
  size_t *num = lac_malloc (nl * sizeof *num), *nl_of = NULL;
  lac_mesh *m = NULL;
  int status = LAC_SUCCESS;

  if (!lid || !num)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "box of %zu cells", ncells);
      goto done;
    }
  for (size_t i = 0; i < nl; i++)
    num[i] = SIZE_MAX;
  for (size_t b = 0; b < nbox; b++)
    for (size_t s = 0; s < nsub; s++, c++)
      {
        size_t off[LAC_MAX_NODES][3], bc[3] = { b % B->n[0],
                                                b / B->n[0] % B->n[1],
                                                b / B->n[0] / B->n[1] };
        box_offsets (B, re, (int) s, off);
        for (size_t a = 0; a < nn; a++)
          {
            size_t g[3];
            for (int k = 0; k < 3; k++)
              g[k] = bc[k] * (size_t) B->p + off[a][k];
            lid[c * nn + a] = lattice_id (B, g);
            num[lid[c * nn + a]] = 0;              /* used */
          }
      }
  for (size_t i = 0; i < nl; i++)
    if (num[i] == 0)
      num[i] = nnodes++;
    else
      num[i] = SIZE_MAX;
  m = lac_mesh_alloc (B->d, nnodes, ncells, ncells * nn);
  nl_of = lac_malloc (nnodes * sizeof *nl_of);
  if (!m || !nl_of)
    {
      status = m ? LAC_ERRMSG (LAC_ENOMEM, "box nodes") : LAC_ENOMEM;
      goto done;
    }
  for (size_t i = 0; i < nl; i++)
    if (num[i] != SIZE_MAX)
      {
        size_t g[3];
        nl_of[num[i]] = i;
        lattice_coords (B, i, g);
        box_node (B, g, m->x + num[i] * (size_t) B->d);
      }
  for (c = 0; c < ncells; c++)
    {
      m->type[c] = re->type;
      m->ptr[c + 1] = (c + 1) * nn;
      for (size_t a = 0; a < nn; a++)
        m->conn[c * nn + a] = (int) num[lid[c * nn + a]];
    }
done:
  lac_free (lid);
  lac_free (num);
  if (status)
    {
      lac_mesh_free (m);
      lac_free (nl_of);
      m = NULL;
      nl_of = NULL;
    }
  *out = m;
  *node_lid = nl_of;
  return status;
}

/* Side of the box that face f of cell c lies on: 2*axis + (0 min, 1 max),
 * or -1 if it is interior. */
static int
box_face_side (const box *B, const lac_mesh *m, const size_t *node_lid,
               size_t c, int f)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  for (int k = 0; k < B->d; k++)
    for (int end = 0; end < 2; end++)
      {
        size_t want = end ? B->m[k] - 1 : 0;
        int on = 1;
        for (int i = 0; i < nv && on; i++)
          {
            size_t g[3];
            int node = m->conn[m->ptr[c] + (size_t) re->face_node[f][i]];
            lattice_coords (B, node_lid[node], g);
            on = g[k] == want;
          }
        if (on)
          return 2 * k + end;
      }
  return -1;
}

/* Facet groups "xmin" ... "zmax" and the cell group "body". */
static int
box_groups (const box *B, lac_mesh *m, const size_t *node_lid)
{
  static const char *side_name[6] = { "xmin", "xmax", "ymin", "ymax",
                                      "zmin", "zmax" };
  const lac_refelem *re = lac_refelem_get (m->type[0]);
  size_t count[6] = { 0 }, *cell = NULL;
  int *face = NULL, status = LAC_SUCCESS;

  for (size_t c = 0; c < m->ncells; c++)
    for (int f = 0; f < re->nfaces; f++)
      {
        int s = box_face_side (B, m, node_lid, c, f);
        if (s >= 0)
          count[s]++;
      }
  cell = lac_malloc ((m->ncells > 0 ? m->ncells : 1) * re->nfaces
                     * sizeof *cell);
  face = lac_malloc ((m->ncells > 0 ? m->ncells : 1) * re->nfaces
                     * sizeof *face);
  if (!cell || !face)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "box groups");
      goto done;
    }
  for (int s = 0; s < 2 * B->d && !status; s++)
    {
      size_t n = 0;
      for (size_t c = 0; c < m->ncells; c++)
        for (int f = 0; f < re->nfaces; f++)
          if (box_face_side (B, m, node_lid, c, f) == s)
            {
              cell[n] = c;
              face[n++] = f;
            }
      status = lac_mesh_add_group (m, side_name[s], B->d - 1, 0, n, cell,
                                   face);
    }
  if (status)
    goto done;
  for (size_t c = 0; c < m->ncells; c++)
    cell[c] = c;
  status = lac_mesh_add_group (m, "body", B->d, 0, m->ncells, cell, NULL);
  for (size_t c = 0; c < m->ncells && !status; c++)
    m->body[c] = (int) m->ngroups - 1;
done:
  lac_free (cell);
  lac_free (face);
  return status;
}

/* lac_mesh_box: structured mesh of [0,L0]x[0,L1](x[0,L2]) with n0 x n1
 * (x n2) boxes, each one cell (quadrangles, hexahedra) or split into 2
 * triangles or 6 tetrahedra.  0 <= distort < 0.5; a distortion that
 * inverts a cell is reported (LAC_EINVAL).
 *   [in]  type  any 2D or 3D type but pyr5
 *   [in]  n, L  dim entries each
 *   [out] out   the mesh (caller frees), NULL on failure */
int
lac_mesh_box (lac_elem_type type, const size_t *n, const double *L,
              double distort, lac_mesh **out)
{
  const lac_refelem *re = lac_refelem_get (type);
  box B = { 0 };
  lac_mesh *m = NULL;
  size_t *node_lid = NULL;
  int status;

  if (!out)
    LAC_ERROR (LAC_EINVAL, "no output pointer");
  *out = NULL;
  if (!re || re->dim < 2 || re->shape == LAC_SHAPE_PYR)
    LAC_ERROR (LAC_EINVAL, "box meshes are made of triangles, quadrangles, "
               "tetrahedra or hexahedra, not %s", re ? re->name : "(none)");
  if (!n || !L || !(distort >= 0 && distort < 0.5))
    LAC_ERROR (LAC_EINVAL, "box: missing sizes, or distort = %g not in "
               "[0, 0.5)", distort);
  B.d = re->dim;
  B.p = re->order;
  B.simplex = re->shape == LAC_SHAPE_TRI || re->shape == LAC_SHAPE_TET;
  B.distort = distort;
  for (int k = 0; k < 3; k++)
    {
      B.n[k] = k < B.d ? n[k] : 1;
      if (k < B.d && (n[k] < 1 || !(L[k] > 0)))
        LAC_ERROR (LAC_EINVAL, "box: direction %d has %zu cells of length %g",
                   k, n[k], L[k]);
      B.m[k] = k < B.d ? (size_t) B.p * B.n[k] + 1 : 1;
      B.h[k] = k < B.d ? L[k] / (double) n[k] : 0;
    }
  status = box_cells (&B, re, B.simplex ? (B.d == 2 ? 2 : 6) : 1, &m,
                      &node_lid);
  if (!status)
    status = box_groups (&B, m, node_lid);
  if (!status)
    {
      status = lac_mesh_check_orientation (m, 0, NULL);
      if (status == LAC_EINVAL || status == LAC_ESING)
        {
          char msg[512];
          snprintf (msg, sizeof msg, "%s", lac_error_message ());
          status = LAC_ERRMSG (LAC_EINVAL, "distort = %g is too large: %s",
                               distort, msg);
        }
    }
  lac_free (node_lid);
  if (status)
    lac_mesh_free (m);
  else
    *out = m;
  return status;
}
