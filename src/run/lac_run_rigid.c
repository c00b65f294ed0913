/* lac_run_rigid.c -- is every body fixed against rigid motions?  [LAC §2]
 *
 * Part of the assemble stage (lac_run.c): with too few Dirichlet
 * conditions K is singular, and a solver's pivot message cannot say why.
 * Here the bodies (connected components of the mesh) are found, the rigid
 * motions of the model are restricted to the fixed dofs of each body, and
 * the Gram matrix of these restrictions is checked for singularity: its
 * null space names the free motion ("rotation about (0, 0)",
 * "translation along z", ...).
 */
#include "run/lac_run_internal.h"

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

/* The free rigid motions of a body from the Gram matrix G of the modes
 * restricted to its fixed dofs: eigenvalues <= 1e-10 * max are free.
 * Describes them in buf; returns their number (-1: GSL failed). */
static int
free_modes (lac_model model, int nm, double *G, const double *ctr, double L,
            char *buf, size_t size)
{
  gsl_matrix_view A = gsl_matrix_view_array (G, (size_t) nm, (size_t) nm);
  gsl_vector *ev = gsl_vector_alloc ((size_t) nm);
  gsl_matrix *V = gsl_matrix_alloc ((size_t) nm, (size_t) nm);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc ((size_t) nm);
  int nfree = 0;
  size_t len = 0;
  double lmax;
  buf[0] = '\0';
  if (!ev || !V || !w || gsl_eigen_symmv (&A.matrix, ev, V, w))
    nfree = -1;
  lmax = nfree ? 0 : gsl_vector_max (ev);
  for (int k = 0; nfree >= 0 && k < nm; k++)
    {
      double v[6];
      if (lmax > 0 && gsl_vector_get (ev, (size_t) k) > 1e-10 * lmax)
        continue;
      for (int j = 0; j < nm; j++)
        v[j] = gsl_matrix_get (V, (size_t) j, (size_t) k);
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

/* G_b += v v^T over the fixed dofs q of body b, v = the rigid modes at q
 * (36 entries per body, nm x nm used). */
static void
mode_gram (const lac_run *r, const char *fixed, const size_t *comp,
           const double *ctr, int nm, double *G)
{
  const lac_mesh *m = r->mesh;
  int dim = m->dim;
  for (size_t q = 0; q < r->ndof; q++)
    {
      size_t a = q / (size_t) dim, b = comp[a];
      double x[3] = { 0, 0, 0 }, v[6];
      if (!fixed[q] || b == SIZE_MAX)
        continue;
      for (int i = 0; i < dim; i++)
        x[i] = (m->x[a * (size_t) dim + (size_t) i] - ctr[4 * b + (size_t) i])
               / ctr[4 * b + 3];
      rigid_modes (r->model, (int) (q % (size_t) dim), x, v);
      for (int i = 0; i < nm; i++)
        for (int j = 0; j < nm; j++)
          G[36 * b + (size_t) (i * nm + j)] += v[i] * v[j];
    }
}

/* ---- the check -------------------------------------------------------- */

/* Every connected body must be fixed against rigid motions by the fixed
 * dofs; otherwise K is singular.  Checking it here names the body and the
 * free motion, which a solver's pivot message cannot:  the rigid modes
 * restricted to the fixed dofs of a body must be linearly independent,
 * i.e. their Gram matrix G_b must be non-singular. */
/* Does body b touch a contact surface?  Such a body may be held by the
 * contact constraints alone (the upper block of a patch test). */
static int
body_on_contact (const lac_run *r, const size_t *comp, size_t b)
{
  if (!r->on_contact)
    return 0;
  for (size_t a = 0; a < r->mesh->nnodes; a++)
    if (comp[a] == b && r->on_contact[a])
      return 1;
  return 0;
}

int
lac_run_check_rigid (lac_run *r, const lac_dirichlet *d)
{
  const lac_mesh *m = r->mesh;
  int nm = r->model == LAC_PLANE_STRAIN ? 3
           : r->model == LAC_AXISYMMETRIC ? 1 : 6;
  size_t n = m->nnodes, nb, *p = lac_malloc (n * sizeof *p);
  size_t *comp = lac_malloc (n * sizeof *comp);
  size_t *cell0 = lac_malloc (n * sizeof *cell0);
  double *ctr = NULL, *G = NULL;
  char *fixed = lac_calloc (r->ndof, 1), desc[400];
  int status = LAC_SUCCESS;
  if (!p || !comp || !cell0 || !fixed)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "rigid-motion check");
      goto done;
    }
  nb = find_bodies (m, p, comp, cell0);
  ctr = lac_calloc (4 * nb, sizeof *ctr);
  G = lac_calloc (36 * nb, sizeof *G);
  if (!ctr || !G)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "rigid-motion check");
      goto done;
    }
  body_frames (m, comp, nb, ctr);
  for (size_t k = 0; k < d->n; k++)
    fixed[d->dof[k]] = 1;
  mode_gram (r, fixed, comp, ctr, nm, G);
  for (size_t b = 0; b < nb && !status; b++)
    {
      if (body_on_contact (r, comp, b))
        continue;         /* held by the contact constraints (if at all) */
      int nfree = free_modes (r->model, nm, G + 36 * b, ctr + 4 * b,
                              ctr[4 * b + 3], desc, sizeof desc);
      size_t c = cell0[b];
      if (nfree < 0)
        status = LAC_ERRMSG (LAC_ENOMEM, "rigid-motion check (GSL)");
      else if (nfree > 0 && m->body[c] >= 0)
        status = lac_error_set (LAC_ESING, r->scene->path, "stiffness is "
                                "singular: body '%s' is not fixed against "
                                "rigid motion (%s); add [dirichlet] "
                                "conditions that prevent it",
                                m->group[m->body[c]].name, desc);
      else if (nfree > 0)
        status = lac_error_set (LAC_ESING, r->scene->path, "stiffness is "
                                "singular: the cells around cell %zu are not "
                                "fixed against rigid motion (%s); add "
                                "[dirichlet] conditions that prevent it",
                                m->cell_tag[c], desc);
    }
done:
  lac_free (G);
  lac_free (fixed);
  lac_free (ctr);
  lac_free (cell0);
  lac_free (comp);
  lac_free (p);
  return status;
}
