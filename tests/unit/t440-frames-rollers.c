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
 *   4. The pieces of a face (lac_frames_pieces): two sides of the turned
 *      square meet at a corner, two pieces there; the outer arc of a
 *      quarter ring, 6 chords: radial normals, the chords' at the ends
 *      (which end the piece), tilts sin 15 and sin 7.5 degrees; the same
 *      arc as two groups, one piece where they meet.
 *   5. The rigid motions a roller leaves free: on the turned square, a
 *      roller on one side leaves one, the slide along that side; rollers
 *      on two sides none; the same fixed flags read along the axes would
 *      leave the slide along y instead.  A roller on the quarter arc: its
 *      chords' normals alone hold the rotation about the centre (6, 12,
 *      24 chords); with what the check sees (the ends left out, the
 *      tilts) it is free, about the centre.
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

/* ---- 3. a square turned by 30 degrees: normals ------------------------- */

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

/* The normals of one facet group, one per node (a flat face: one piece
 * at each node); NULL if some node has more than one piece. */
static double *
group_normals (const lac_mesh *m, const lac_group *g, int *status)
{
  lac_face_pieces P;
  double *n = malloc (3 * g->nnodes * sizeof *n);
  *status = lac_frames_pieces (m, 1, &g, &P);
  for (size_t i = 0; !*status && i < g->nnodes; i++)
    {
      size_t a = g->node[i];
      if (P.ptr[a + 1] != P.ptr[a] + 1)
        *status = LAC_ESANITY;
      else
        memcpy (n + 3 * i, P.normal + 3 * P.ptr[a], 3 * sizeof *n);
    }
  lac_face_pieces_clear (&P);
  if (*status)
    free (n), n = NULL;
  return n;
}

static void
test_normals (void)
{
  lac_mesh *m = turned_square (LAC_QUAD8);
  double c = cos (PI / 6), s = sin (PI / 6);
  const char *gn[4] = { "xmin", "xmax", "ymin", "ymax" };
  double want[4][2] = { { -c, -s }, { c, s }, { s, -c }, { -s, c } };
  int status;
  for (int k = 0; k < 4; k++)
    {
      const lac_group *g = lac_mesh_group (m, gn[k]);
      double *n = group_normals (m, g, &status), e = 0;
      check_status (status, LAC_SUCCESS, "normals %s", gn[k]);
      for (size_t i = 0; n && i < g->nnodes; i++)
        e = fmax (e, hypot (n[3 * i] - want[k][0], n[3 * i + 1]
                            - want[k][1]));
      check_abs (e, 0, 1e-14, "outward normal of the turned %s", gn[k]);
      free (n);
    }
  const lac_group *body = lac_mesh_group (m, "body");
  lac_face_pieces P;
  check_status (lac_frames_pieces (m, 1, &body, &P), LAC_EINVAL, "a cell "
                "group has no normal");
  check_message ("facets", "the message says what is needed");
  lac_mesh_free (m);
}

/* ---- 4. the pieces of a face: corners, arcs, two groups ---------------- */

/* The quarter annulus 1 < r < 2, 0 < theta < 90 degrees, from a box of
 * n x n cells of `type` (x -> r, y -> theta): its "xmax" is the outer arc,
 * a polygon of n chords (linear cells), "ymin" and "ymax" the cuts. */
static lac_mesh *
quarter_ring (lac_elem_type type, size_t n)
{
  size_t nb[2] = { n, n };
  double L[2] = { 1, 1 };
  lac_mesh *m = NULL;
  lac_mesh_box (type, nb, L, 0.0, &m);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double r = 1 + m->x[2 * a], t = m->x[2 * a + 1] * PI / 2;
      m->x[2 * a] = r * cos (t);
      m->x[2 * a + 1] = r * sin (t);
    }
  return m;
}

/* Group g's facets from k0 to k1 (excluded) as a group of their own, its
 * nodes those of the facets (sorted). */
static lac_group
sub_group (const lac_mesh *m, const lac_group *g, size_t k0, size_t k1)
{
  lac_group h = { "part", 1, 0, k1 - k0, g->cell + k0, g->face + k0, 0,
                  malloc (g->nnodes * sizeof (size_t)) };
  for (size_t i = 0; i < g->nnodes; i++)
    {
      int fn[LAC_MAX_FACE_NODES], in = 0;
      for (size_t e = k0; e < k1 && !in; e++)
        {
          int nf = lac_mesh_facet_nodes (m, g->cell[e], g->face[e], fn, NULL);
          for (int q = 0; q < nf; q++)
            in |= (size_t) fn[q] == g->node[i];
        }
      if (in)
        h.node[h.nnodes++] = g->node[i];
    }
  return h;
}

/* The angle (degrees) of the pieces' normal at node a, and their count. */
static size_t
pieces_at (const lac_face_pieces *P, size_t a, double *deg)
{
  size_t p = P->ptr[a];
  if (P->ptr[a + 1] > p)
    *deg = atan2 (P->normal[3 * p + 1], P->normal[3 * p]) * 180 / PI;
  return P->ptr[a + 1] - p;
}

static void
test_pieces (void)
{
  /* the turned square's xmin and ymin as two groups: their corner node
   * has two pieces (a right angle), each along one side's normal, both
   * ending there; every other node one */
  lac_mesh *m = turned_square (LAC_QUAD4);
  const lac_group *g2[2] = { lac_mesh_group (m, "xmin"),
                             lac_mesh_group (m, "ymin") };
  lac_face_pieces P;
  size_t two = 0, corner = 0;
  check_status (lac_frames_pieces (m, 2, g2, &P), LAC_SUCCESS, "pieces");
  for (size_t a = 0; a < m->nnodes; a++)
    if (P.ptr[a + 1] - P.ptr[a] == 2)
      two++, corner = P.ptr[a];
  check_int ((long) two, 1, "one node with two pieces (the corner)");
  check_abs (P.normal[3 * corner] * P.normal[3 * corner + 3]
             + P.normal[3 * corner + 1] * P.normal[3 * corner + 4], 0, 1e-14,
             "... at right angles");
  check_true (P.end[corner] && P.end[corner + 1] && P.tilt[corner] == 0
              && P.grp[P.gptr[corner]] == 0 && P.grp[P.gptr[corner + 1]] == 1,
              "... each of one group, ending there, not tilted");
  lac_face_pieces_clear (&P);
  lac_mesh_free (m);

  /* the outer arc of a quarter ring, 6 chords of 15 degrees: radial
   * normals inside, the end nodes those of their chords (7.5 degrees in),
   * ending there; tilts sin 15 inside, sin 7.5 at the ends */
  m = quarter_ring (LAC_QUAD4, 6);
  const lac_group *arc = lac_mesh_group (m, "xmax");
  double deg = 0, e = 0, et = 0;
  check_status (lac_frames_pieces (m, 1, &arc, &P), LAC_SUCCESS, "arc");
  for (size_t i = 0; i < arc->nnodes; i++)
    {
      size_t a = arc->node[i], p = P.ptr[a];
      double t = atan2 (m->x[2 * a + 1], m->x[2 * a]) * 180 / PI;
      int end = t < 1e-9 || t > 90 - 1e-9;
      double want = t < 1e-9 ? 7.5 : t > 90 - 1e-9 ? 82.5 : t;
      check_int ((long) pieces_at (&P, a, &deg), 1, "one piece at %g", t);
      e = fmax (e, fabs (deg - want));
      et = fmax (et, fabs (P.tilt[p] - sin ((end ? 7.5 : 15) * PI / 180)));
      check_int (P.end[p], end, "the arc ends at %g degrees: %d", t, end);
    }
  check_abs (e, 0, 1e-12, "normals: radial, the chords' at the ends");
  check_abs (et, 0, 1e-14, "tilts: sin 15 degrees, sin 7.5 at the ends");
  lac_face_pieces_clear (&P);

  /* the arc as two groups of 3 chords: their common node (45 degrees)
   * has one piece of both groups, radial, not an end */
  lac_group h1 = sub_group (m, arc, 0, 3), h2 = sub_group (m, arc, 3, 6);
  const lac_group *two_arcs[2] = { &h1, &h2 };
  size_t shared = 0;
  check_status (lac_frames_pieces (m, 2, two_arcs, &P), LAC_SUCCESS,
                "two arcs");
  for (size_t a = 0; a < m->nnodes; a++)
    if (P.ptr[a + 1] > P.ptr[a] && P.gptr[P.ptr[a] + 1] - P.gptr[P.ptr[a]] == 2)
      {
        shared++;
        check_int ((long) pieces_at (&P, a, &deg), 1, "one piece where the "
                   "arcs meet");
        check_abs (deg, 45, 1e-12, "... radial");
        check_int (P.end[P.ptr[a]], 0, "... not an end");
      }
  check_int ((long) shared, 1, "one node shared by the two arcs");
  lac_face_pieces_clear (&P);
  free (h1.node), free (h2.node);
  lac_mesh_free (m);
}

/* ---- 5. the rigid motions rollers leave free ------------------------- */

/* Free rigid motions of the turned square with rollers on the groups
 * (their normal dofs fixed in frames), or the same flags along the axes. */
static int
free_motions (const char *const *groups, int ngroups, int frames,
              double *mode)
{
  lac_mesh *m = turned_square (LAC_QUAD4);
  lac_frames *f = lac_frames_alloc (2, m->nnodes);
  char *fixed = calloc (2 * m->nnodes, 1);
  int status;
  for (int k = 0; k < ngroups; k++)
    {
      const lac_group *g = lac_mesh_group (m, groups[k]);
      double *n = group_normals (m, g, &status);
      for (size_t i = 0; n && i < g->nnodes; i++)
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

/* The quarter ring of quarter_ring (quad4, n chords) on a roller on its
 * outer arc, the frames of its pieces; what the check sees (tilts, the
 * chords' ends left out) set or not.  The free motions; the fixed point
 * of the first, a rotation, in x. */
static int
arc_motions (size_t n, int check, double *x)
{
  lac_mesh *m = quarter_ring (LAC_QUAD4, n);
  const lac_group *arc = lac_mesh_group (m, "xmax");
  lac_frames *f = lac_frames_alloc (2, m->nnodes);
  char *fixed = calloc (2 * m->nnodes, 1);
  lac_face_pieces P;
  lac_bodies *B = NULL;
  lac_frames_pieces (m, 1, &arc, &P);
  for (size_t i = 0; i < arc->nnodes; i++)
    {
      size_t a = arc->node[i], p = P.ptr[a];
      const double *q = P.normal + 3 * p;
      double R[9] = { q[0], -q[1], 0, q[1], q[0], 0, 0, 0, 1 };
      lac_frames_set (f, a, R);
      fixed[2 * a] = 1;
      if (check)
        lac_frames_set_check (f, a, P.end[p] ? 0 : P.tilt[p] * P.tilt[p],
                              P.end[p] ? 0 : 1);
    }
  check_status (lac_bodies_find (m, LAC_PLANE_STRAIN, fixed, f, &B),
                LAC_SUCCESS, "bodies of the quarter ring");
  int nfree = B ? B->body[0].nfree : -1;
  if (nfree > 0)          /* u = (v0 - v2 y, v1 + v2 x) in the body's frame */
    {
      const lac_body *y = &B->body[0];
      const double *v = y->mode[0];
      x[0] = y->ctr[0] - y->size * v[1] / v[2];
      x[1] = y->ctr[1] + y->size * v[0] / v[2];
    }
  lac_bodies_free (B);
  lac_face_pieces_clear (&P);
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
  /* a roller on a quarter arc: the chords' ends hold the rotation about
   * the centre, weakly; what the check sees frees it */
  for (size_t n = 6; n <= 24; n *= 2)
    {
      check_int (arc_motions (n, 0, v), 0, "%zu chords, the chords' "
                 "normals: the rotation held", n);
      check_int (arc_motions (n, 1, v), 1, "%zu chords, the smooth arc: "
                 "one motion free", n);
      check_abs (hypot (v[0], v[1]), 0, 1e-12, "... the rotation about "
                 "the centre (%g, %g)", v[0], v[1]);
    }
}

int
main (void)
{
  lac_init ();
  test_basis ();
  test_rotate (LAC_QUAD8, "quad8");
  test_rotate (LAC_HEX8, "hex8");
  test_normals ();
  test_pieces ();
  test_rigid ();
  lac_finalize ();
  return check_summary ();
}
