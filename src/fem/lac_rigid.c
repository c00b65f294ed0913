/* lac_rigid.c -- bodies and their free rigid motions (see lac_rigid.h)
 *                                                                  [LAC §2]
 */
#include "fem/lac_rigid.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* ---- rigid motions of the models -------------------------------------- */

/* Rigid motions of the model at component i of a node at x (relative to
 * the body's centre, divided by its size):  plane strain t_x, t_y, r_z;
 * axisymmetric t_z (the only one: u_r = const strains the hoops); 3D t_x,
 * t_y, t_z, r_x, r_y, r_z with r_w = w x x. */
static int
rigid_modes (lac_model model, int i, const double *x, double *v)
{
  if (model == LAC_AXISYMMETRIC)
    return v[0] = (i == 1), 1;
  if (model == LAC_PLANE_STRAIN)
    {
      v[0] = (i == 0), v[1] = (i == 1);
      v[2] = i == 0 ? -x[1] : x[0];                   /* e_z x x */
      return 3;
    }
  for (int k = 0; k < 3; k++)
    v[k] = (i == k);
  v[3] = i == 0 ? 0 : i == 1 ? -x[2] : x[1];          /* e_x x x */
  v[4] = i == 0 ? x[2] : i == 1 ? 0 : -x[0];          /* e_y x x */
  v[5] = i == 0 ? -x[1] : i == 1 ? x[0] : 0;          /* e_z x x */
  return 6;
}

static const char *
mode_name (lac_model model, int k)
{
  static const char *const n2[] = { "translation along x",
    "translation along y", "rotation about z" };
  static const char *const n3[] = { "translation along x",
    "translation along y", "translation along z", "rotation about x",
    "rotation about y", "rotation about z" };
  if (model == LAC_AXISYMMETRIC)
    return "translation along z (the axis)";
  if (k < 0 || k >= (model == LAC_PLANE_STRAIN ? 3 : 6))
    return "no rigid mode";                 /* not one of the table's */
  return model == LAC_PLANE_STRAIN ? n2[k] : n3[k];
}

static size_t
uf_find (size_t *p, size_t a)
{
  while (p[a] != a)
    a = p[a] = p[p[a]];
  return a;
}

/* Describe the rigid motion with mode coefficients v (relative to the
 * body's centre ctr and size L): in 2D a translation or the rotation about
 * its fixed point, in 3D the modes that take part. */
static int
describe_mode (lac_model model, int nm, const double *v, const double *ctr,
               double L, char *buf, size_t size)
{
  if (model == LAC_PLANE_STRAIN && fabs (v[2]) > 1e-6)
    /* u = (v0 - v2 y, v1 + v2 x) vanishes at x = -v1/v2, y = v0/v2 */
    {
      double x = ctr[0] - L * v[1] / v[2], y = ctr[1] + L * v[0] / v[2];
      return snprintf (buf, size, "rotation about (%.3g, %.3g)",
                       fabs (x) < 1e-9 * L ? 0.0 : x,     /* no -2e-16 */
                       fabs (y) < 1e-9 * L ? 0.0 : y);
    }
  if (model == LAC_PLANE_STRAIN && fabs (v[0]) > 1e-6 && fabs (v[1]) > 1e-6)
    return snprintf (buf, size, "translation along (%.3g, %.3g)", v[0], v[1]);
  {
    int len = 0;
    buf[0] = '\0';
    for (int j = 0; j < nm; j++)
      if (fabs (v[j]) > 0.1 && len >= 0 && (size_t) len < size)
        len += snprintf (buf + len, size - (size_t) len, "%s%s",
                         len ? " + " : "", mode_name (model, j));
    return len;
  }
}

/* v^T H v (nm x nm). */
static double
quadratic (int nm, const double *H, const double *v)
{
  double s = 0;
  for (int i = 0; i < nm; i++)
    for (int j = 0; j < nm; j++)
      s += v[i] * H[i * nm + j] * v[j];
  return s;
}

/* The free rigid motions of a body from the Gram matrix G of the modes
 * restricted to its fixed dofs and the allowance H of its rollers' tilts:
 * an eigenvector v of G is free if its eigenvalue is <= 1e-10 * max, or
 * <= v^T H v (*slide = 1: some free motion moves rollers on curved faces,
 * v^T H v > 0).  Describes them in
 * buf, their coefficients in mode[]; returns their number (-1: GSL
 * failed, -2: GSL's allocations failed). */
static int
free_modes (lac_model model, int nm, double *G, const double *H,
            const double *ctr, double L, char *buf, size_t size,
            double (*mode)[6], int *slide)
{
  gsl_matrix_view A = gsl_matrix_view_array (G, (size_t) nm, (size_t) nm);
  gsl_vector *ev = gsl_vector_alloc ((size_t) nm);
  gsl_matrix *V = gsl_matrix_alloc ((size_t) nm, (size_t) nm);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc ((size_t) nm);
  int nfree = 0;
  size_t len = 0;
  double lmax;
  buf[0] = '\0';
  if (!ev || !V || !w)
    nfree = -2;
  else if (gsl_eigen_symmv (&A.matrix, ev, V, w))
    nfree = -1;
  lmax = nfree ? 0 : gsl_vector_max (ev);
  *slide = 0;
  for (int k = 0; nfree >= 0 && k < nm; k++)
    {
      double v[6] = { 0, 0, 0, 0, 0, 0 }, g = gsl_vector_get (ev, (size_t) k);
      for (int j = 0; j < nm; j++)
        v[j] = gsl_matrix_get (V, (size_t) j, (size_t) k);
      if (lmax > 0 && g > 1e-10 * lmax && g > quadratic (nm, H, v))
        continue;
      *slide |= quadratic (nm, H, v) > 0;
      memcpy (mode[nfree], v, sizeof v);
      if (len + 8 < size)
        len += (size_t) snprintf (buf + len, size - len, nfree ? "; "
                                  : "free: ");
      if (len < size)
        len += (size_t) describe_mode (model, nm, v, ctr, L, buf + len,
                                       size - len);
      nfree++;
    }
  if (nfree > 0 && lmax == 0)
    snprintf (buf, size, "no Dirichlet condition acts on it");
  gsl_eigen_symmv_free (w);
  gsl_matrix_free (V);
  gsl_vector_free (ev);
  return nfree;
}

/* ---- bodies ----------------------------------------------------------- */

/* Bodies: the connected components of the mesh (nodes joined through
 * cells, union-find in p).  comp[a] = body of node a (SIZE_MAX: in no
 * cell), cell0[b] = a cell of body b; returns the number of bodies. */
static size_t
find_bodies (const lac_mesh *m, size_t *p, size_t *comp, size_t *cell0)
{
  size_t nb = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    p[a] = a, comp[a] = SIZE_MAX;
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t k = m->ptr[c] + 1; k < m->ptr[c + 1]; k++)
      p[uf_find (p, (size_t) m->conn[k])] = uf_find (p, (size_t)
                                                     m->conn[m->ptr[c]]);
  for (size_t c = 0; c < m->ncells; c++)
    {
      size_t root = uf_find (p, (size_t) m->conn[m->ptr[c]]);
      if (comp[root] == SIZE_MAX)
        cell0[nb] = c, comp[root] = nb++;
    }
  for (size_t a = 0; a < m->nnodes; a++)
    comp[a] = comp[uf_find (p, a)];
  return nb;
}

/* Centre ctr[4b .. 4b+2] and size ctr[4b+3] (largest distance of a node
 * to the centre along an axis, 1 if zero) of each body; ctr zeroed. */
static void
body_frames (const lac_mesh *m, const size_t *comp, size_t nb, double *ctr)
{
  int dim = m->dim;
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; comp[a] != SIZE_MAX && i <= dim; i++)
      ctr[4 * comp[a] + (size_t) (i < dim ? i : 3)]
        += i < dim ? m->x[a * (size_t) dim + (size_t) i] : 1.0;
  for (size_t b = 0; b < nb; b++)
    {
      for (int i = 0; i < 3; i++)
        ctr[4 * b + (size_t) i] /= ctr[4 * b + 3];     /* mean of x */
      ctr[4 * b + 3] = 0;
    }
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; comp[a] != SIZE_MAX && i < dim; i++)
      ctr[4 * comp[a] + 3] = fmax (ctr[4 * comp[a] + 3],
                                   fabs (m->x[a * (size_t) dim + (size_t) i]
                                         - ctr[4 * comp[a] + (size_t) i]));
  for (size_t b = 0; b < nb; b++)
    if (!(ctr[4 * b + 3] > 0))
      ctr[4 * b + 3] = 1;
}

/* The rigid modes at the fixed dof q of a node at x: along its axis e
 * (a coordinate axis, or an axis of the node's frame), v = sum_i e_i
 * (modes at component i). */
static void
modes_along (lac_model model, int dim, const lac_frames *fr, size_t q,
             const double *x, double *v)
{
  double e[3], vi[6];
  int nm = 0;
  lac_frames_axis (fr, dim, q, e);
  for (int k = 0; k < 6; k++)
    v[k] = 0;
  for (int i = 0; i < dim; i++)
    {
      nm = rigid_modes (model, i, x, vi);
      for (int k = 0; k < nm && e[i] != 0; k++)
        v[k] += e[i] * vi[k];
    }
}

/* Node a's position in the frame of body b (centre, size). */
static void
body_x (const lac_mesh *m, size_t a, size_t b, const double *ctr, double *x)
{
  for (int i = 0; i < m->dim; i++)
    x[i] = (m->x[a * (size_t) m->dim + (size_t) i] - ctr[4 * b + (size_t) i])
           / ctr[4 * b + 3];
}

/* G_b += v v^T over the fixed dofs q of body b that the check counts
 * (fem/lac_frames.h: not the rollers where a curved piece ends), v = the
 * rigid modes at q; H_b += t_a sum_i v_i v_i^T over the nodes a with a
 * tilt t_a, v_i = the modes at component i: the squared length of a
 * motion there, times the squared sines of the angles by which the
 * rollers' normals may miss the smooth face's.  36 entries per body, nm
 * x nm used. */
static void
mode_gram (const lac_mesh *m, lac_model model, const char *fixed,
           const lac_frames *fr, const size_t *comp, const double *ctr,
           int nm, double *G, double *H)
{
  int dim = m->dim;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      size_t b = comp[a];
      double x[3] = { 0, 0, 0 }, v[6], t = lac_frames_tilt (fr, a);
      if (b == SIZE_MAX)
        continue;
      body_x (m, a, b, ctr, x);
      for (int c = 0; c < dim; c++)
        {
          size_t q = a * (size_t) dim + (size_t) c;
          int count = fixed[q] && c < lac_frames_counted (fr, a);
          if (count)
            modes_along (model, dim, fr, q, x, v);
          for (int i = 0; count && i < nm; i++)
            for (int j = 0; j < nm; j++)
              G[36 * b + (size_t) (i * nm + j)] += v[i] * v[j];
          if (t > 0)
            rigid_modes (model, c, x, v);
          for (int i = 0; t > 0 && i < nm; i++)
            for (int j = 0; j < nm; j++)
              H[36 * b + (size_t) (i * nm + j)] += t * v[i] * v[j];
        }
    }
}

/* ---- the public functions --------------------------------------------- */

void
lac_bodies_free (lac_bodies *b)
{
  if (!b)
    return;
  lac_free (b->body);
  lac_free (b->node_body);
  lac_free (b);
}

/* Each body's cell, group, frame and free motions from the Gram matrices
 * G and the allowances H (36 per body) and the frames ctr (4 per
 * body). */
static int
describe_bodies (lac_bodies *B, const lac_mesh *m, const size_t *cell0,
                 double *G, const double *H, const double *ctr)
{
  for (size_t b = 0; b < B->n; b++)
    {
      lac_body *y = &B->body[b];
      y->cell0 = cell0[b];
      y->group = m->body[cell0[b]];
      memcpy (y->ctr, ctr + 4 * b, 3 * sizeof (double));
      y->size = ctr[4 * b + 3];
      y->nfree = free_modes (B->model, B->nm, G + 36 * b, H + 36 * b,
                             y->ctr, y->size, y->desc, sizeof y->desc,
                             y->mode, &y->slide);
      if (y->nfree == -2)
        LAC_ERROR (LAC_ENOMEM, "rigid motions of body %zu", b);
      if (y->nfree < 0)
        LAC_ERROR (LAC_EDEP, "rigid motions of body %zu: GSL's eigensolver "
                   "failed", b);
    }
  return LAC_SUCCESS;
}

int
lac_bodies_find (const lac_mesh *m, lac_model model, const char *fixed,
                 const lac_frames *fr, lac_bodies **out)
{
  size_t n = m->nnodes, *p = lac_malloc ((n ? n : 1) * sizeof *p);
  size_t *cell0 = lac_malloc ((n ? n : 1) * sizeof *cell0);
  lac_bodies *B = lac_calloc (1, sizeof *B);
  double *ctr = NULL, *G = NULL, *H = NULL;
  int status = LAC_SUCCESS;
  *out = NULL;
  if (B)
    B->node_body = lac_malloc ((n ? n : 1) * sizeof *B->node_body);
  if (!p || !cell0 || !B || !B->node_body)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "bodies of %zu nodes", n);
      goto done;
    }
  B->model = model;
  B->nm = model == LAC_PLANE_STRAIN ? 3 : model == LAC_AXISYMMETRIC ? 1 : 6;
  B->n = find_bodies (m, p, B->node_body, cell0);
  ctr = lac_calloc (4 * B->n + 1, sizeof *ctr);
  G = lac_calloc (36 * B->n + 1, sizeof *G);
  H = lac_calloc (36 * B->n + 1, sizeof *H);
  B->body = lac_calloc (B->n + 1, sizeof *B->body);
  if (!ctr || !G || !H || !B->body)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "rigid motions of %zu bodies", B->n);
      goto done;
    }
  body_frames (m, B->node_body, B->n, ctr);
  mode_gram (m, model, fixed, fr, B->node_body, ctr, B->nm, G, H);
  status = describe_bodies (B, m, cell0, G, H, ctr);
done:
  lac_free (H);
  lac_free (G);
  lac_free (ctr);
  lac_free (cell0);
  lac_free (p);
  if (status)
    lac_bodies_free (B);
  else
    *out = B;
  return status;
}

const char *
lac_bodies_name (const lac_bodies *b, const lac_mesh *m, size_t body)
{
  int g = b->body[body].group;
  return g >= 0 ? m->group[g].name : NULL;
}

/* Column j of N: free motion f of body b at every dof of the body. */
static void
motion_column (const lac_bodies *B, const lac_mesh *m, size_t b, int f,
               double *col)
{
  const lac_body *y = &B->body[b];
  int dim = m->dim;
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; i < dim; i++)
      {
        double x[3] = { 0, 0, 0 }, v[6], s = 0;
        size_t q = a * (size_t) dim + (size_t) i;
        col[q] = 0;
        if (B->node_body[a] != b)
          continue;
        for (int k = 0; k < dim; k++)
          x[k] = (m->x[a * (size_t) dim + (size_t) k] - y->ctr[k]) / y->size;
        rigid_modes (B->model, i, x, v);
        for (int k = 0; k < B->nm; k++)
          s += y->mode[f][k] * v[k];
        col[q] = s;
      }
}

int
lac_bodies_free_motions (const lac_bodies *B, const lac_mesh *m,
                         const char *which, size_t *nfree, double **N,
                         char ***what)
{
  size_t ndof = (size_t) m->dim * m->nnodes, nf = 0, j = 0;
  *nfree = 0;
  *N = NULL;
  *what = NULL;
  for (size_t b = 0; b < B->n; b++)
    nf += !which || which[b] ? (size_t) B->body[b].nfree : 0;
  if (nf == 0)
    return LAC_SUCCESS;
  *N = lac_malloc (nf * ndof * sizeof **N);
  *what = lac_calloc (nf, sizeof **what);
  if (!*N || !*what)
    {
      lac_free (*N);
      lac_free (*what);
      *N = NULL;
      *what = NULL;
      LAC_ERROR (LAC_ENOMEM, "%zu free rigid motions", nf);
    }
  for (size_t b = 0; b < B->n; b++)
    for (int f = 0; (!which || which[b]) && f < B->body[b].nfree; f++, j++)
      {
        char buf[LAC_RIGID_DESC + 80], one[LAC_RIGID_DESC];
        const char *name = lac_bodies_name (B, m, b);
        double v[6];
        motion_column (B, m, b, f, *N + j * ndof);
        memcpy (v, B->body[b].mode[f], sizeof v);
        describe_mode (B->model, B->nm, v, B->body[b].ctr, B->body[b].size,
                       one, sizeof one);
        if (name)
          snprintf (buf, sizeof buf, "body '%s' (%s)", name, one);
        else
          snprintf (buf, sizeof buf, "the body of cell %zu (%s)",
                    m->cell_tag[B->body[b].cell0], one);
        (*what)[j] = lac_strdup (buf);
      }
  *nfree = nf;
  return LAC_SUCCESS;
}
