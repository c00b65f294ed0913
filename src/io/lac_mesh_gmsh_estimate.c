/* lac_mesh_gmsh_estimate.c -- the size of a .geo mesh before it is made
 *                                                 (lac_mesh_gmsh_estimate.h)
 *
 * Where the counts come from.  gmsh 4.8's C API sets transfinite,
 * recombine and extrusion constraints but reads none of them back (there
 * is no getTransfinite...), and the unrolled .geo gmsh can write keeps
 * the transfinite constraints but drops the extrusion layers.  lac parses
 * neither: it meshes the curves, which costs little, and gmsh's 1D mesh
 * already obeys every constraint a curve has -- a transfinite curve of
 * N nodes has N - 1 segments, a curve swept by an extrusion with Layers
 * has one segment per layer.  Per top-dimensional entity e, with C(e) its
 * boundary curves, s_c segments and mean segment length h_c on curve c:
 *
 *   counted (the scene's cells are quadrilaterals or hexahedra: gmsh
 *   makes an all-hexahedral mesh only of a transfinite or extruded
 *   volume, lac asking no 3D recombination, and a surface has >= 3
 *   curves; or the entity is a topological quadrilateral, 4 curves, or
 *   hexahedron, 6 faces and 12 curves, whatever the cells)
 *       nodes(e) = prod_c (s_c + 1)^(d/|C|)
 *   exact for a transfinite quadrilateral or a hexahedral block (each of
 *   the d directions has |C|/d curves of equal counts), and for a
 *   quadrilateral extruded in layers; for order 2 times f(s)/(s+1)^d, s
 *   the geometric mean of the s_c, f = (2s+1)^d (quad9, hex27, and tri6,
 *   tet10 on a transfinite block: its diagonals' nodes included),
 *   (s+1)(3s+1) (quad8), (s+1)^2 (4s+1) (hex20): edge, face, centre
 *   nodes of the s^d cells.  An unstructured mesh of such a block has
 *   about as many nodes (within the 2/sqrt(3) and 1.4 below);
 *
 *   otherwise (triangles, tetrahedra: the Delaunay bound)
 *       nodes(e) = c_d * measure(e) / h^d, h = exp(mean of log h_c),
 *   c_2 = 2/sqrt(3) (1 for recombined quadrangles), c_3 = 1.4 (vertices per
 *   h^3 of a Delaunay tetrahedral mesh), times 2^d for order 2; the
 *   measure is the entity's area / volume for the OpenCASCADE kernel
 *   (gmshModelOccGetMass), the measure of its bounding box otherwise.
 *
 * Memory of the run on n = dim * nodes dofs, with r nonzeros per row of K
 * (by cell: the nodes a node shares a cell with, times dim; hex8 81),
 *   bytes = 1e8 + 24 r n (K and its assembly)
 *         + Cholesky  (cholmod; schur, augmented, split):
 *              1.5e3 n (2D), 277 k n^(4/3) (3D; k = 2 for order 2),
 *         + LU (umfpack; saddle): twice that,
 *         + dense LU: 8 n^2,
 *         + iterative (petsc): 36 r n + 200 n (PETSc's copy of K, the
 *              multigrid hierarchy, K + C W C^T, vectors),
 *         + lac infsup (no solve: the Cholesky factor of its norm matrix
 *              A, f C with C the Cholesky term above, f = 1/4 for the H1
 *              Gram matrix in 3D, else 1): f C + 512 n (the dense path,
 *              A^-1 C by blocks), 3.5 f C (the sparse path, also the LU
 *              factor of the saddle-point matrix).
 * The constants: lac run's peaks on tri6 and hex meshes (Cholesky, 3D:
 * 1.2 kB x nodes^(4/3) per node^(4/3) of hex8), and the 5.1 GB summed
 * over 2 processes of the 1M-dof 3D Taylor patch test with petsc.
 */
#include "io/lac_mesh_gmsh_estimate.h"

#include <gmshc.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "contact/lac_infsup.h"
#include "fem/lac_spaces.h"
#include "io/lac_mesh_gmsh_cells.h"

/* The 1D mesh of one curve. */
typedef struct
{
  int tag;
  double seg, len;               /* segments, their total length          */
} curve;

/* The cells asked for: quadrilateral / hexahedral, order, serendipity. */
typedef struct
{
  int quad, order, serendipity;
} cells;

static int
by_tag (const void *a, const void *b)
{
  int x = ((const curve *) a)->tag, y = ((const curve *) b)->tag;
  return (x > y) - (x < y);
}

static int
int_cmp (const void *a, const void *b)
{
  int x = *(const int *) a, y = *(const int *) b;
  return (x > y) - (x < y);
}

/* Segments and length of the 1D mesh of curve c (nodes read into R). */
static int
measure_curve (lac_gmsh_reader *R, curve *c)
{
  lac_gmsh_elements E;
  int status = lac_gmsh_get_elements (R, &E, 1, c->tag);
  c->seg = c->len = 0;
  for (size_t i = 0; !status && i < E.ntypes; i++)
    {
      size_t ne = E.etags_n[i], nn = ne ? E.ntags_n[i] / ne : 0;
      for (size_t j = 0; nn >= 2 && j < ne; j++)
        {
          size_t a = lac_gmsh_tag_position (R, E.ntags[i][j * nn]);
          size_t b = lac_gmsh_tag_position (R, E.ntags[i][j * nn + 1]);
          double d2 = 0;
          if (a == SIZE_MAX || b == SIZE_MAX)
            continue;
          for (int k = 0; k < 3; k++)
            d2 += pow (R->coord[3 * a + k] - R->coord[3 * b + k], 2);
          c->len += sqrt (d2);
          c->seg += 1;
        }
    }
  if (!status)
    lac_gmsh_elements_free (&E);
  return status;
}

/* Every curve of the model with its 1D mesh, sorted by tag. */
static int
read_curves (lac_gmsh_reader *R, curve **out, size_t *n)
{
  int *dimtags = NULL, ierr = 0, status;
  size_t nd = 0;
  *out = NULL;
  *n = 0;
  if ((status = lac_gmsh_read_nodes (R)))
    return status;
  gmshModelGetEntities (&dimtags, &nd, 1, &ierr);
  if (ierr)
    status = lac_gmsh_fail (R, LAC_EDEP, "cannot get the curves");
  else if (nd && !(*out = lac_malloc (nd / 2 * sizeof **out)))
    status = lac_error_set (LAC_ENOMEM, "lac_mesh_read", "%zu curves",
                            nd / 2);
  for (size_t e = 0; !status && e + 1 < nd; e += 2)
    {
      (*out)[*n].tag = dimtags[e + 1];
      status = measure_curve (R, &(*out)[(*n)++]);
    }
  gmshFree (dimtags);
  lac_free (R->tag), lac_free (R->index), lac_free (R->coord);
  R->tag = R->index = NULL;
  R->coord = NULL;
  R->nall = 0;
  if (status)
    {
      lac_free (*out);
      *out = NULL;
      return status;
    }
  if (*n)
    qsort (*out, *n, sizeof **out, by_tag);
  return LAC_SUCCESS;
}

/* The distinct curves bounding entity (dim, tag): *tags (gmshFree), *n;
 * *nfaces: the surfaces bounding a volume (0 for a surface). */
static int
entity_curves (const lac_gmsh_reader *R, int dim, int tag, int **tags,
               size_t *n, size_t *nfaces)
{
  int one[2] = { dim, tag }, *b = NULL, *c = NULL, ierr = 0;
  size_t nb = 0, nc = 0, k = 0;
  gmshModelGetBoundary (one, 2, &b, &nb, 0, 0, 0, &ierr);
  if (!ierr && dim == 3)
    gmshModelGetBoundary (b, nb, &c, &nc, 0, 0, 0, &ierr);
  *nfaces = dim == 3 ? nb / 2 : 0;
  if (dim != 3)
    c = b, nc = nb, b = NULL;
  gmshFree (b);
  if (ierr)
    {
      gmshFree (c);
      return lac_gmsh_fail (R, LAC_EDEP, "cannot get the boundary curves");
    }
  for (size_t i = 0; i + 1 < nc; i += 2)      /* keep the tags only */
    c[i / 2] = abs (c[i + 1]);
  nc /= 2;
  if (nc)
    qsort (c, nc, sizeof *c, int_cmp);
  for (size_t i = 0; i < nc; i++)
    if (k == 0 || c[i] != c[k - 1])
      c[k++] = c[i];
  *tags = c;
  *n = k;
  return LAC_SUCCESS;
}

/* Area / volume of the entity: OpenCASCADE's, or its bounding box's
 * (the dim largest extents multiplied). */
static double
entity_measure (int dim, int tag)
{
  double lo[3], hi[3], ext[3], m = 1;
  int ierr = 0;
  gmshModelOccGetMass (dim, tag, &m, &ierr);
  if (!ierr && m > 0 && isfinite (m))
    return m;
  ierr = 0;
  gmshModelGetBoundingBox (dim, tag, &lo[0], &lo[1], &lo[2], &hi[0],
                           &hi[1], &hi[2], &ierr);
  if (ierr)
    return 0;
  for (int k = 0; k < 3; k++)
    ext[k] = isfinite (hi[k] - lo[k]) && hi[k] > lo[k] ? hi[k] - lo[k] : 0;
  for (int i = 0; i < 3; i++)                  /* largest first */
    for (int j = i + 1; j < 3; j++)
      if (ext[j] > ext[i])
        {
          double t = ext[i];
          ext[i] = ext[j];
          ext[j] = t;
        }
  m = 1;
  for (int k = 0; k < dim; k++)
    m *= ext[k];
  return m;
}

/* Nodes of entity (dim, tag) by the rules of the header comment. */
static double
entity_nodes (const curve *cv, size_t ncv, const int *tags, size_t n,
              size_t nfaces, int dim, int tag, cells k)
{
  double lognodes = 0, logs = 0, logh = 0, s, f, m;
  size_t used = 0;
  for (size_t i = 0; i < n; i++)
    {
      curve key = { tags[i], 0, 0 };
      const curve *c = bsearch (&key, cv, ncv, sizeof *cv, by_tag);
      if (!c || c->seg < 1 || c->len <= 0)
        continue;
      lognodes += log (c->seg + 1);
      logs += log (c->seg);
      logh += log (c->len / c->seg);
      used++;
    }
  if (used == 0)
    return 0;
  if (k.quad ? dim == 3 || used >= 3
      : dim == 2 ? used == 4 : nfaces == 6 && used == 12)
    {
      s = exp (logs / (double) used);
      f = k.order < 2 ? pow (s + 1, dim)
          : !k.serendipity ? pow (2 * s + 1, dim)
          : dim == 2 ? (s + 1) * (3 * s + 1) : pow (s + 1, 2) * (4 * s + 1);
      return exp (lognodes * dim / (double) used) * f / pow (s + 1, dim);
    }
  m = entity_measure (dim, tag);
  f = k.order < 2 ? 1 : k.quad ? (k.serendipity ? 3 : 4) : pow (2, dim);
  return (dim == 3 ? 1.4 : k.quad ? 1 : 2 / sqrt (3)) * m
         / exp (logh / (double) used * dim) * f;
}

/* The cells of the scene (opts->element), else of the mesh options. */
static cells
cells_asked (const lac_mesh_opts *o)
{
  const lac_refelem *e = o->element >= 0 && o->element < LAC_NELEM_TYPES
                         ? lac_refelem_get ((lac_elem_type) o->element)
                         : NULL;
  cells k = { o->recombine, o->order == 2 ? 2 : 1, o->serendipity };
  if (e && e->dim >= 2)
    {
      k.quad = e->shape == LAC_SHAPE_QUAD || e->shape == LAC_SHAPE_HEX;
      k.order = e->order;
      k.serendipity = e->nnodes == 8 || e->nnodes == 20;
    }
  return k;
}

/* Nonzeros per row of K: the nodes a node shares a cell with, averaged
 * over the vertex, edge, face and centre nodes, times dim. */
static double
row_nonzeros (int dim, cells k)
{
  static const double r[2][2][3] = {     /* [3D][quad][1, 2, serendipity] */
    { { 14, 23, 23 }, { 18, 32, 31 } },
    { { 44, 90, 90 }, { 81, 192, 175 } } };
  return r[dim == 3][k.quad != 0][k.order < 2 ? 0 : k.serendipity ? 2 : 1];
}

/* What lac infsup holds besides K, chol being K's Cholesky term: the
 * Cholesky factor of its norm matrix A -- K's with --norm energy; the H1
 * Gram matrix has one block per component, whose factor measured 0.21
 * of K's estimate in 3D (hex8, 9e4 and 2.1e5 dofs) and 0.9 in 2D
 * (quad8, 2.8e5 dofs) -- and, on the dense path, two blocks of
 * LAC_INFSUP_BLOCK columns for A^-1 C; on the sparse path the LU factor
 * of the saddle-point matrix [A C; C^T 0], 2.5 times A's (measured 0.5 to
 * 0.6 of K's estimate in 3D with the H1 norm). */
static double
infsup_bytes (int solve, int dim, double n, double chol)
{
  int energy = solve == LAC_MESH_SOLVE_INFSUP_ENERGY
               || solve == LAC_MESH_SOLVE_INFSUP_ENERGY_SPARSE;
  int sparse = solve == LAC_MESH_SOLVE_INFSUP_SPARSE
               || solve == LAC_MESH_SOLVE_INFSUP_ENERGY_SPARSE;
  double a = (energy || dim == 2 ? 1 : 0.25) * chol;
  return sparse ? 3.5 * a : a + 2 * 8 * LAC_INFSUP_BLOCK * n;
}

/* lac_gmsh_run_bytes: see lac_mesh_gmsh_estimate.h. */
double
lac_gmsh_run_bytes (double nodes, int dim, const lac_mesh_opts *o)
{
  cells k = cells_asked (o);
  double n = dim * nodes, r = row_nonzeros (dim, k), factor;
  factor = dim == 2 ? 1.5e3 * n
           : 277 * (k.order == 2 ? 2 : 1) * pow (n, 4.0 / 3);
  switch (o->solve)
    {
    case LAC_MESH_SOLVE_LU:
      factor *= 2;
      break;
    case LAC_MESH_SOLVE_DENSE:
      factor = 8 * n * n;
      break;
    case LAC_MESH_SOLVE_ITERATIVE:
      factor = 36 * r * n + 200 * n;
      break;
    case LAC_MESH_SOLVE_INFSUP:
    case LAC_MESH_SOLVE_INFSUP_SPARSE:
    case LAC_MESH_SOLVE_INFSUP_ENERGY:
    case LAC_MESH_SOLVE_INFSUP_ENERGY_SPARSE:
      factor = infsup_bytes (o->solve, dim, n, factor);
      break;
    default:
      break;
    }
  return LAC_MESH_RUN_BYTES_MIN + 24 * r * n + factor;
}

/* The estimate on the 1D mesh made with size factor g (g <= 0: as the
 * options are): nodes, bytes, and the curves (*cv, owned by the caller,
 * sorted by tag). */
static int
estimate_at (lac_gmsh_reader *R, int dim, double g, curve **cv, size_t *ncv,
             double *nodes, double *bytes)
{
  int *dimtags = NULL, ierr = 0, status;
  size_t nd = 0;
  cells k = cells_asked (R->opts);
  *nodes = *bytes = 0;
  *cv = NULL;
  *ncv = 0;
  gmshModelMeshClear (NULL, 0, &ierr);
  if (!ierr && g > 0)
    gmshOptionSetNumber ("Mesh.MeshSizeFactor", g, &ierr);
  if (!ierr)
    gmshModelMeshGenerate (1, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "meshing the curves failed");
  if ((status = read_curves (R, cv, ncv)))
    return status;
  gmshModelGetEntities (&dimtags, &nd, dim, &ierr);
  if (ierr)
    status = lac_gmsh_fail (R, LAC_EDEP, "cannot get the entities");
  for (size_t e = 0; !status && e + 1 < nd; e += 2)
    {
      int *tags = NULL;
      size_t n = 0, nf = 0;
      if (!(status = entity_curves (R, dim, dimtags[e + 1], &tags, &n, &nf)))
        *nodes += entity_nodes (*cv, *ncv, tags, n, nf, dim, dimtags[e + 1],
                                k);
      gmshFree (tags);
    }
  gmshFree (dimtags);
  if (!status && *nodes > 0)
    *bytes = lac_gmsh_run_bytes (*nodes, dim, R->opts);
  return status;
}

/* A curve with fewer segments at a smaller size factor: gmsh's count of
 * the segments overflowed its int (a curve asked for more than 2^31
 * segments gets 1). */
static int
shrunk (const lac_gmsh_reader *R, const curve *prev, size_t np,
        const curve *cur, size_t nc, double gprev, double g)
{
  for (size_t i = 0, j = 0; i < nc && j < np; i++)
    {
      while (j < np && prev[j].tag < cur[i].tag)
        j++;
      if (j < np && prev[j].tag == cur[i].tag && cur[i].seg < prev[j].seg)
        return READ_ERR (LAC_EINVAL, "'%s': size = %g asks gmsh for more "
                         "segments on curve %d than its 32-bit counts hold "
                         "(%.0f at size %g, %.0f at size %g): the mesh would "
                         "be coarser, not finer", R->path, R->opts->size,
                         cur[i].tag, prev[j].seg, gprev, cur[i].seg, g);
    }
  return LAC_SUCCESS;
}

/* Has every curve the same segments in both meshes? */
static int
same_counts (const curve *a, size_t na, const curve *b, size_t nb)
{
  if (na != nb)
    return 0;
  for (size_t i = 0; i < na; i++)
    if (a[i].tag != b[i].tag || a[i].seg != b[i].seg)
      return 0;
  return 1;
}

/* lac_gmsh_estimate: see lac_mesh_gmsh_estimate.h. */
int
lac_gmsh_estimate (lac_gmsh_reader *R, int dim, double *nodes, double *bytes)
{
  curve *cv = NULL;
  size_t ncv = 0;
  int status = estimate_at (R, dim, 0, &cv, &ncv, nodes, bytes);
  lac_free (cv);
  return status;
}

/* The estimate at the size factor f = o->size < 1, reached in steps from
 * 1: each step halves the factor (by 16 when no curve changed: they are
 * transfinite or extruded), so that a 1D mesh is at most 16 times the
 * one before, whose estimate was within the limit; a step whose estimate
 * passes the limit stops (a smaller factor only makes more nodes: the
 * nodes and bytes are then lower bounds, *early = that factor).  gmsh meshed the
 * curves at f at once: a size of 1e-10 overflowed its counts (1 segment
 * a curve, fewer cells than at size 1) or took the memory of the 1D mesh. */
static int
estimate_steps (lac_gmsh_reader *R, int dim, double *nodes, double *bytes,
                double *early)
{
  const lac_mesh_opts *o = R->opts;
  curve *prev = NULL, *cur = NULL;
  size_t np = 0, nc = 0;
  double g = 1, gprev = 1;
  int status = LAC_SUCCESS, changed = 1;
  *early = 0;
  for (int step = 0; !status; step++)
    {
      status = estimate_at (R, dim, g, &cur, &nc, nodes, bytes);
      if (!status && step > 0)
        status = shrunk (R, prev, np, cur, nc, gprev, g);
      changed = step == 0 || !same_counts (prev, np, cur, nc);
      lac_free (prev);
      prev = cur, np = nc, cur = NULL;
      if (status || g <= o->size)
        break;
      if (o->max_memory > 0 && *bytes > o->max_memory)
        {
          *early = g;
          break;
        }
      gprev = g;
      g = fmax (o->size, g / (changed ? 2 : 16));
    }
  lac_free (prev);
  return status;
}

static const char *const solve_names[LAC_MESH_NSOLVES] = {
  "a sparse Cholesky factor", "a sparse LU factor", "a dense LU factor",
  "an iterative solve",
  "lac infsup's Cholesky factor of the H1 Gram matrix (its dense path)",
  "lac infsup's Cholesky factor of the H1 Gram matrix and LU factor of "
  "the saddle-point matrix (its sparse path)",
  "lac infsup's Cholesky factor of K (--norm energy, its dense path)",
  "lac infsup's Cholesky factor of K and LU factor of the saddle-point "
  "matrix (--norm energy, its sparse path)" };

/* lac_gmsh_solve_name: see lac_mesh_gmsh_estimate.h. */
const char *
lac_gmsh_solve_name (int solve)
{
  return solve_names[solve >= 0 && solve < LAC_MESH_NSOLVES ? solve : 0];
}

/* The estimate and its check against the limit, for R->opts->solve. */
static int
estimate_check (lac_gmsh_reader *R, int dim)
{
  const lac_mesh_opts *o = R->opts;
  double nodes, bytes, early = 0;
  char at[64] = "";
  int status = o->size > 0 && o->size < 1
               ? estimate_steps (R, dim, &nodes, &bytes, &early)
               : lac_gmsh_estimate (R, dim, &nodes, &bytes);
  if (status || o->max_memory <= 0 || bytes <= o->max_memory)
    return status;
  if (early > 0)
    snprintf (at, sizeof at, " already at size %g (more at %g)", early,
              o->size);
  return READ_ERR (LAC_EINVAL, "'%s': level = %d, size = %g: an estimated "
                   "%.2g nodes%s, which need about %.3g GB of memory with "
                   "%s, more than the limit of %.3g GB (--max-memory)",
                   R->path, o->level, o->size > 0 ? o->size : 1, nodes, at,
                   bytes / 1e9, lac_gmsh_solve_name (o->solve),
                   o->max_memory / 1e9);
}

/* lac_gmsh_estimate_check: see lac_mesh_gmsh_estimate.h. */
int
lac_gmsh_estimate_check (lac_gmsh_reader *R, int dim)
{
  const lac_mesh_opts *o = R->opts;
  lac_mesh_opts it;
  int status = estimate_check (R, dim);
  if (status != LAC_EINVAL || !o->else_iterative
      || o->solve == LAC_MESH_SOLVE_ITERATIVE)
    return status;
  it = *o;                      /* the factor does not fit: without one? */
  it.solve = LAC_MESH_SOLVE_ITERATIVE;
  lac_error_clear ();
  R->opts = &it;
  status = estimate_check (R, dim);
  R->opts = o;
  return status;
}
