/* lac_contact.c -- the contact data of one slave/master pair
 *                                       [LAC Def. 1, (16)-(18)]
 * Allocation, the two stages (lac_admissibility.c, lac_assembly_lac.c) and
 * the Dirichlet correction of C and G, the interference of G.
 */
#include "contact/lac_contact.h"

#include <math.h>
#include "contact/lac_admissibility.h"
#include "contact/lac_assembly_lac.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

lac_contact *
lac_contact_alloc (size_t nmacro)
{
  lac_contact *c = lac_calloc (1, sizeof *c);
  if (!c)
    return NULL;
  c->nmacro = nmacro;
  c->meas = lac_calloc (nmacro, sizeof *c->meas);
  c->covered = lac_calloc (nmacro, sizeof *c->covered);
  c->inode = lac_calloc (nmacro, sizeof *c->inode);
  c->phiint = lac_calloc (nmacro, sizeof *c->phiint);
  c->crit = lac_calloc (nmacro, sizeof *c->crit);
  c->admissible = lac_calloc (nmacro, 1);
  c->mult = lac_calloc (nmacro, sizeof *c->mult);
  c->macro = lac_calloc (nmacro, sizeof *c->macro);
  c->G = lac_calloc (nmacro, sizeof *c->G);
  c->area = lac_calloc (nmacro, sizeof *c->area);
  c->size = lac_calloc (nmacro, sizeof *c->size);
  c->lost = lac_calloc (nmacro, sizeof *c->lost);
  if (!c->meas || !c->covered || !c->inode || !c->phiint || !c->crit || !c->admissible
      || !c->mult || !c->macro || !c->G || !c->area || !c->size
      || !c->lost)
    {
      lac_contact_free (c);
      return NULL;
    }
  return c;
}

void
lac_contact_free (lac_contact *c)
{
  if (!c)
    return;
  lac_free (c->meas);
  lac_free (c->covered);
  lac_free (c->inode);
  lac_free (c->phiint);
  lac_free (c->crit);
  lac_free (c->admissible);
  lac_free (c->mult);
  lac_free (c->macro);
  lac_csc_free (c->C);
  lac_free (c->G);
  lac_free (c->area);
  lac_free (c->size);
  lac_free (c->lost);
  lac_free (c->xpt);
  lac_free (c->npt);
  lac_csc_free (c->Ct);
  lac_free (c->sfix);
  lac_free (c->mu);
  lac_free (c);
}

int
lac_contact_build (const lac_mesh *mesh, lac_model model, const lac_macro *M,
                   const lac_pairing *P, const lac_pairing_facets *master,
                   double epsilon, lac_contact **out)
{
  *out = NULL;
  lac_contact *c = lac_contact_alloc (M->n);
  if (!c)
    LAC_ERROR (LAC_ENOMEM, "contact data for %zu macro-elements", M->n);
  int st = lac_admissibility_compute (c, mesh, model, M, P, epsilon);
  if (!st && c->k == 0)
    {
      double best = 0;
      for (size_t m = 0; m < M->n; m++)
        best = fmax (best, c->crit[m]);
      st = LAC_ERRMSG (LAC_EADMISS, "no admissible macro-element among %zu: "
                       "largest phibar*sqrt(delta) = %.10g < epsilon = %.10g "
                       "[LAC Def. 1]", M->n, best, epsilon);
    }
  if (!st)
    st = lac_assembly_lac (c, mesh, model, M, P, master);
  if (st)
    {
      lac_contact_free (c);
      return st;
    }
  *out = c;
  return LAC_SUCCESS;
}

int
lac_contact_apply_dirichlet (lac_contact *c, size_t n, const size_t *dof,
                             const double *val)
{
  lac_csc *C = c->C;
  char *fixed = lac_calloc (C->nrow, 1);
  double *g = lac_calloc (C->nrow, sizeof *g);
  if (!fixed || !g)
    {
      lac_free (fixed);
      lac_free (g);
      LAC_ERROR (LAC_ENOMEM, "Dirichlet marks");
    }
  for (size_t t = 0; t < n; t++)
    if (dof[t] < C->nrow)
      {
        fixed[dof[t]] = 1;
        g[dof[t]] = val[t];                      /* later entries win */
      }
  for (size_t i = 0; i < C->ncol; i++)
    for (int p = C->p[i]; p < C->p[i + 1]; p++)
      if (fixed[C->i[p]])
        {
          c->G[i] -= C->x[p] * g[C->i[p]];      /* G_i -= C(dof,i) value */
          C->x[p] = 0;                          /* row of a fixed dof */
        }
  for (size_t i = 0; c->Ct && i < c->Ct->ncol; i++)     /* friction */
    for (int p = c->Ct->p[i]; p < c->Ct->p[i + 1]; p++)
      if (fixed[c->Ct->i[p]])
        {
          c->sfix[i] += c->Ct->x[p] * g[c->Ct->i[p]];
          c->Ct->x[p] = 0;
        }
  lac_free (fixed);
  lac_free (g);
  return LAC_SUCCESS;
}

int
lac_contact_to_frames (lac_contact *c, const lac_frames *f)
{
  int status = lac_frames_rotate_rows (f, &c->C);
  if (!status && c->Ct)
    status = lac_frames_rotate_rows (f, &c->Ct);
  return status;
}

int
lac_contact_set_offset (lac_contact *c, double delta)
{
  if (!isfinite (delta))
    LAC_ERROR (LAC_EINVAL, "interference %g: expected a finite length",
               delta);
  for (size_t i = 0; i < c->k; i++)
    c->G[i] -= (delta - c->offset) * c->area[i];  /* int (g0 - delta) */
  c->offset = delta;
  return LAC_SUCCESS;
}

long
lac_contact_mult_of_subfacet (const lac_contact *c, const lac_macro *M,
                              size_t j)
{
  size_t lo = 0, hi = M->n;             /* ptr is increasing: bisection */
  if (j >= M->ptr[M->n])
    return -1;
  while (hi - lo > 1)
    {
      size_t mid = (lo + hi) / 2;
      if (M->ptr[mid] <= j)
        lo = mid;
      else
        hi = mid;
    }
  return c->mult[lo];
}
