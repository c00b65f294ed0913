/* lac_nodal.c -- nodal averages of a stress computed cell by cell
 *                                                      (see lac_nodal.h)
 */
#include "fem/lac_nodal.h"

#include <string.h>
#include "base/lac_mem.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"

int
lac_nodal_point (const lac_mesh *m, lac_cell_stress *f, const void *law,
                 const double *u, size_t c, const double *xi, double *s)
{
  if (!u || !xi || !s || c >= m->ncells)
    LAC_ERROR (LAC_EINVAL, "cell %zu out of range (%zu cells) or NULL "
               "argument", c, m->ncells);
  return f (m, law, u, c, xi, s);
}

/* lac_nodal_sum: sigma[a] += the stress of each cell (cells[c] != 0,
 * E[c] > 0) at its node a, evaluated by f; count[a] += 1 for each. */
int
lac_nodal_sum (const lac_mesh *m, lac_model model, const double *E,
               const char *cells, lac_cell_stress *f, const void *law,
               const double *u, double *sigma, double *count)
{
  int ns = lac_model_nstress (model), status = LAC_SUCCESS;
  double s[6];
  if (!u || !sigma || !count)
    LAC_ERROR (LAC_EINVAL, "displacement or output is NULL");
  for (size_t c = 0; c < m->ncells && !status; c++)
    {
      if ((cells && !cells[c]) || !(E[c] > 0.0))
        continue;
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      if (!re)
        {
          status = LAC_ERRMSG (LAC_EINVAL, "cell %zu has an unknown type", c);
          break;
        }
      const int *conn = m->conn + m->ptr[c];
      for (int a = 0; a < re->nnodes && !status; a++)
        {
          status = f (m, law, u, c, re->xi + a * re->dim, s);
          for (int k = 0; k < ns && !status; k++)
            sigma[(size_t) conn[a] * (size_t) ns + (size_t) k] += s[k];
          count[conn[a]] += 1.0;
        }
    }
  return status;
}

void
lac_nodal_mean (const lac_mesh *m, lac_model model, const double *count,
                double *sigma, double *vm)
{
  int ns = lac_model_nstress (model);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      if (count[a] > 0)
        for (int k = 0; k < ns; k++)
          sigma[a * (size_t) ns + (size_t) k] /= count[a];   /* mean */
      if (vm)
        vm[a] = lac_von_mises (model, sigma + a * (size_t) ns);
    }
}

/* lac_nodal_average: sigma at the nodes = the mean over the cells sharing
 * a node (cells[c] != 0, E[c] > 0) of the cell's stress there, evaluated
 * by f; vm (may be NULL) its von Mises value.
 *   [out] sigma  nnodes*ns, vm  nnodes
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ENOMEM, or f's error */
int
lac_nodal_average (const lac_mesh *m, lac_model model, const double *E,
                   const char *cells, lac_cell_stress *f, const void *law,
                   const double *u, double *sigma, double *vm)
{
  int ns = lac_model_nstress (model), status;
  double *count;
  if (!u || !sigma)
    LAC_ERROR (LAC_EINVAL, "displacement or output is NULL");
  if (!(count = lac_calloc (m->nnodes + 1, sizeof *count)))
    LAC_ERROR (LAC_ENOMEM, "counters for %zu nodes", m->nnodes);
  memset (sigma, 0, m->nnodes * (size_t) ns * sizeof *sigma);
  status = lac_nodal_sum (m, model, E, cells, f, law, u, sigma, count);
  if (!status)
    lac_nodal_mean (m, model, count, sigma, vm);
  lac_free (count);
  return status;
}
