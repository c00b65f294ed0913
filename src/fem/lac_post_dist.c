/* lac_post_dist.c -- the stresses and errors of a linear run on the
 *                    processes that own the cells (see lac_post_dist.h)
 *                                                 [LAC (2), §5; ch. 13]
 *
 * 1. u and the exact solution from the root to every process;
 * 2. on each process, over its own cells: the sums of the nodal stresses
 *    and their counts, the squares of the errors;
 * 3. the sums to the root, which divides and takes the roots.
 */
#include "fem/lac_post_dist.h"

#ifdef LAC_HAVE_PETSC

#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_nodal.h"
#include "fem/lac_post.h"
#include "linalg/lac_petsc_env.h"

/* What every process works with: the root's arrays or its own. */
typedef struct post_work
{
  double *u;               /* the root's (only read) or owned            */
  double *sigma, *count;   /* nnodes * ns, nnodes: the sums             */
  double sq[4];            /* the errors' squares                        */
  char *mine;              /* owned, ncells: the own cells               */
  int has_exact;
  lac_exact exact;
} post_work;

/* Step 1 and the arrays of step 2 (root: p, else NULL). */
static int
receive (const lac_dist *d, const lac_post_request *p, post_work *w)
{
  const lac_mesh *m = lac_dist_mesh (d);
  size_t nn = m->nnodes;
  size_t ns = (size_t) lac_model_nstress (lac_dist_material (d)->model);
  int status = LAC_SUCCESS;
  if (p)
    {
      w->has_exact = p->exact != NULL;
      if (p->exact)
        w->exact = *p->exact;
      w->u = (double *) p->u;              /* the root sends it, unchanged */
      w->sigma = p->sigma;
    }
  else
    {
      w->u = lac_malloc ((size_t) m->dim * nn * sizeof *w->u);
      w->sigma = lac_malloc (nn * ns * sizeof *w->sigma);
    }
  w->count = lac_calloc (nn + 1, sizeof *w->count);
  w->mine = lac_malloc (m->ncells + 1);
  if (!w->u || !w->sigma || !w->count || !w->mine)
    status = LAC_ERRMSG (LAC_ENOMEM, "the stresses of %zu nodes", nn);
  if ((status = lac_petsc_agree (status))
      || (status = lac_petsc_bcast (&w->has_exact, sizeof w->has_exact))
      || (status = lac_petsc_bcast (&w->exact, sizeof w->exact))
      || (status = lac_petsc_bcast (w->u, (size_t) m->dim * nn
                                    * sizeof *w->u)))
    return status;
  memset (w->sigma, 0, nn * ns * sizeof *w->sigma);
  lac_dist_own_cells (d, w->mine);
  return LAC_SUCCESS;
}

/* Step 2 on this process's cells. */
static int
own_sums (const lac_dist *d, post_work *w)
{
  const lac_mesh *m = lac_dist_mesh (d);
  const lac_elastic *mat = lac_dist_material (d);
  int status = lac_post_stress_sum (m, mat, w->u, w->mine, w->sigma,
                                    w->count);
  memset (w->sq, 0, sizeof w->sq);
  if (!status && w->has_exact)
    status = lac_post_error_sums (m, mat->model, w->u, w->mine, lac_exact_u,
                                  lac_exact_grad, &w->exact, w->sq);
  return status;
}

int
lac_dist_post (const lac_dist *d, lac_post_request *p)
{
  const lac_mesh *m = lac_dist_mesh (d);
  post_work w;
  int status, root = p != NULL;
  memset (&w, 0, sizeof w);
  if (!m)
    LAC_ERROR (LAC_EINVAL, "the stresses on the processes need the cells "
               "K was assembled from");
  size_t nn = m->nnodes;
  size_t ns = (size_t) lac_model_nstress (lac_dist_material (d)->model);
  if (!(status = receive (d, p, &w))
      && !(status = lac_petsc_agree (own_sums (d, &w)))
      && !(status = lac_petsc_sum_to_root (w.sigma, nn * ns))
      && !(status = lac_petsc_sum_to_root (w.count, nn))
      && !(status = lac_petsc_sum_to_root (w.sq, 4)) && root)
    {
      lac_nodal_mean (m, lac_dist_material (d)->model, w.count, p->sigma,
                      p->vm);
      if (w.has_exact)
        lac_post_error_roots (w.sq, &p->err[0], &p->err[1], &p->err[2],
                              &p->err[3]);
    }
  if (!root)
    {
      lac_free (w.u);
      lac_free (w.sigma);
    }
  lac_free (w.count);
  lac_free (w.mine);
  return status;
}

#else /* LAC_HAVE_PETSC */

typedef int lac_post_dist_unused;       /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
