/* lac_newton_check.c -- no silent penetration (see lac_newton_check.h)
 *                                                   [LAC Alg. 1, line 10]
 */
#include "solve/lac_newton_check.h"

#include <math.h>
#include "base/lac_status.h"

int
lac_newton_check_lost (const lac_model_point *p, const char *active,
                       int dim, double pen_tol)
{
  for (size_t i = 0; p->lost && i < p->k; i++)
    {
      size_t m = lac_model_slot (p, i);
      double area = p->area ? p->area[i] : 1.0;
      double gap = area > 0 ? p->d[i] / area : 0.0;     /* a mean gap */
      double h = lac_model_h (p, i, dim);
      if (!(p->lost[i] > 0))
        continue;
      if (active[m])
        LAC_ERROR (LAC_EADMISS, "macro-element %zu is in contact, but the "
                   "pairing lost %.3g of its surface (%.3g paired): the "
                   "projections of its points onto the master failed "
                   "there (a master facet folded or far from flat?)", m,
                   p->lost[i], p->size ? p->size[i] : 0.0);
      if (pen_tol >= 0 && gap <= pen_tol * h)
        LAC_ERROR (LAC_EADMISS, "macro-element %zu is out of contact by a "
                   "mean gap of %.3g (%.3g of its size), but the pairing "
                   "lost %.3g of its surface (%.3g paired): the "
                   "projections of its points onto the master failed "
                   "there, and that part may pass into the master unseen "
                   "(a master facet folded or far from flat?)", m, gap,
                   h > 0 ? gap / h : 0.0, p->lost[i],
                   p->size ? p->size[i] : 0.0);
    }
  return LAC_SUCCESS;
}

int
lac_newton_check_covered (const lac_contact_model *m, const double *U,
                          double pen_tol, size_t *gained)
{
  const lac_contact_model_type *t = m->type;
  lac_contact_uncovered u;
  double umax = 0;
  int status;
  *gained = 0;
  if (pen_tol < 0 || !t->uncovered)
    return LAC_SUCCESS;
  if ((status = t->uncovered (m->self, U, pen_tol, &u)) || u.count == 0)
    return status;
  for (size_t j = 0; j < m->n; j++)
    umax = fmax (umax, fabs (U[j]));
  if (t->widen && (status = t->widen (m->self, U, 2 * umax + u.depth,
                                      gained)))
    return status;
  if (*gained > 0)
    return LAC_SUCCESS;
  LAC_ERROR (LAC_EADMISS, "macro-element %zu at (%.6g, %.6g, %.6g) has no "
             "contact multiplier (%s) and passes %.3g into the master (%.3g "
             "of its size; %zu macro-element%s beyond %g of their size): "
             "refine the master side, or lower [contact] epsilon",
             u.macro, u.x[0], u.x[1], u.x[2], u.paired ? "not admissible"
             : "not paired", u.depth, u.depth / u.h, u.count,
             u.count == 1 ? "" : "s", pen_tol);
}
