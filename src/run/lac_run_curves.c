/* lac_run_curves.c -- the loads of a small-strain scene by load curve
 *                     (see lac_run_curves.h)          [LAC (8), Alg. 1]
 */
#include "run/lac_run_curves.h"

#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_assembly_digest.h"
#include "fem/lac_frames.h"
#include "run/lac_run_roller.h"

void
lac_run_curves_free (lac_run_curves *cv)
{
  if (!cv)
    return;
  lac_free (cv->curve);
  lac_free (cv->of_load);
  lac_free (cv->of_dirichlet);
  lac_free (cv->F);
  lac_free (cv->b);
  lac_free (cv->of_entry);
  lac_free (cv->g);
  lac_free (cv);
}

double
lac_run_curves_factor (const lac_run_curves *cv, size_t c, double t)
{
  const lac_run_curve *f = &cv->curve[c];
  return lac_scene_factor (f->pt, f->n, f->ramp, t);
}

/* ---- the curves of the sections --------------------------------------- */

static int
same_curve (const lac_run_curve *a, const lac_run_curve *b)
{
  if (a->n != b->n || (a->n == 0 && a->ramp != b->ramp))
    return 0;
  return a->n == 0 || !memcmp (a->pt, b->pt, (size_t) a->n * sizeof *a->pt);
}

/* The index of curve f in cv (added if new). */
static size_t
curve_index (lac_run_curves *cv, lac_run_curve f)
{
  for (size_t c = 0; c < cv->n; c++)
    if (same_curve (&cv->curve[c], &f))
      return c;
  cv->curve[cv->n] = f;
  return cv->n++;
}

lac_run_curves *
lac_run_curves_alloc (const lac_scene *sc, size_t ndof)
{
  size_t ns = sc->nload + sc->ndirichlet;
  lac_run_curves *cv = lac_calloc (1, sizeof *cv);
  if (cv)
    {
      cv->curve = lac_malloc ((ns + 1) * sizeof *cv->curve);
      cv->of_load = lac_malloc ((sc->nload + 1) * sizeof *cv->of_load);
      cv->of_dirichlet = lac_malloc ((sc->ndirichlet + 1)
                                     * sizeof *cv->of_dirichlet);
    }
  if (!cv || !cv->curve || !cv->of_load || !cv->of_dirichlet)
    {
      lac_run_curves_free (cv);
      LAC_ERROR_NULL (LAC_ENOMEM, "load curves of %zu sections", ns);
    }
  for (size_t k = 0; k < sc->nload; k++)      /* loads: f = t by default */
    cv->of_load[k] = curve_index (cv, (lac_run_curve) { sc->load[k].curve,
                                  sc->load[k].ncurve, 1 });
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      const lac_scene_dirichlet *d = &sc->dirichlet[k];
      cv->of_dirichlet[k] = curve_index (cv, (lac_run_curve) { d->curve,
                                         d->ncurve, d->ramp != 0 });
    }
  cv->ndof = ndof;
  cv->F = lac_calloc ((cv->n ? cv->n : 1) * ndof, sizeof *cv->F);
  cv->b = lac_calloc ((cv->n ? cv->n : 1) * ndof, sizeof *cv->b);
  if (!cv->F || !cv->b)
    {
      lac_run_curves_free (cv);
      LAC_ERROR_NULL (LAC_ENOMEM, "loads of %zu curves", cv->n);
    }
  return cv;
}

/* ---- the curve of each Dirichlet entry ---------------------------------- */

/* Two non-zero conditions of one dof, or of one node with a frame, from
 * [dirichlet first] and [dirichlet d], on different curves. */
static int
two_curves (const lac_scene *sc, const lac_mesh *m, size_t first, size_t d,
            size_t a, int frame)
{
  return lac_scene_error (sc, &sc->dirichlet[d].sec, NULL, LAC_EINVAL,
                          "node %zu has non-zero values from [dirichlet %s] "
                          "and from this section on different load curves "
                          "(curve or ramp)%s", m->node_tag[a],
                          sc->dirichlet[first].sec.name, frame ? ": a node "
                          "with a frame (normal = ...) follows one curve"
                          : "");
}

/* The curve of each dof from the conditions of the nodes, in the order
 * of the sections: that of its non-zero conditions (nz[q]: 1 + the
 * section of one), else of its last one.  A condition at a node with a
 * frame acts on every dof of the node, else on the dof of its axis. */
static int
dof_curves (const lac_scene *sc, const lac_mesh *m, const lac_frames *fr,
            const lac_run_conditions *cs, const lac_run_curves *cv,
            size_t *of, size_t *nz)
{
  size_t dim = (size_t) m->dim;
  for (size_t a = 0; a < m->nnodes; a++)
    for (size_t j = cs->ptr[a]; j < cs->ptr[a + 1]; j++)
      {
        const lac_run_condition *c = &cs->c[j];
        int frame = lac_frames_of (fr, a) != NULL;
        size_t i = 0, cur = cv->of_dirichlet[c->sec];
        while (!frame && i + 1 < dim && c->d[i] != 1)
          i++;                              /* its axis: dof a dim + i */
        for (size_t q = a * dim + i; q < a * dim + (frame ? dim : i + 1);
             q++)
          {
            if (c->v != 0 && nz[q] && cv->of_dirichlet[nz[q] - 1] != cur)
              return two_curves (sc, m, nz[q] - 1, c->sec, a, frame);
            if (c->v != 0)
              nz[q] = c->sec + 1;
            of[q] = nz[q] ? cv->of_dirichlet[nz[q] - 1] : cur;
          }
      }
  return LAC_SUCCESS;
}

int
lac_run_curves_entries (const lac_scene *sc, lac_model model,
                        const lac_mesh *m, const lac_dirichlet *dir,
                        lac_run_curves *cv)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  lac_run_conditions cs = { 0, NULL, NULL };
  size_t *of = lac_calloc (ndof + 1, sizeof *of);
  size_t *nz = lac_calloc (ndof + 1, sizeof *nz);
  int status = of && nz ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "curves of %zu dofs", ndof);
  if (!status && !(status = lac_run_conditions_build (sc, model, m, NULL,
                                                      &cs)))
    status = dof_curves (sc, m, dir->frames, &cs, cv, of, nz);
  cv->nentry = dir->n;
  cv->of_entry = status ? NULL : lac_malloc ((dir->n + 1)
                                             * sizeof *cv->of_entry);
  cv->g = status ? NULL : lac_malloc ((dir->n + 1) * sizeof *cv->g);
  if (!status && (!cv->of_entry || !cv->g))
    status = LAC_ERRMSG (LAC_ENOMEM, "curves of %zu entries", dir->n);
  for (size_t i = 0; !status && i < dir->n; i++)
    {
      cv->of_entry[i] = of[dir->dof[i]];
      cv->g[i] = dir->val[i];
    }
  lac_run_conditions_clear (&cs);
  lac_free (of);
  lac_free (nz);
  return status;
}

/* ---- b_c ---------------------------------------------------------------- */

void
lac_run_curves_tie (lac_run_curves *cv, const lac_run_ties *ties)
{
  for (size_t c = 0; c < cv->n; c++)
    {
      double *F = cv->F + c * cv->ndof;
      for (size_t k = 0; k < ties->n; k++)
        {
          F[ties->to[k]] += F[ties->dof[k]];
          F[ties->dof[k]] = 0;
        }
    }
}

/* The Dirichlet data of curve c alone: dir's dofs, the values of the
 * entries of curve c (0 for the others and for the entries after
 * cv->nentry), in val (dir->n). */
static lac_dirichlet
curve_values (const lac_run_curves *cv, size_t c, const lac_dirichlet *dir,
              double *val)
{
  lac_dirichlet d = { dir->n, dir->n, dir->dof, val, NULL };
  for (size_t i = 0; i < dir->n; i++)
    val[i] = i < cv->nentry && cv->of_entry[i] == c ? cv->g[i] : 0.0;
  return d;
}

/* b = b - K(:, j) g_j for the fixed dofs j in dof order, then b_j = d_j
 * g_j: lac_dirichlet_column's numbers, K left as it is. */
static void
lift (const lac_csc *K, const char *fixed, const double *g, double *b)
{
  for (size_t j = 0; j < K->ncol; j++)
    if (fixed[j] && g[j] != 0.0)
      for (int p = K->p[j]; p < K->p[j + 1]; p++)
        b[K->i[p]] -= K->x[p] * g[j];
  for (size_t j = 0; j < K->ncol; j++)
    if (fixed[j])
      {
        double d = 1.0;
        for (int p = K->p[j]; p < K->p[j + 1]; p++)
          if ((size_t) K->i[p] == j && K->x[p] > 0.0)
            d = K->x[p];
        b[j] = d * g[j];
      }
}

int
lac_run_curves_lift (lac_run_curves *cv, const lac_csc *K,
                     const lac_dirichlet *dir)
{
  double *val = lac_malloc ((dir->n + 1) * sizeof *val);
  int status = val ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "curve values");
  for (size_t c = 0; c < cv->n && !status; c++)
    {
      lac_dirichlet d = curve_values (cv, c, dir, val);
      double *b = cv->b + c * cv->ndof, *g = NULL;
      char *fixed = NULL;
      memcpy (b, cv->F + c * cv->ndof, cv->ndof * sizeof *b);
      lac_frames_to_local (dir->frames, b);                   /* T^T F_c */
      if (!(status = lac_dirichlet_dense (&d, cv->ndof, &fixed, &g)))
        lift (K, fixed, g, b);
      lac_free (fixed);
      lac_free (g);
    }
  lac_free (val);
  return status;
}

int
lac_run_curves_digest (lac_run_curves *cv, const lac_mesh *m,
                       const lac_elastic *mat, const lac_dirichlet *dir)
{
  double *val = lac_malloc ((dir->n + 1) * sizeof *val);
  int status = val ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "curve values");
  size_t nnz;
  for (size_t c = 0; c < cv->n && !status; c++)
    {
      lac_dirichlet d = curve_values (cv, c, dir, val);
      double *b = cv->b + c * cv->ndof;
      memcpy (b, cv->F + c * cv->ndof, cv->ndof * sizeof *b);
      status = lac_assembly_digest (m, mat, &d, b, &nnz);
    }
  lac_free (val);
  return status;
}

/* ---- a load step -------------------------------------------------------- */

void
lac_run_curves_set (const lac_run_curves *cv, double t, double *F,
                    double *b, lac_dirichlet *dir)
{
  memset (F, 0, cv->ndof * sizeof *F);
  memset (b, 0, cv->ndof * sizeof *b);
  for (size_t c = 0; c < cv->n; c++)
    {
      double f = lac_run_curves_factor (cv, c, t);
      const double *Fc = cv->F + c * cv->ndof, *bc = cv->b + c * cv->ndof;
      for (size_t q = 0; f != 0 && q < cv->ndof; q++)
        {
          F[q] += f * Fc[q];
          b[q] += f * bc[q];
        }
    }
  for (size_t i = 0; i < cv->nentry && i < dir->n; i++)
    dir->val[i] = lac_run_curves_factor (cv, cv->of_entry[i], t) * cv->g[i];
}
