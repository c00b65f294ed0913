/* t290: the answers of chapters/03-macromesh/exercises.md
 *                                          [LAC Hyp. 1, Remark 1, §4.4]
 *
 * Every number quoted in an answer is checked here against a closed form
 * computed in the test (integers exactly, reals to 1e-12):
 *   1. counts of a 4 x 4 x 4 box whose top is the slave surface, per
 *      family: hex8 +16 nodes / +64 cells, ...;
 *   2. a chain of 7 seg2: 3 macro-elements, the last one (x in [0, 3]) a
 *      triple; with unequal segments the designated node is next to the
 *      longer end segment [LAC Remark 1];
 *   3. the means of the interior basis functions of a six-hexahedra
 *      macro-element: hex20 corners -1/18, I-I midpoints 5/36 (designated),
 *      T-I midpoints 1/8; hex8 7/48;
 *   4. rounds: a hex8 cube with top and side slave faces needs 2, all six
 *      faces 2; a tet4 (Kuhn) cube top + xmax 1, top + xmin 2;
 *   5. the largest epsilon for which every fully covered macro-element is
 *      admissible is the smallest mean, 5/36 (hex20); moving a top vertex
 *      in its plane keeps the tri3-fan mean 1/3 but not the six-hex 7/48;
 *   6. the six-hexahedra cut with its inner square at +-a: the hex8 mean
 *      is (a^2 + a + 1)/12, 7/48 for lac's a = 1/2, 13/108 for code_aster's
 *      a = 1/3;
 *   7. the cone rule: a cell with F faces cut on one face becomes F - 1
 *      cells, with one new node, and the face as many triangles as it has
 *      vertices, of mean 1/3 (tet4, hex8, pyr5; a prism would follow).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

#define TOL 1e-12

static lac_mesh *
box (lac_elem_type t, size_t n0, size_t n1, size_t n2)
{
  size_t n[3] = { n0, n1, n2 };
  double L[3] = { (double) n0, (double) n1, (double) n2 };
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (t, n, L, 0.0, &m), LAC_SUCCESS, "box %s",
                lac_refelem_get (t)->name);
  return m;
}

/* Group `name` = the union of the facet groups a and b. */
static void
union_group (lac_mesh *m, const char *name, const char *a, const char *b)
{
  const lac_group *A = lac_mesh_group (m, a), *B = lac_mesh_group (m, b);
  size_t n = A->n + B->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      cell[e] = e < A->n ? A->cell[e] : B->cell[e - A->n];
      face[e] = e < A->n ? A->face[e] : B->face[e - A->n];
    }
  lac_mesh_add_group (m, name, A->dim, 0, n, cell, face);
  free (cell);
  free (face);
}

/* One cell of type t on its reference nodes, facet group "s" = face f. */
static lac_mesh *
one_cell (lac_elem_type t, int f)
{
  const lac_refelem *re = lac_refelem_get (t);
  lac_mesh *m = lac_mesh_alloc (re->dim, (size_t) re->nnodes, 1,
                                (size_t) re->nnodes);
  size_t cell = 0;
  for (int a = 0; a < re->nnodes; a++)
    {
      for (int i = 0; i < re->dim; i++)
        m->x[a * re->dim + i] = re->xi[a * re->dim + i];
      m->conn[a] = a;
    }
  m->type[0] = t;
  m->ptr[1] = (size_t) re->nnodes;
  lac_mesh_add_group (m, "s", re->dim - 1, 0, 1, &cell, &f);
  return m;
}

/* int_{T^k} phi_i, from the face maps of the sub-facets (quadrature of
 * degree 6: exact on flat faces). */
static double
node_integral (const lac_mesh *m, const lac_macro *M, size_t k, size_t i)
{
  double s = 0;
  for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
    {
      int fn[LAC_MAX_FACE_NODES];
      lac_elem_type ft;
      int nf = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], fn, &ft);
      const lac_refelem *rf = lac_refelem_get (ft);
      double xe[LAC_MAX_FACE_NODES * 3];
      int slot = -1;
      for (int a = 0; a < nf; a++)
        {
          if ((size_t) fn[a] == i)
            slot = a;
          for (int d = 0; d < m->dim; d++)
            xe[a * m->dim + d] = m->x[(size_t) fn[a] * (size_t) m->dim
                                      + (size_t) d];
        }
      if (slot < 0)
        continue;
      lac_quad *q = lac_quad_alloc (rf->shape, 6);
      for (int p = 0; p < q->n; p++)
        {
          lac_map mp;
          lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
          s += q->w[p] * mp.N[slot] * mp.detJ;
        }
      lac_quad_free (q);
    }
  return s;
}

/* Exercise 1: counts of an n x n x n box, top slave.  Per top face of the
 * grid (n^2 of them), the template adds dn nodes and dc cells; simplices:
 * 2 Kuhn triangles per top square. */
static void
exercise1 (void)
{
  const size_t n = 4, q = n * n;
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 };
  struct
  {
    lac_elem_type t;
    const lac_macro_opts *o;
    size_t per_square;   /* slave facets per top square             */
    size_t dn, dc;       /* new nodes, new cells per slave facet     */
    size_t nsub;         /* sub-facets per macro-element             */
  } c[] = {
    { LAC_HEX8, NULL, 1, 1, 4, 4 },  { LAC_HEX8, &six, 1, 8, 5, 5 },
    { LAC_TET4, NULL, 2, 1, 2, 3 },  { LAC_TET10, NULL, 2, 5, 2, 3 },
    { LAC_HEX20, NULL, 1, 28, 5, 5 }, { LAC_HEX27, NULL, 1, 0, 0, 1 },
  };
  for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
    {
      lac_mesh *m = box (c[i].t, n, n, n);
      lac_macro *M = NULL;
      char what[32];
      size_t nn0 = m->nnodes, nc0 = m->ncells, nf = c[i].per_square * q;
      int status;
      snprintf (what, sizeof what, "ex1 %s%s", lac_refelem_get (c[i].t)->name,
                c[i].o ? " six" : "");
      status = lac_macromesh_build (&m, "zmax", c[i].o, &M);
      check_status (status, LAC_SUCCESS, "%s: build", what);
      if (status)
        {
          lac_mesh_free (m);
          continue;
        }
      check_int ((long) (m->nnodes - nn0), (long) (nf * c[i].dn),
                 "%s: new nodes", what);
      check_int ((long) (m->ncells - nc0), (long) (nf * c[i].dc),
                 "%s: new cells", what);
      check_int ((long) M->n, (long) nf, "%s: macro-elements", what);
      check_int ((long) M->ptr[M->n], (long) (nf * c[i].nsub),
                 "%s: sub-facets", what);
      check_int (M->nrounds, c[i].dn ? 1 : 0, "%s: rounds", what);
      lac_macromesh_free (M);
      lac_mesh_free (m);
    }
  /* the quoted answer itself: hex8, +16 nodes, +64 cells */
  {
    lac_mesh *m = box (LAC_HEX8, 4, 4, 4);
    lac_macro *M = NULL;
    check_status (lac_macromesh_build (&m, "zmax", NULL, &M), LAC_SUCCESS,
                  "ex1 hex8 4x4x4");
    check_int ((long) m->nnodes, 125 + 16, "ex1 hex8 4x4x4: nodes");
    check_int ((long) m->ncells, 64 + 64, "ex1 hex8 4x4x4: cells");
    lac_macromesh_free (M);
    lac_mesh_free (m);
  }
}

/* x-range of macro-element k of a 2D mesh. */
static void
xrange (const lac_mesh *m, const lac_macro *M, size_t k, double *x0,
        double *x1)
{
  *x0 = INFINITY;
  *x1 = -INFINITY;
  for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
    {
      int fn[LAC_MAX_FACE_NODES];
      int nf = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], fn, NULL);
      for (int a = 0; a < nf; a++)
        {
          *x0 = fmin (*x0, m->x[2 * (size_t) fn[a]]);
          *x1 = fmax (*x1, m->x[2 * (size_t) fn[a]]);
        }
    }
}

/* Exercise 2: a chain of k = 7 seg2 -> floor(k/2) = 3 macro-elements, the
 * last of the chain a triple; then unequal segments. */
static void
exercise2 (void)
{
  const size_t k = 7;
  lac_mesh *m = box (LAC_QUAD4, k, 1, 0);
  lac_macro *M = NULL;
  check_status (lac_macromesh_build (&m, "ymax", NULL, &M), LAC_SUCCESS,
                "ex2 chain of 7");
  if (M)
    {
      size_t triples = 0, nsub = 0;
      check_int ((long) M->n, (long) (k / 2), "ex2: macro-elements");
      check_int (M->nrounds, 0, "ex2: nothing refined");
      for (size_t j = 0; j < M->n; j++)
        {
          size_t s = M->ptr[j + 1] - M->ptr[j], in[8];
          double x0, x1;
          nsub += s;
          triples += s == 3;
          xrange (m, M, j, &x0, &x1);
          check_int ((long) s, j + 1 == M->n ? 3 : 2, "ex2: T^%zu size", j);
          check_int ((long) lac_macromesh_interior (m, M, j, in, 8),
                     (long) s - 1, "ex2: T^%zu interior nodes", j);
          check_rel (M->phi[j] / M->meas[j], 1.0 / (double) s, TOL,
                     "ex2: T^%zu mean 1/%zu", j, s);
          if (s == 3)
            {
              check_abs (x0, 0, TOL, "ex2: triple starts at x = 0");
              check_abs (x1, 3, TOL, "ex2: triple ends at x = 3");
              check_abs (m->x[2 * M->inode[j]], 1, TOL,
                         "ex2: designated node of the triple at x = 1");
            }
          else
            check_abs (x1 - x0, 2, TOL, "ex2: pair of length 2");
        }
      check_int ((long) triples, (long) (k % 2), "ex2: triples");
      check_int ((long) nsub, (long) k, "ex2: all segments used");
      check_abs (m->x[2 * M->inode[0]], 6, TOL, "ex2: T^0 = [5, 7], node 6");
    }
  lac_macromesh_free (M);
  lac_mesh_free (m);

  /* Unequal segments: the top of 3 quad4 with vertices at x = 0, a, b, 3.
   * The two interior nodes have int phi = (L1 + L2)/2 and (L2 + L3)/2; the
   * larger wins [LAC Remark 1]. */
  {
    const double a = 0.8, b = 1.9;
    const double L1 = a, L2 = b - a, L3 = 3 - b;
    const double i1 = (L1 + L2) / 2, i2 = (L2 + L3) / 2;
    const lac_group *G;
    m = box (LAC_QUAD4, 3, 1, 0);
    G = lac_mesh_group (m, "ymax");
    for (size_t q = 0; q < G->nnodes; q++)
      {
        double *x = &m->x[2 * G->node[q]];
        if (fabs (x[0] - 1) < TOL)
          x[0] = a;
        else if (fabs (x[0] - 2) < TOL)
          x[0] = b;
      }
    M = NULL;
    check_status (lac_macromesh_build (&m, "ymax", NULL, &M), LAC_SUCCESS,
                  "ex2 unequal");
    if (M)
      {
        check_int ((long) M->n, 1, "ex2 unequal: one triple");
        check_abs (m->x[2 * M->inode[0]], i2 > i1 ? b : a, TOL,
                   "ex2 unequal: designated node at x = %g", b);
        check_rel (M->phi[0], fmax (i1, i2), TOL, "ex2 unequal: int phi");
        check_rel (M->phi[0] / M->meas[0], fmax (i1, i2) / 3, TOL,
                   "ex2 unequal: mean 1.1/3");
        check_rel (fmax (i1, i2) / 3, 1.1 / 3, TOL, "ex2: quoted value");
      }
    lac_macromesh_free (M);
    lac_mesh_free (m);
  }
}

/* Exercise 3: the six-hexahedra face.  On the reference face [-1,1]^2
 * (area 4) the central square [-1/2,1/2]^2 has det = 1/4, a trapezoid
 * (T0 T1 I1 I0) x = s (3 - t)/4, y = (t - 3)/4 has det = (3 - t)/16.  With
 * the 1D moments of (3 - t)/16 against 1, 1 + t, 1 - t^2, ...: */
static void
exercise3 (void)
{
  /* central square: int N = (1/4) int_{[-1,1]^2} N; quad8 corner mean
   * -1/12, mid-edge 1/3; quad4 1/4 (of the reference area 4) */
  const double sq_corner = -1.0 / 12, sq_mid = 1.0 / 3, sq_q4 = 1.0 / 4;
  /* trapezoid integrals, products of 1D moments: int_{-1}^{1} (1+t)(3-t)
   * dt = 16/3, int (1-t^2)(3-t) dt = 4, int (t^2-1)(3-t) dt = -4,
   * int (1-s^2)/2 ds = 2/3, int (1-s) ds = 2, int s(1-s) ds = -2/3 */
  const double tr_mid_top = (2.0 / 3) * (16.0 / 3) / 16;           /* 2/9 */
  const double tr_mid_side = (2.0 / 2) * 4.0 / 16;                 /* 1/4 */
  const double tr_q4_top = (2.0 / 4) * (16.0 / 3) / 16;            /* 1/6 */
  /* quad8 corner I0 = (s,t) = (-1,1): (1/4)(1-s)(1+t)(t-s-1), times det:
   * (1/64) [2 (-4) - (-2/3)(16/3)] = -5/72 */
  const double tr_corner_top = (2.0 * (-4.0) - (-2.0 / 3) * (16.0 / 3)) / 64;
  const double mean_corner = (sq_corner + 2 * tr_corner_top) / 4;
  const double mean_ii = (sq_mid + tr_mid_top) / 4;
  const double mean_ti = 2 * tr_mid_side / 4;
  const double mean_hex8 = (sq_q4 + 2 * tr_q4_top) / 4;

  check_rel (mean_ii, 5.0 / 36, TOL, "ex3: closed form 5/36");
  check_rel (mean_ti, 1.0 / 8, TOL, "ex3: closed form 1/8");
  check_rel (mean_corner, -1.0 / 18, TOL, "ex3: closed form -1/18");
  check_rel (mean_hex8, 7.0 / 48, TOL, "ex3: closed form 7/48");

  for (int hex20 = 0; hex20 < 2; hex20++)
    {
      lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 };
      lac_mesh *m = box (hex20 ? LAC_HEX20 : LAC_HEX8, 2, 2, 1);
      lac_macro *M = NULL;
      const char *name = hex20 ? "hex20" : "hex8 six";
      check_status (lac_macromesh_build (&m, "zmax", &six, &M), LAC_SUCCESS,
                    "ex3 %s", name);
      if (!M)
        {
          lac_mesh_free (m);
          continue;
        }
      for (size_t k = 0; k < M->n; k++)
        {
          size_t in[32], ni = lac_macromesh_interior (m, M, k, in, 32);
          size_t ncorner = 0, nii = 0, nti = 0;
          double A = M->meas[k];
          check_rel (A, 1, TOL, "ex3 %s T^%zu: |T^m| = 1", name, k);
          check_rel (M->phi[k] / A, hex20 ? mean_ii : mean_hex8, TOL,
                     "ex3 %s T^%zu: phi/meas", name, k);
          check_int ((long) ni, hex20 ? 12 : 4, "ex3 %s: interior nodes",
                     name);
          for (size_t q = 0; q < ni; q++)
            {
              double mean = node_integral (m, M, k, in[q]) / A;
              if (fabs (mean - mean_corner) < TOL && hex20)
                ncorner++;
              else if (fabs (mean - (hex20 ? mean_ii : mean_hex8)) < TOL)
                nii++;
              else if (fabs (mean - mean_ti) < TOL && hex20)
                nti++;
            }
          check_int ((long) (hex20 ? ncorner : nii), 4,
                     "ex3 %s T^%zu: 4 corners of the central square", name,
                     k);
          if (hex20)
            {
              check_int ((long) nii, 4, "ex3 hex20 T^%zu: 4 I-I midpoints",
                         k);
              check_int ((long) nti, 4, "ex3 hex20 T^%zu: 4 T-I midpoints",
                         k);
            }
        }
      lac_macromesh_free (M);
      lac_mesh_free (m);
    }
}

/* Exercise 4: rounds.  With LAC_DOC_TABLE=ex4 the answer's table, a row
 * per case: cell, slave faces, rounds, new nodes, cells. */
static void
table_row (const char *cell, const char *faces, const lac_macro *M,
           long dn, long ncells)
{
  if (check_doc_table ("ex4"))
    printf ("| %s | %s | %d | %ld | %ld |\n", cell, faces, M->nrounds, dn,
            ncells);
}

static void
rounds_case (lac_elem_type t, const char *a, const char *b,
             const lac_macro_opts *o, int rounds, long dn, long ncells,
             const char *what, const char *cell, const char *faces)
{
  lac_mesh *m = box (t, 1, 1, 1);
  lac_macro *M = NULL;
  size_t nn0 = m->nnodes;
  double vol0 = lac_mesh_measure (m);
  if (b)
    union_group (m, "u", a, b);
  check_status (lac_macromesh_build (&m, b ? "u" : a, o, &M), LAC_SUCCESS,
                "ex4 %s", what);
  if (M)
    {
      check_int (M->nrounds, rounds, "ex4 %s: rounds", what);
      check_int ((long) (m->nnodes - nn0), dn, "ex4 %s: new nodes", what);
      check_int ((long) m->ncells, ncells, "ex4 %s: cells", what);
      check_rel (lac_mesh_measure (m), vol0, TOL, "ex4 %s: volume", what);
      table_row (cell, faces, M, (long) (m->nnodes - nn0), (long) m->ncells);
    }
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

static void
exercise4 (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 };
  if (check_doc_table ("ex4"))
    printf ("| cell | slave faces | rounds | new nodes | cells |\n"
            "|---|---|---|---|---|\n");
  /* hex8: 5 pyramids (+1 node), then the pyramid on the side cut on its
   * base into 4 tets (+1 node): 5 - 1 + 4 = 8 cells */
  rounds_case (LAC_HEX8, "zmax", "xmax", NULL, 2, 2, 5 - 1 + 4,
               "hex8 top+side", "hex8", "top + xmax");
  /* six hexahedra: 6 - 1 + 6 = 11 cells, 8 + 8 nodes */
  rounds_case (LAC_HEX8, "zmax", "xmax", &six, 2, 16, 6 - 1 + 6,
               "hex8 six top+side", "hex8 six", "top + xmax");
  rounds_case (LAC_HEX20, "zmax", "xmax", NULL, 2, 56, 6 - 1 + 6,
               "hex20 top+side", "hex20", "top + xmax");
  /* Kuhn tets 0, e_a, e_a+e_b, 1 (x_a >= x_b >= x_c): boundary faces
   * x_a = 1 and x_c = 0 only.  top (z = 1) and xmax (x = 1) are never in
   * the same tet: 1 round, 4 facets, +4 nodes, 6 + 4*2 cells; top and
   * xmin (x = 0): the tet z >= y >= x owns both: 2 rounds. */
  rounds_case (LAC_TET4, "zmax", "xmax", NULL, 1, 4, 6 + 4 * 2,
               "tet4 top+xmax", "tet4", "top + xmax");
  rounds_case (LAC_TET4, "zmax", "xmin", NULL, 2, 4, 6 + 4 * 2,
               "tet4 top+xmin", "tet4", "top + xmin");
  /* all six faces of one hex8: round 1 gives 5 pyramids, each other face
   * the base of one of them; round 2 cuts all five: 5 * 4 cells. */
  {
    lac_mesh *m = box (LAC_HEX8, 1, 1, 1);
    size_t cell[6] = { 0, 0, 0, 0, 0, 0 };
    int face[6] = { 0, 1, 2, 3, 4, 5 };
    lac_macro *M = NULL;
    lac_mesh_add_group (m, "all", 2, 0, 6, cell, face);
    check_status (lac_macromesh_build (&m, "all", NULL, &M), LAC_SUCCESS,
                  "ex4 hex8 all faces");
    if (M)
      {
        check_int (M->nrounds, 2, "ex4 hex8 all faces: rounds");
        check_int ((long) m->nnodes, 8 + 6, "ex4 hex8 all faces: nodes");
        check_int ((long) m->ncells, 5 * 4, "ex4 hex8 all faces: cells");
        table_row ("hex8", "all six", M, (long) m->nnodes - 8, (long) m->ncells);
      }
    lac_macromesh_free (M);
    lac_mesh_free (m);
  }
}

/* Exercise 6: the six-hexahedra cut with the inner square at +-a (I and
 * M): mean of the I-node function on a hex8 face, (a^2 + a + 1)/12.
 * Checked against the library at a = 1/2 (above, 7/48) and here against
 * a 3 x 3 Gauss rule on the pieces for a = 1/3 and a = 1/2. */
static double
six_mean_gauss (double a)
{
  /* reference face [-1,1]^2; I0 = (-a,-a); its bilinear function on the
   * central square [-a,a]^2 and on the two trapezoids that touch it
   * (bottom: T0 T1 I1 I0, left: T3 T0 I0 I3, mirror images of each
   * other: twice the bottom one) */
  static const double g[3] = { -0.7745966692414834, 0, 0.7745966692414834 };
  static const double w[3] = { 5.0 / 9, 8.0 / 9, 5.0 / 9 };
  const double X[4][2] = { { -1, -1 }, { 1, -1 }, { a, -a }, { -a, -a } };
  double trap = 0, square = a * a;    /* int = (1/4) |square| = a^2 */
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      {
        double s = g[i], t = g[j], dx[2][2] = { { 0, 0 }, { 0, 0 } };
        static const double cs[4] = { -1, 1, 1, -1 }, ct[4] = { -1, -1, 1, 1 };
        for (int v = 0; v < 4; v++)
          for (int k = 0; k < 2; k++)
            {
              dx[k][0] += X[v][k] * cs[v] * (1 + ct[v] * t) / 4;
              dx[k][1] += X[v][k] * ct[v] * (1 + cs[v] * s) / 4;
            }
        double det = dx[0][0] * dx[1][1] - dx[0][1] * dx[1][0];
        double N = (1 - s) * (1 + t) / 4;          /* vertex 3 = I0 */
        trap += w[i] * w[j] * N * det;
      }
  return (square + 2 * trap) / 4;
}

static void
exercise6 (void)
{
  const double a[2] = { 1.0 / 3, 1.0 / 2 };
  for (int i = 0; i < 2; i++)
    check_rel (six_mean_gauss (a[i]), (a[i] * a[i] + a[i] + 1) / 12, TOL,
               "ex6: mean(a = %g) = (a^2 + a + 1)/12", a[i]);
  check_rel ((a[0] * a[0] + a[0] + 1) / 12, 13.0 / 108, TOL,
             "ex6: code_aster's a = 1/3 gives 13/108");
  check_rel ((a[1] * a[1] + a[1] + 1) / 12, 7.0 / 48, TOL,
             "ex6: lac's a = 1/2 gives 7/48");
  check_true (13.0 / 108 < 7.0 / 48, "ex6: 13/108 < 7/48");
}

/* Exercise 7: the cone rule on one cell, every face. */
static void
exercise7 (void)
{
  const lac_elem_type t[3] = { LAC_TET4, LAC_HEX8, LAC_PYR5 };
  for (int i = 0; i < 3; i++)
    {
      const lac_refelem *re = lac_refelem_get (t[i]);
      for (int f = 0; f < re->nfaces; f++)
        {
          lac_mesh *m = one_cell (t[i], f);
          lac_macro *M = NULL;
          int nv = lac_refelem_get (re->face_type[f])->nvertices;
          check_status (lac_macromesh_build (&m, "s", NULL, &M), LAC_SUCCESS,
                        "ex7 %s face %d", re->name, f);
          if (M)
            {
              check_int ((long) m->ncells, re->nfaces - 1,
                         "ex7 %s face %d: F - 1 cells", re->name, f);
              check_int ((long) m->nnodes, re->nnodes + 1,
                         "ex7 %s face %d: one new node", re->name, f);
              check_int ((long) (M->ptr[1] - M->ptr[0]), nv,
                         "ex7 %s face %d: sub-facets", re->name, f);
              check_rel (M->phi[0] / M->meas[0], 1.0 / 3, TOL,
                         "ex7 %s face %d: mean 1/3", re->name, f);
            }
          lac_macromesh_free (M);
          lac_mesh_free (m);
        }
    }
}

/* Exercise 5: the upper bound of epsilon, and a top vertex moved in its
 * plane. */
static void
exercise5 (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 };
  struct
  {
    lac_elem_type t;
    const lac_macro_opts *o;
    double mean;
  } c[] = {
    { LAC_TET4, NULL, 1.0 / 3 },   { LAC_HEX8, NULL, 1.0 / 3 },
    { LAC_TET10, NULL, 2.0 / 9 },  { LAC_HEX20, NULL, 5.0 / 36 },
    { LAC_HEX27, NULL, 4.0 / 9 },  { LAC_HEX8, &six, 7.0 / 48 },
    { LAC_QUAD4, NULL, 1.0 / 2 },  { LAC_QUAD8, NULL, 2.0 / 3 },
  };
  double lo = INFINITY, lo_default = INFINITY;
  for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
    {
      int d3 = lac_refelem_get (c[i].t)->dim == 3;
      lac_mesh *m = d3 ? box (c[i].t, 2, 2, 1) : box (c[i].t, 4, 1, 0);
      lac_macro *M = NULL;
      check_status (lac_macromesh_build (&m, d3 ? "zmax" : "ymax", c[i].o,
                                         &M), LAC_SUCCESS, "ex5 build");
      if (M)
        for (size_t k = 0; k < M->n; k++)
          {
            double mean = M->phi[k] / M->meas[k];
            check_rel (mean, c[i].mean, TOL, "ex5 %s: mean",
                       lac_refelem_get (c[i].t)->name);
            lo = fmin (lo, mean);
            if (!c[i].o)
              lo_default = fmin (lo_default, mean);
          }
      lac_macromesh_free (M);
      lac_mesh_free (m);
    }
  check_rel (lo_default, 5.0 / 36, TOL, "ex5: default cuts: min 5/36");
  check_rel (lo, 5.0 / 36, TOL, "ex5: all cuts: min 5/36 (hex20)");
  check_true (7.0 / 48 > 5.0 / 36, "ex5: 7/48 > 5/36");

  /* the centre vertex (1, 1, 1) of the top of a 2 x 2 x 1 hex8 box moved
   * to (1.2, 0.9, 1): tri3 fans keep 1/3, the six-hex cut loses 7/48 */
  for (int s = 0; s < 2; s++)
    {
      lac_mesh *m = box (LAC_HEX8, 2, 2, 1);
      lac_macro *M = NULL;
      for (size_t a = 0; a < m->nnodes; a++)
        {
          double *x = &m->x[3 * a];
          if (fabs (x[0] - 1) < TOL && fabs (x[1] - 1) < TOL
              && fabs (x[2] - 1) < TOL)
            x[0] = 1.2, x[1] = 0.9;
        }
      check_status (lac_macromesh_build (&m, "zmax", s ? &six : NULL, &M),
                    LAC_SUCCESS, "ex5 moved vertex");
      if (M)
        for (size_t k = 0; k < M->n; k++)
          {
            double mean = M->phi[k] / M->meas[k];
            if (s)
              check_true (fabs (mean - 7.0 / 48) > 1e-3 && mean > 0.1525
                          && mean < 0.1551, "ex5 moved, six T^%zu: mean "
                          "%.6f != 7/48, in [0.1525, 0.1551]", k, mean);
            else
              check_rel (mean, 1.0 / 3, TOL, "ex5 moved, pyramids T^%zu",
                         k);
          }
      lac_macromesh_free (M);
      lac_mesh_free (m);
    }
}

int
main (void)
{
  lac_init ();
  exercise1 ();
  exercise2 ();
  exercise3 ();
  exercise4 ();
  exercise5 ();
  exercise6 ();
  exercise7 ();
  lac_finalize ();
  return check_summary ();
}
