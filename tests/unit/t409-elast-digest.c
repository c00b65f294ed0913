/* t409: the digest of K (lac_assembly_digest) against the whole K
 *                                                        [LAC §4.3]
 *
 * On distorted box meshes of several element types and models, with
 * Dirichlet values that are zero on some groups, nonzero on others and
 * given twice for some dofs (the later wins), and a few cells of no body
 * (E = 0): the right-hand side and the number of entries that
 * lac_assembly_digest gives must equal, bit for bit, those of
 * lac_assembly_stiffness_csc + lac_dirichlet_apply; with every value
 * zero, b is F with zeros on the fixed dofs.  A fixed dof of a node in
 * no cell of a body is refused by both with the same status.  Out of
 * memory at every allocation: LAC_ENOMEM and no count left, then the
 * same numbers.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_assembly.h"
#include "fem/lac_assembly_digest.h"

/* The whole-K reference: b, nnz. */
static int
reference (const lac_mesh *m, const lac_elastic *mat, const lac_dirichlet *d,
           double *b, size_t *nnz)
{
  lac_csc *K = NULL;
  int status = lac_assembly_stiffness_csc (m, mat, &K);
  if (!status)
    {
      *nnz = (size_t) K->p[K->ncol];
      status = lac_dirichlet_apply (d, K, b);
    }
  lac_csc_free (K);
  return status;
}

/* The digest of F against the reference b, nnz (what: the case). */
static void
compare (const lac_mesh *m, const lac_elastic *mat, const lac_dirichlet *d,
         const double *F, const double *b, size_t nnz, const char *what)
{
  size_t ndof = (size_t) m->dim * m->nnodes, count = 0;
  double *f = lac_malloc (ndof * sizeof *f);
  memcpy (f, F, ndof * sizeof *f);
  check_status (lac_assembly_digest (m, mat, d, f, &count), LAC_SUCCESS,
                "%s: digest", what);
  check_true (!memcmp (f, b, ndof * sizeof *f), "%s: b bit for bit", what);
  check_int ((long) count, (long) nnz, "%s: entries", what);
  lac_free (f);
}

static void
run (lac_elem_type type, lac_model model)
{
  const lac_refelem *re = lac_refelem_get (type);
  const char *name = re->name, *mname = lac_model_name (model);
  int dim = lac_model_dim (model);
  size_t n[3] = { 4, 3, 2 };
  double L[3] = { 1.0, 1.3, 0.9 };
  lac_mesh *m = NULL;
  int status = lac_mesh_box (type, n, L, 0.2, &m);
  check_status (status, LAC_SUCCESS, "%s %s: box mesh", name, mname);
  if (status)
    return;
  if (model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      m->x[2 * a] += 1.0;                             /* r in [1, 2] */
  size_t ndof = (size_t) dim * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_malloc (ndof * sizeof *F);
  double *b = lac_malloc (ndof * sizeof *b);
  char what[64];
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = 200.0 + (double) (c % 5);
      nu[c] = 0.3;
    }
  for (size_t j = 0; j < ndof; j++)
    F[j] = sin (0.37 * (double) j);
  lac_elastic mat = { model, E, nu };
  lac_dirichlet *d = lac_dirichlet_alloc ();
  check_status (lac_dirichlet_add_group (d, m, lac_mesh_group (m, "xmin"), 0,
                                         0.0), LAC_SUCCESS, "xmin");
  for (int c = 0; c < dim; c++)
    check_status (lac_dirichlet_add_group (d, m, lac_mesh_group (m, "ymin"), c,
                                           1e-3 * (c + 1)), LAC_SUCCESS,
                  "ymin");
  check_status (lac_dirichlet_add_group (d, m, lac_mesh_group (m, "xmax"), 1,
                                         -2e-3), LAC_SUCCESS, "xmax");
  check_status (lac_dirichlet_add_group (d, m, lac_mesh_group (m, "ymin"), 0,
                                         5e-3), LAC_SUCCESS, "ymin again");
  char *fixed = lac_calloc (m->nnodes, 1);       /* holes: every 7th cell */
  for (size_t k = 0; k < d->n; k++)               /* with no fixed node   */
    fixed[d->dof[k] / (size_t) dim] = 1;
  for (size_t c = 3; c < m->ncells; c += 7)
    {
      int free_cell = 1;
      for (size_t q = m->ptr[c]; q < m->ptr[c + 1]; q++)
        free_cell &= !fixed[m->conn[q]];
      E[c] = free_cell ? 0.0 : E[c];
    }
  lac_free (fixed);
  size_t nnz_ref = 0;
  memcpy (b, F, ndof * sizeof *b);
  status = reference (m, &mat, d, b, &nnz_ref);
  check_status (status, LAC_SUCCESS, "%s %s: the whole K", name, mname);
  snprintf (what, sizeof what, "%s %s", name, mname);
  if (!status)
    compare (m, &mat, d, F, b, nnz_ref, what);
  for (size_t k = 0; k < d->n; k++)                  /* every value zero */
    d->val[k] = 0.0;
  memcpy (b, F, ndof * sizeof *b);
  status = reference (m, &mat, d, b, &nnz_ref);
  snprintf (what, sizeof what, "%s %s, g = 0", name, mname);
  if (!status)
    compare (m, &mat, d, F, b, nnz_ref, what);
  lac_dirichlet_free (d);
  lac_free (b);
  lac_free (F);
  lac_free (nu);
  lac_free (E);
  lac_mesh_free (m);
}

/* A fixed dof whose node is in no cell of a body: both refuse it. */
static void
orphan (void)
{
  size_t n[3] = { 2, 2, 2 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  if (lac_mesh_box (LAC_QUAD4, n, L, 0.0, &m))
    return;
  size_t ndof = 2 * m->nnodes;
  double E[4] = { 0, 1, 1, 1 }, nu[4] = { 0.3, 0.3, 0.3, 0.3 };
  double *F = lac_calloc (ndof, sizeof *F);
  size_t nnz = 0;
  lac_elastic mat = { LAC_PLANE_STRAIN, E, nu };
  lac_dirichlet *d = lac_dirichlet_alloc ();
  size_t a0 = (size_t) m->conn[m->ptr[0]];      /* a corner of cell 0 only */
  lac_dirichlet_add (d, 2 * a0, 1.0);
  int want = reference (m, &mat, d, F, &nnz);
  check_status (want, LAC_EINVAL, "orphan fixed dof: the whole K refuses it");
  check_status (lac_assembly_digest (m, &mat, d, F, &nnz), want,
                "orphan fixed dof: the digest refuses it too");
  check_message ("no diagonal entry", "orphan: the message");
  lac_dirichlet_free (d);
  lac_free (F);
  lac_mesh_free (m);
}

/* Out of memory at the k-th allocation, for every k until it succeeds. */
static void
no_memory (void)
{
  size_t n[3] = { 3, 2, 2 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  if (lac_mesh_box (LAC_HEX8, n, L, 0.1, &m))
    return;
  size_t ndof = 3 * m->nnodes;
  double *E = lac_malloc (m->ncells * sizeof *E);
  double *nu = lac_malloc (m->ncells * sizeof *nu);
  double *F = lac_malloc (ndof * sizeof *F), *f = lac_malloc (ndof * 8);
  double *b = lac_malloc (ndof * sizeof *b);
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = 100, nu[c] = 0.25;
  for (size_t j = 0; j < ndof; j++)
    F[j] = cos ((double) j);
  lac_elastic mat = { LAC_SOLID3D, E, nu };
  lac_dirichlet *d = lac_dirichlet_alloc ();
  for (int c = 0; c < 3; c++)
    lac_dirichlet_add_group (d, m, lac_mesh_group (m, "zmin"), c, 1e-3 * c);
  size_t nnz = 0, count = 0;
  memcpy (b, F, ndof * sizeof *b);
  int status = reference (m, &mat, d, b, &nnz);
  long k;
  for (k = 0; k < 10000 && !status; k++)
    {
      memcpy (f, F, ndof * sizeof *f);
      lac_mem_fail_after (k);
      status = lac_assembly_digest (m, &mat, d, f, &count);
      lac_mem_fail_after (-1);
      if (status == LAC_SUCCESS)
        break;
      check_status (status, LAC_ENOMEM, "no memory at allocation %ld", k);
      check_true (count == 0, "no memory at allocation %ld: no count left",
                  k);
      status = status == LAC_ENOMEM ? LAC_SUCCESS : status;
    }
  check_true (k > 5 && k < 10000, "no memory: the loop ends (%ld "
              "allocations)", k);
  check_true (!status && !memcmp (f, b, ndof * sizeof *f) && count == nnz,
              "no memory: the same numbers after the loop");
  lac_dirichlet_free (d);
  lac_free (b);
  lac_free (f);
  lac_free (F);
  lac_free (nu);
  lac_free (E);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  run (LAC_HEX8, LAC_SOLID3D);
  run (LAC_HEX20, LAC_SOLID3D);
  run (LAC_TET10, LAC_SOLID3D);
  run (LAC_QUAD8, LAC_PLANE_STRAIN);
  run (LAC_TRI3, LAC_PLANE_STRAIN);
  run (LAC_QUAD4, LAC_AXISYMMETRIC);
  orphan ();
  no_memory ();
  lac_finalize ();
  return check_summary ();
}
