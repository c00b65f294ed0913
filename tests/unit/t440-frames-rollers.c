/* t440: nodal frames, the rollers' rotation of the dofs  [LAC (4), (8)]
 *
 * fem/lac_frames.h and fem/lac_rigid.h with frames.
 *   1. The frame of the conditions at a node (lac_frames_basis): one
 *      roller (q_1 = n, the rest orthonormal); two rollers at a corner (both
 *      fixed, values satisfying both); a roller and a symmetry plane in 3D;
 *      a clamp and a roller (the roller adds nothing); a direction fixed
 *      twice with two values (an error naming both).
 *   2. K <- T^T K T in place equals the dense product (quad8 in 2D, hex8
 *      in 3D), stays symmetric; C <- T^T C for a C of any pattern; to_local
 *      then to_global gives v back.
 *   3. Nodal normals: the faces of a box turned by 30 degrees, and a
 *      facet group with no facet (refused).
 *   4. The rigid motions a roller leaves free: on the turned square, a
 *      roller on one side leaves one, the slide along that side; rollers
 *      on two sides none; the same fixed flags read along the axes would
 *      leave the slide along y instead.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "fem/lac_frames.h"
#include "fem/lac_rigid.h"
#include "base/lac_status.h"

#define PI 3.14159265358979323846

/* ---- 1. the frame of the conditions ----------------------------------- */

/* R^T R = I on the first dim columns, and d_j . (sum_k q_k w_k) = v_j. */
static void
check_frame (int dim, size_t n, const double *d, const double *v,
             const double *R, const double *w, const char *name)
{
  double e = 0;
  for (int i = 0; i < dim; i++)
    for (int j = 0; j < dim; j++)
      {
        double s = 0;
        for (int k = 0; k < 3; k++)
          s += R[3 * k + i] * R[3 * k + j];
        e = fmax (e, fabs (s - (i == j)));
      }
  check_abs (e, 0, 1e-14, "%s: orthonormal", name);
  for (size_t j = 0; j < n; j++)
    {
      double s = 0;
      for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
          s += d[3 * j + i] * R[3 * i + k] * w[k];
      check_abs (s, v[j], 1e-14, "%s: condition %zu holds", name, j);
    }
}

static void
test_basis (void)
{
  double c = cos (PI / 6), s = sin (PI / 6), R[9], w[3];
  char ind[4];
  int rank;
  size_t bad, with;
  /* one roller */
  double d1[3] = { -s, c, 0 }, v1[1] = { 0 };
  check_status (lac_frames_basis (2, 1, d1, v1, R, w, ind, &rank, &bad,
                                  &with), LAC_SUCCESS, "one roller");
  check_int (rank, 1, "one roller: rank 1");
  check_abs (fabs (R[0] * d1[0] + R[3] * d1[1]), 1, 1e-15, "q_1 = n");
  check_frame (2, 1, d1, v1, R, w, "one roller");
  /* two rollers at a corner, values 0.1 and -0.2: both fixed */
  double d2[6] = { -s, c, 0, c, s, 0 }, v2[2] = { 0.1, -0.2 };
  lac_frames_basis (2, 2, d2, v2, R, w, ind, &rank, &bad, &with);
  check_int (rank, 2, "corner: rank 2");
  check_frame (2, 2, d2, v2, R, w, "corner");
  /* 3D: a roller on x + y + z = 0 and the symmetry plane z = 0 */
  double r3 = 1 / sqrt (3.0);
  double d3[6] = { r3, r3, r3, 0, 0, 1 }, v3[2] = { 0, 0 };
  lac_frames_basis (3, 2, d3, v3, R, w, ind, &rank, &bad, &with);
  check_int (rank, 2, "3D roller and symmetry: rank 2");
  check_frame (3, 2, d3, v3, R, w, "3D roller and symmetry");
  /* a clamp (x, y, z) then a roller: the roller adds nothing */
  double d4[12] = { 1, 0, 0, 0, 1, 0, 0, 0, 1, r3, r3, r3 };
  double v4[4] = { 0, 0, 0, 0 };
  check_status (lac_frames_basis (3, 4, d4, v4, R, w, ind, &rank, &bad,
                                  &with), LAC_SUCCESS, "clamp and roller");
  check_int (rank, 3, "clamp and roller: rank 3");
  check_true (ind[0] && ind[1] && ind[2] && !ind[3], "the roller adds "
              "nothing");
  /* ux = 0.1, then a roller along x with 0: a contradiction */
  double d5[6] = { 1, 0, 0, 1, 0, 0 }, v5[2] = { 0.1, 0 };
  check_status (lac_frames_basis (2, 2, d5, v5, R, w, ind, &rank, &bad,
                                  &with), LAC_EINVAL, "contradiction");
  check_true (bad == 1 && with == 0, "contradiction: condition 1 against 0 "
              "(%zu, %zu)", bad, with);
  /* the same value twice: fine */
  v5[1] = 0.1;
  check_status (lac_frames_basis (2, 2, d5, v5, R, w, ind, &rank, &bad,
                                  &with), LAC_SUCCESS, "agreeing values");
}

/* ---- 2. rotations -------------------------------------------------------- */

/* A rotation about the unit axis (ax) by angle t, row-major 3 x 3. */
static void
rotation (const double *ax, double t, double *R)
{
  double c = cos (t), s = sin (t), x = ax[0], y = ax[1], z = ax[2];
  double M[9] = { c + x * x * (1 - c), x * y * (1 - c) - z * s,
                  x * z * (1 - c) + y * s, y * x * (1 - c) + z * s,
                  c + y * y * (1 - c), y * z * (1 - c) - x * s,
                  z * x * (1 - c) - y * s, z * y * (1 - c) + x * s,
                  c + z * z * (1 - c) };
  memcpy (R, M, sizeof M);
}

/* The dense n x n T of the frames (row-major). */
static double *
dense_T (const lac_frames *f)
{
  int d = f->dim;
  size_t n = (size_t) d * f->nnodes;
  double *T = calloc (n * n, sizeof *T);
  for (size_t a = 0; a < f->nnodes; a++)
    {
      const double *R = lac_frames_of (f, a);
      for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++)
          T[(d * a + i) * n + d * a + j] = R ? R[3 * i + j] : (i == j);
    }
  return T;
}

static double *
dense_of (const lac_csc *A)
{
  double *D = calloc (A->nrow * A->ncol, sizeof *D);
  for (size_t j = 0; j < A->ncol; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      D[(size_t) A->i[q] * A->ncol + j] += A->x[q];
  return D;
}

static void
test_rotate (lac_elem_type type, const char *name)
{
  int dim = lac_refelem_get (type)->dim;
  size_t nb[3] = { 2, 2, 1 };
  double L[3] = { 1, 1, 1 }, E[64], nu[64];
  lac_mesh *m = NULL;
  lac_csc *K = NULL;
  lac_mesh_box (type, nb, L, 0.1, &m);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = 100, nu[c] = 0.3;
  lac_elastic el = { dim == 3 ? LAC_SOLID3D : LAC_PLANE_STRAIN, E, nu };
  check_status (lac_assembly_stiffness_csc (m, &el, &K), LAC_SUCCESS,
                "%s: K", name);
  lac_frames *f = lac_frames_alloc (dim, m->nnodes);
  double ax[3] = { 0.48, -0.6, 0.64 }, R[9];
  if (dim == 2)
    ax[0] = ax[1] = 0, ax[2] = 1;
  for (size_t a = 0; a < m->nnodes; a += 3)
    {
      rotation (ax, 0.3 + 0.1 * (double) a, R);
      check_status (lac_frames_set (f, a, R), LAC_SUCCESS, "%s: set", name);
    }
  size_t n = (size_t) dim * m->nnodes;
  double *T = dense_T (f), *Kd = dense_of (K), e = 0, es = 0, kmax = 0;
  check_status (lac_frames_rotate_matrix (f, K), LAC_SUCCESS, "%s: rotate",
                name);
  double *Kr = dense_of (K);
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++)
      {
        double s = 0;                                /* (T^T K T)_ij */
        for (size_t p = 0; p < n; p++)
          for (size_t q = 0; q < n; q++)
            if (T[p * n + i] != 0 && T[q * n + j] != 0)
              s += T[p * n + i] * Kd[p * n + q] * T[q * n + j];
        e = fmax (e, fabs (s - Kr[i * n + j]));
        es = fmax (es, fabs (Kr[i * n + j] - Kr[j * n + i]));
        kmax = fmax (kmax, fabs (s));
      }
  check_abs (e / kmax, 0, 1e-14, "%s: T^T K T in place", name);
  check_abs (es / kmax, 0, 1e-14, "%s: symmetric", name);
  /* C <- T^T C, a C of two columns with a partial block */
  lac_triplet *Tc = lac_triplet_alloc (n, 2, 8);
  lac_triplet_add (Tc, 0, 0, 1.5);              /* node 0, x only */
  lac_triplet_add (Tc, (size_t) dim * 3 + 1, 1, -2);   /* node 3, y only */
  lac_triplet_add (Tc, (size_t) dim * 1, 1, 0.5);      /* node 1, no frame */
  lac_csc *C = lac_csc_from_triplet (Tc), *C0 = lac_csc_copy (C);
  check_status (lac_frames_rotate_rows (f, &C), LAC_SUCCESS, "%s: rows",
                name);
  double *Cd = dense_of (C0), *Cr = dense_of (C);
  e = 0;
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < 2; j++)
      {
        double s = 0;
        for (size_t p = 0; p < n; p++)
          s += T[p * n + i] * Cd[p * 2 + j];
        e = fmax (e, fabs (s - Cr[i * 2 + j]));
      }
  check_abs (e, 0, 1e-14, "%s: T^T C", name);
  double *v = malloc (n * sizeof *v), *v0 = malloc (n * sizeof *v0);
  for (size_t i = 0; i < n; i++)
    v[i] = v0[i] = sin (1.0 + (double) i);
  lac_frames_to_local (f, v);
  lac_frames_to_global (f, v);
  e = 0;
  for (size_t i = 0; i < n; i++)
    e = fmax (e, fabs (v[i] - v0[i]));
  check_abs (e, 0, 1e-15, "%s: to_local then to_global", name);
  free (T), free (Kd), free (Kr), free (Cd), free (Cr), free (v), free (v0);
  lac_triplet_free (Tc);
  lac_csc_free (C), lac_csc_free (C0), lac_csc_free (K);
  lac_frames_free (f);
  lac_mesh_free (m);
}

/* ---- 3. and 4.: a square turned by 30 degrees ---------------------------- */

static lac_mesh *
turned_square (lac_elem_type type)
{
  size_t nb[2] = { 3, 3 };
  double L[2] = { 2, 2 }, c = cos (PI / 6), s = sin (PI / 6);
  lac_mesh *m = NULL;
  lac_mesh_box (type, nb, L, 0.0, &m);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double x = m->x[2 * a], y = m->x[2 * a + 1];
      m->x[2 * a] = c * x - s * y;
      m->x[2 * a + 1] = s * x + c * y;
    }
  return m;
}

static void
test_normals (void)
{
  lac_mesh *m = turned_square (LAC_QUAD8);
  double c = cos (PI / 6), s = sin (PI / 6);
  const char *gn[4] = { "xmin", "xmax", "ymin", "ymax" };
  double want[4][2] = { { -c, -s }, { c, s }, { s, -c }, { -s, c } };
  for (int k = 0; k < 4; k++)
    {
      const lac_group *g = lac_mesh_group (m, gn[k]);
      double *n = malloc (3 * g->nnodes * sizeof *n), e = 0;
      check_status (lac_frames_normals (m, g, n), LAC_SUCCESS, "normals %s",
                    gn[k]);
      for (size_t i = 0; i < g->nnodes; i++)
        e = fmax (e, hypot (n[3 * i] - want[k][0], n[3 * i + 1]
                            - want[k][1]));
      check_abs (e, 0, 1e-14, "outward normal of the turned %s", gn[k]);
      free (n);
    }
  const lac_group *body = lac_mesh_group (m, "body");
  double nb[3];
  check_status (lac_frames_normals (m, body, nb), LAC_EINVAL, "a cell "
                "group has no normal");
  check_message ("facets", "the message says what is needed");
  lac_mesh_free (m);
}

/* Free rigid motions of the turned square with rollers on the groups
 * (their normal dofs fixed in frames), or the same flags along the axes. */
static int
free_motions (const char *const *groups, int ngroups, int frames,
              double *mode)
{
  lac_mesh *m = turned_square (LAC_QUAD4);
  lac_frames *f = lac_frames_alloc (2, m->nnodes);
  char *fixed = calloc (2 * m->nnodes, 1);
  for (int k = 0; k < ngroups; k++)
    {
      const lac_group *g = lac_mesh_group (m, groups[k]);
      double *n = malloc (3 * g->nnodes * sizeof *n);
      lac_frames_normals (m, g, n);
      for (size_t i = 0; i < g->nnodes; i++)
        {
          double R[9] = { n[3 * i], -n[3 * i + 1], 0, n[3 * i + 1],
                          n[3 * i], 0, 0, 0, 1 };
          if (!lac_frames_of (f, g->node[i]))     /* a corner: the first */
            lac_frames_set (f, g->node[i], R);
          fixed[2 * g->node[i]] = 1;
        }
      free (n);
    }
  lac_bodies *B = NULL;
  check_status (lac_bodies_find (m, LAC_PLANE_STRAIN, fixed,
                                 frames ? f : NULL, &B), LAC_SUCCESS,
                "bodies");
  int nfree = B ? B->body[0].nfree : -1;
  if (nfree > 0)
    memcpy (mode, B->body[0].mode[0], 3 * sizeof *mode);
  lac_bodies_free (B);
  free (fixed);
  lac_frames_free (f);
  lac_mesh_free (m);
  return nfree;
}

static void
test_rigid (void)
{
  const char *one[1] = { "xmin" }, *two[2] = { "xmin", "ymin" };
  double v[3] = { 0, 0, 0 }, c = cos (PI / 6), s = sin (PI / 6);
  check_int (free_motions (one, 1, 1, v), 1, "a roller on one side: one "
             "motion free");
  check_abs (fabs (v[0] * c + v[1] * s), 0, 1e-10, "... along the side");
  check_abs (v[2], 0, 1e-10, "... not a rotation");
  check_int (free_motions (two, 2, 1, v), 0, "rollers on two sides: nothing "
             "free");
  check_int (free_motions (one, 1, 0, v), 1, "the same flags along x: one");
  check_abs (v[0], 0, 1e-10, "... the slide along y");
}

int
main (void)
{
  lac_init ();
  test_basis ();
  test_rotate (LAC_QUAD8, "quad8");
  test_rotate (LAC_HEX8, "hex8");
  test_normals ();
  test_rigid ();
  lac_finalize ();
  return check_summary ();
}
