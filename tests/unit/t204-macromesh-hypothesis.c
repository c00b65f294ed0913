/* t204: every macro-element satisfies Hypothesis 1  [LAC Hyp. 1, Remark 1]
 *
 *   - T^m has interior nodes, and the designated one, inode[m], is one of
 *     them; the sub-facets of the (new) slave group that contain inode[m]
 *     all belong to T^m: supp(phi_inode) is inside T^m;
 *   - inode[m] has the largest int_{T^m} phi of the interior nodes, and
 *     phi[m] is that integral (recomputed here from the face maps);
 *   - the sub-facets of all T^m are exactly the slave group, each once, and
 *     sum |T^m| = |original slave group| (1e-13);
 *   - the mean phi/|T^m| takes its textbook value where the geometry makes
 *     it exact: seg2 pair 1/2, seg3 2/3, tri3 fan 1/3 [LAC Def. 1], tri6
 *     split at the centroid 2/9 (a tri6 vertex function has zero mean, so
 *     the centroid is never chosen), quad9 centre 4/9, six-hex cut 7/48
 *     (hex8) and 5/36 (hex20) (rectangular faces);
 *   - 2D gathering: chains of odd length (3, 5, closed loops of 3 and 5
 *     segments gathered across their corners) give floor(k/2)
 *     macro-elements.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "fem/lac_quadrature.h"
#include "base/lac_status.h"

/* int_facet 1 and int_facet N_a for the facet's nodes. */
static double
facet_integrals (const lac_mesh *m, size_t c, int f, int *nodes, int *nn,
                 double *intN)
{
  lac_elem_type ft;
  const lac_refelem *rf;
  lac_quad *q;
  double xe[LAC_MAX_FACE_NODES * 3], area = 0;
  *nn = lac_mesh_facet_nodes (m, c, f, nodes, &ft);
  rf = lac_refelem_get (ft);
  q = lac_quad_alloc (rf->shape, 6);
  for (int a = 0; a < *nn; a++)
    {
      intN[a] = 0;
      for (int d = 0; d < m->dim; d++)
        xe[a * m->dim + d] = m->x[(size_t) nodes[a] * m->dim + d];
    }
  for (int p = 0; p < q->n; p++)
    {
      lac_map mp;
      lac_map_face (rf, m->dim, xe, q->xi + p * q->dim, &mp);
      area += q->w[p] * mp.detJ;
      for (int a = 0; a < *nn; a++)
        intN[a] += q->w[p] * mp.N[a] * mp.detJ;
    }
  lac_quad_free (q);
  return area;
}

static double
group_area (const lac_mesh *m, const char *name)
{
  const lac_group *G = lac_mesh_group (m, name);
  double area = 0, intN[LAC_MAX_FACE_NODES];
  int nodes[LAC_MAX_FACE_NODES], nn;
  for (size_t e = 0; e < G->n; e++)
    area += facet_integrals (m, G->cell[e], G->face[e], nodes, &nn, intN);
  return area;
}

typedef struct pair
{
  size_t c;
  int f;
} pair;

static int
cmp_pair (const void *a, const void *b)
{
  const pair *p = a, *q = b;
  if (p->c != q->c)
    return p->c < q->c ? -1 : 1;
  return p->f - q->f;
}

/* int_{T^m} phi_i for node i. */
static double
macro_phi (const lac_mesh *m, const lac_macro *M, size_t k, size_t i)
{
  double s = 0, intN[LAC_MAX_FACE_NODES];
  int nodes[LAC_MAX_FACE_NODES], nn;
  for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
    {
      facet_integrals (m, M->cell[j], M->face[j], nodes, &nn, intN);
      for (int a = 0; a < nn; a++)
        if ((size_t) nodes[a] == i)
          s += intN[a];
    }
  return s;
}

/* All checks on one built macro-mesh.  mean < 0: do not check the mean. */
static void
check_macros (const lac_mesh *m, const lac_macro *M, const char *slave,
              double area0, double mean, const char *what)
{
  const lac_group *G = lac_mesh_group (m, slave);
  size_t nsub = M->ptr[M->n], bad_support = 0, bad_inode = 0, bad_best = 0;
  size_t *macro_of = malloc (G->n * sizeof *macro_of);
  pair *a = malloc (nsub * sizeof *a), *b = malloc (G->n * sizeof *b);
  double sum = 0, phierr = 0, meanerr = 0;

  /* The sub-facets are the slave group, each once. */
  check_int ((long) nsub, (long) G->n, "%s: sub-facets = slave facets", what);
  for (size_t j = 0; j < nsub; j++)
    a[j] = (pair) { M->cell[j], M->face[j] };
  for (size_t e = 0; e < G->n; e++)
    b[e] = (pair) { G->cell[e], G->face[e] };
  qsort (a, nsub, sizeof *a, cmp_pair);
  qsort (b, G->n, sizeof *b, cmp_pair);
  {
    int same = nsub == G->n;
    for (size_t j = 0; same && j < nsub; j++)
      same = cmp_pair (&a[j], &b[j]) == 0
             && (j == 0 || cmp_pair (&a[j - 1], &a[j]) != 0);
    check_true (same, "%s: same facet sets, each once", what);
  }
  for (size_t e = 0; e < G->n; e++)
    {
      macro_of[e] = SIZE_MAX;
      for (size_t k = 0; k < M->n; k++)
        for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
          if (M->cell[j] == G->cell[e] && M->face[j] == G->face[e])
            macro_of[e] = k;
    }

  for (size_t k = 0; k < M->n; k++)
    {
      size_t inter[64], ni = lac_macromesh_interior (m, M, k, inter, 64);
      int is_inter = 0;
      double best = -INFINITY;
      sum += M->meas[k];
      for (size_t i = 0; i < ni; i++)
        {
          double p = macro_phi (m, M, k, inter[i]);
          is_inter |= inter[i] == M->inode[k];
          if (p > best)
            best = p;
        }
      if (!is_inter)
        bad_inode++;
      /* support of phi_inode on the slave group: inside T^m */
      for (size_t e = 0; e < G->n; e++)
        {
          int nodes[LAC_MAX_FACE_NODES];
          int nn = lac_mesh_facet_nodes (m, G->cell[e], G->face[e], nodes,
                                         NULL);
          for (int q = 0; q < nn; q++)
            if ((size_t) nodes[q] == M->inode[k] && macro_of[e] != k)
              bad_support++;
        }
      {
        double p = macro_phi (m, M, k, M->inode[k]);
        phierr = fmax (phierr, fabs (p - M->phi[k]));
        if (p < best - 1e-12 * fabs (best))
          bad_best++;
        if (mean >= 0)
          meanerr = fmax (meanerr, fabs (M->phi[k] / M->meas[k] - mean));
      }
    }
  check_int ((long) bad_inode, 0, "%s: inode is an interior node", what);
  check_int ((long) bad_support, 0, "%s: supp phi_inode inside T^m", what);
  check_int ((long) bad_best, 0, "%s: inode has the largest integral", what);
  check_abs (phierr, 0, 1e-13, "%s: phi[m] = int phi_inode", what);
  check_rel (sum, area0, 1e-13, "%s: sum |T^m| = |slave group|", what);
  if (mean >= 0)
    check_abs (meanerr, 0, 1e-13, "%s: mean of phi_inode = %g", what, mean);
  free (macro_of);
  free (a);
  free (b);
}

static void
union_group (lac_mesh *m, const char *a, const char *b)
{
  const lac_group *A = lac_mesh_group (m, a), *B = lac_mesh_group (m, b);
  size_t n = A->n + B->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      cell[e] = e < A->n ? A->cell[e] : B->cell[e - A->n];
      face[e] = e < A->n ? A->face[e] : B->face[e - A->n];
    }
  lac_mesh_add_group (m, "u", A->dim, 0, n, cell, face);
  free (cell);
  free (face);
}

static void
build_and_check (lac_mesh *m, const char *slave, const lac_macro_opts *opts,
                 double mean, long nmacro, const char *what)
{
  lac_macro *M = NULL;
  double area0 = group_area (m, slave);
  int status = lac_macromesh_build (&m, slave, opts, &M);
  check_status (status, LAC_SUCCESS, "%s: build", what);
  if (!status)
    {
      if (nmacro >= 0)
        check_int ((long) M->n, nmacro, "%s: macro-elements", what);
      check_macros (m, M, slave, area0, mean, what);
    }
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

static void
run_box (lac_elem_type t, int two, const lac_macro_opts *opts, double mean,
         const char *label)
{
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 3, 2, 2 };
  double L[3] = { 1, 1.5, 2 };
  const char *slave = re->dim == 3 ? "zmax" : "ymax";
  lac_mesh *m = NULL;
  char what[96];
  snprintf (what, sizeof what, "%s %s%s", re->name, label,
            two ? " 2 faces" : "");
  check_status (lac_mesh_box (t, n, L, 0.2, &m), LAC_SUCCESS, "%s: box",
                what);
  if (two)
    {
      union_group (m, slave, "xmax");
      slave = "u";
    }
  build_and_check (m, slave, opts, mean, -1, what);
}

/* A fan of k tri3 around the origin: its boundary is a closed loop of k
 * segments (face 1 of each triangle), group "rim". */
static lac_mesh *
fan (int k)
{
  lac_mesh *m = lac_mesh_alloc (2, (size_t) k + 1, (size_t) k,
                                3 * (size_t) k);
  size_t cell[16];
  int face[16];
  m->x[0] = m->x[1] = 0;
  for (int i = 0; i < k; i++)
    {
      double th = 2 * acos (-1.0) * i / k, r = 1 + 0.1 * i;
      m->x[2 * (i + 1)] = r * cos (th);
      m->x[2 * (i + 1) + 1] = r * sin (th);
      m->type[i] = LAC_TRI3;
      m->conn[3 * i] = 0;
      m->conn[3 * i + 1] = i + 1;
      m->conn[3 * i + 2] = (i + 1) % k + 1;
      m->ptr[i + 1] = 3 * ((size_t) i + 1);
      cell[i] = (size_t) i;
      face[i] = 1;
    }
  lac_mesh_add_group (m, "rim", 1, 0, (size_t) k, cell, face);
  return m;
}

int
main (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 }, cut2d = { 0, 1 };
  lac_macro_opts across = { 0, 2 };      /* gathered across corners */
  lac_init ();

  for (int two = 0; two < 2; two++)
    {
      run_box (LAC_TET4, two, NULL, 1.0 / 3, "");
      run_box (LAC_TET10, two, NULL, 2.0 / 9, "");
      run_box (LAC_HEX8, two, NULL, 1.0 / 3, "pyramids");
      run_box (LAC_HEX8, two, &six, 7.0 / 48, "six");
      run_box (LAC_HEX20, two, NULL, 5.0 / 36, "six");
      run_box (LAC_HEX27, two, NULL, 4.0 / 9, "");
      run_box (LAC_TRI6, two, NULL, 2.0 / 3, "");
      run_box (LAC_QUAD8, two, NULL, 2.0 / 3, "");
      run_box (LAC_QUAD9, two, NULL, 2.0 / 3, "");
      run_box (LAC_TRI3, two, &cut2d, 1.0 / 2, "cut");
      run_box (LAC_QUAD4, two, &cut2d, 1.0 / 2, "cut");
    }
  /* Gathering: ymax of a 3x2 box is a chain of 3 (one macro of 3); of a
   * 2x2 box with xmax a chain of 4 (2 pairs, mean 1/2); 5 segments: a pair
   * and a triple; closed loops of 3, 4 and 5 segments, gathered across
   * their corners (cut_2d = 2: the gathering of a loop as such). */
  run_box (LAC_QUAD4, 0, NULL, -1, "chain of 3");
  run_box (LAC_TRI3, 1, NULL, -1, "chain of 5");
  {
    size_t n[2] = { 2, 2 };
    double L[2] = { 1, 1 };
    lac_mesh *m = NULL;
    lac_mesh_box (LAC_QUAD4, n, L, 0.2, &m);
    union_group (m, "ymax", "xmax");
    build_and_check (m, "u", NULL, 0.5, 2, "quad4 chain of 4");
  }
  for (int k = 3; k <= 5; k++)
    {
      char what[32];
      snprintf (what, sizeof what, "fan loop of %d", k);
      build_and_check (fan (k), "rim", &across, k == 4 ? 0.5 : -1, k / 2,
                       what);
    }
  lac_finalize ();
  return check_summary ();
}
