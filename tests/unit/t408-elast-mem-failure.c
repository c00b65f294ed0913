/* t408: every allocation failure in assembly and post-processing is
 *       reported as LAC_ENOMEM, without a crash or a leak (CSparse's loop)
 *
 * For k = 0, 1, 2, ... the k-th allocation from the start of the sequence
 * fails; the sequence must answer LAC_ENOMEM until k is past its last
 * allocation, and then succeed with the same result as without failures.
 * Run under AddressSanitizer (make test-asan) to catch leaks.
 */
#include <math.h>
#include <stdio.h>
#include "check.h"
#include "fem/lac_assembly.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "fem/lac_post.h"
#include "base/lac_status.h"

static void
one (const double *x, void *ctx, double *out)
{
  (void) ctx;
  out[0] = 1.0 + x[1];
  out[1] = -x[0];
}

static void
grad (const double *x, void *ctx, double *out)
{
  (void) x;
  (void) ctx;
  out[0] = 0; out[1] = 1; out[2] = -1; out[3] = 0;
}

/* The sequence under test; returns a status and a checksum of the results. */
static int
sequence (const lac_mesh *m, const lac_elastic *mat, double *sum)
{
  size_t ndof = 2 * m->nnodes;
  int status = LAC_SUCCESS;
  double *F = lac_calloc (ndof, sizeof *F);
  double *sig = lac_calloc (4 * m->nnodes, sizeof *sig);
  lac_triplet *T = lac_triplet_alloc (ndof, ndof, 4);
  lac_dirichlet *d = lac_dirichlet_alloc ();
  lac_csc *K = NULL;
  double Ke[18 * 18], l2 = 0, h1 = 0;
  if (!F || !sig || !T || !d)
    {
      status = LAC_ENOMEM;
      goto done;
    }
  status = lac_assembly_cell_stiffness (m, mat, 0, Ke);
  if (!status)
    status = lac_assembly_stiffness (m, mat, T);
  if (!status)
    status = lac_assembly_volume_force (m, mat->model, NULL, one, NULL, F);
  if (!status)
    status = lac_assembly_traction (m, mat->model, lac_mesh_group (m, "xmax"),
                                    one, NULL, F);
  if (!status)
    status = lac_assembly_pressure (m, mat->model, lac_mesh_group (m, "ymax"),
                                    2.0, F);
  for (int k = 0; k < 40 && !status; k++)   /* grow the list several times */
    status = lac_dirichlet_add_group (d, m, lac_mesh_group (m, "xmin"), k % 2,
                                      0.0);
  if (!status)
    status = lac_dirichlet_add_field (d, m, lac_mesh_group (m, "ymin"), one,
                                      NULL);
  if (!status)
    {
      K = lac_csc_from_triplet (T);
      status = K ? lac_dirichlet_apply (d, K, F) : LAC_ENOMEM;
    }
  if (!status)
    status = lac_post_stress_nodal (m, mat, F, NULL, sig, NULL);
  if (!status)
    status = lac_post_errors (m, mat->model, F, one, grad, NULL, &l2, &h1,
                              NULL, NULL);
  if (!status)
    {
      *sum = l2 + h1;
      for (size_t i = 0; i < ndof; i++)
        *sum += F[i];
      for (size_t i = 0; i < 4 * m->nnodes; i++)
        *sum += sig[i];
    }
done:
  lac_csc_free (K);
  lac_dirichlet_free (d);
  lac_triplet_free (T);
  lac_free (sig);
  lac_free (F);
  return status;
}

int
main (void)
{
  lac_init ();
  const lac_elem_type types[2] = { LAC_QUAD9, LAC_TRI6 };
  for (int t = 0; t < 2; t++)
    {
      size_t n[2] = { 2, 2 };
      double L[2] = { 1, 1 }, E[8], nu[8], ref = 0, got = 0;
      lac_mesh *m = NULL;
      lac_mesh_box (types[t], n, L, 0.1, &m);
      for (size_t c = 0; c < m->ncells; c++)
        {
          E[c] = 10.0;
          nu[c] = 0.2;
        }
      for (size_t a = 0; a < m->nnodes; a++)
        m->x[2 * a] += 1.0;            /* axisymmetric: r in [1, 2] */
      lac_elastic mat = { t ? LAC_AXISYMMETRIC : LAC_PLANE_STRAIN, E, nu };
      int status = sequence (m, &mat, &ref);
      check_status (status, LAC_SUCCESS, "%s: without failures",
                    lac_refelem_get (types[t])->name);
      long k;
      for (k = 0; k < 10000; k++)
        {
          lac_mem_fail_after (k);
          got = 0;
          status = sequence (m, &mat, &got);
          lac_mem_fail_after (-1);
          if (status == LAC_SUCCESS)
            break;
          if (status != LAC_ENOMEM)
            {
              check_status (status, LAC_ENOMEM, "%s: failure at allocation"
                            " %ld", lac_refelem_get (types[t])->name, k);
              break;
            }
        }
      check_true (k > 5 && k < 10000, "%s: the loop ends (%ld allocations)",
                  lac_refelem_get (types[t])->name, k);
      check_rel (got, ref, 1e-14, "%s: same result after the loop",
                 lac_refelem_get (types[t])->name);
      lac_mesh_free (m);
    }
  lac_finalize ();
  return check_summary ();
}
