/* lac_run_steplog.c -- the records of the load steps of a run
 *                      (see lac_run_steplog.h)       [LAC §4.5, Alg. 1]
 */
#include "run/lac_run_steplog.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "contact/lac_contact.h"

void
lac_run_steplog_clear (lac_run_steplog *log)
{
  lac_free (log->factor);
  lac_free (log->step);
  lac_free (log->mult);
  lac_free (log->kept);
  lac_free (log->ukept);
  memset (log, 0, sizeof *log);
}

/* The load factors: `start` (if > 0), then n equal steps to `end`. */
static int
factors (const lac_scene_steps *st, double end, lac_run_steplog *log)
{
  int n = st->n > 0 ? st->n : 1;
  double t0 = st->start > 0 ? st->start : 0.0;
  size_t j = 0;
  log->nfactor = (size_t) n + (t0 > 0);
  log->factor = lac_malloc (log->nfactor * sizeof *log->factor);
  log->step = lac_calloc (log->nfactor, sizeof *log->step);
  if (!log->factor || !log->step)
    LAC_ERROR (LAC_ENOMEM, "%zu load steps", log->nfactor);
  if (t0 > 0)
    log->factor[j++] = t0;
  for (int k = 1; k <= n; k++)
    log->factor[j++] = k == n ? end : t0 + (end - t0) * (double) k / n;
  return LAC_SUCCESS;
}

int
lac_run_steplog_file (size_t j, size_t n, int K)
{
  return K > 0 && ((j + 1) % (size_t) K == 0 || j + 1 == n);
}

/* Room for the displacements of the step files before the last one. */
static int
kept_alloc (int K, size_t ndof, lac_run_steplog *log)
{
  size_t n = 0;
  for (size_t j = 0; j + 1 < log->nfactor; j++)
    n += (size_t) lac_run_steplog_file (j, log->nfactor, K);
  if (n == 0)
    return LAC_SUCCESS;
  log->kept = lac_malloc (n * sizeof *log->kept);
  log->ukept = lac_malloc (n * ndof * sizeof *log->ukept);
  if (!log->kept || !log->ukept)
    LAC_ERROR (LAC_ENOMEM, "displacements of %zu step files", n);
  return LAC_SUCCESS;
}

/* The node of the [steps] monitor group. */
static int
monitor (const lac_scene *sc, const lac_mesh *m, lac_run_steplog *log)
{
  const lac_scene_steps *st = &sc->steps;
  log->monitor = SIZE_MAX;
  if (!st->monitor)
    return LAC_SUCCESS;
  const lac_group *g = lac_mesh_group (m, st->monitor);
  if (!g || g->nnodes == 0)
    return lac_scene_error (sc, &st->sec, "monitor", LAC_EINVAL,
                            "%s in mesh '%s' (a physical point is best)",
                            g ? "the group has no node"
                              : "no physical group of that name",
                            sc->mesh.file);
  log->monitor = g->node[0];
  return LAC_SUCCESS;
}

int
lac_run_steplog_init (lac_run_steplog *log, const lac_scene *sc,
                      const lac_mesh *m, double end)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  int status;
  if ((status = factors (&sc->steps, end, log))
      || (status = monitor (sc, m, log)))
    return status;
  return kept_alloc (sc->steps.vtu_every, ndof, log);
}

void
lac_run_steplog_monitor (const lac_run_steplog *log, const lac_frames *fr,
                         const double *U, int dim, double *um)
{
  const double *R = log->monitor != SIZE_MAX
                    ? lac_frames_of (fr, log->monitor) : NULL;
  for (int k = 0; k < dim && log->monitor != SIZE_MAX; k++)
    {
      const double *u = U + log->monitor * (size_t) dim;
      um[k] = R ? 0 : u[k];
      for (int i = 0; R && i < dim; i++)       /* in the axes: R U~ */
        um[k] += R[3 * k + i] * u[i];
    }
}

double *
lac_run_steplog_keep (lac_run_steplog *log, size_t j, int K, const double *U,
                      size_t ndof)
{
  double *u;
  if (j + 1 >= log->nfactor || !lac_run_steplog_file (j, log->nfactor, K))
    return NULL;
  log->kept[log->nkept] = j;                      /* room: kept_alloc */
  u = log->ukept + log->nkept++ * ndof;
  memcpy (u, U, ndof * sizeof *u);
  return u;
}

int
lac_run_steplog_summary (const lac_run_steplog *log, int dim,
                         lac_summary *sum)
{
  const char *ax[3] = { "x", "y", "z" };
  double ext = 0;
  int status = LAC_SUCCESS;
  if (log->monitor == SIZE_MAX)
    return LAC_SUCCESS;
  for (size_t j = 0; j < log->nfactor; j++)
    if (fabs (log->step[j].um[dim - 1]) > fabs (ext))
      ext = log->step[j].um[dim - 1];
  for (int k = 0; k < dim && !status; k++)
    {
      char key[32];
      snprintf (key, sizeof key, "monitor_u%s", ax[k]);
      status = lac_summary_add (sum, key, "%.10e",
                                log->step[log->nfactor - 1].um[k]);
    }
  return status ? status : lac_summary_add (sum, "monitor_extreme", "%.10e",
                                            ext);
}

/* ---- the multipliers ---------------------------------------------------- */

static int
push_mult (lac_run_steplog *log, lac_run_mult_record **q)
{
  if (lac_grow (&log->mult, log->nmult + 1, &log->capmult,
                sizeof *log->mult, 256))
    LAC_ERROR (LAC_ENOMEM, "multiplier records");
  *q = &log->mult[log->nmult++];
  memset (*q, 0, sizeof **q);
  return LAC_SUCCESS;
}

/* The centroid of T^m cap Gamma_C of macro-element ml of pair pr. */
static int
centroid (const lac_mesh *geom, const lac_macro *M, const lac_pairing *P,
          size_t ml, double *x)
{
  int dim = geom->dim, nodes[LAC_MAX_FACE_NODES];
  double wsum = 0;
  lac_map mp;
  for (size_t j = M->ptr[ml]; j < M->ptr[ml + 1]; j++)
    for (size_t p = P->ptr[j]; p < P->ptr[j + 1]; p++)
      {
        int nn = lac_contact_facet_eval (geom, M->cell[j], M->face[j],
                                         P->xs + p * (size_t) (dim - 1),
                                         nodes, &mp);
        if (nn < 0)
          return -nn;
        wsum += P->w[p];
        for (int k = 0; k < dim; k++)
          x[k] += P->w[p] * mp.x[k];
      }
  for (int k = 0; k < dim && wsum > 0; k++)
    x[k] /= wsum;
  return LAC_SUCCESS;
}

int
lac_run_steplog_mults (lac_run_steplog *log, const lac_mesh *geom,
                       const lac_run_setup *st, lac_pairing *const *P,
                       const lac_contact *c, const lac_newton *loop,
                       int step)
{
  int status;
  for (size_t i = 0; c && i < c->k; i++)
    {
      lac_run_mult_record *q = NULL;
      size_t m = c->macro[i], pr = lac_contact_set_pair_of (&st->set, m);
      if ((status = push_mult (log, &q)))
        return status;
      q->step = step;
      q->macro = m;
      q->lambda = loop->lambda[m];
      q->gap = c->area[i] > 0 ? loop->d[m] / c->area[i] : 0.0;
      q->covered = c->area[i];
      q->active = loop->active[m];
      if (c->xpt)                               /* collocation points */
        memcpy (q->x, c->xpt + 3 * i, sizeof q->x);
      else if ((status = centroid (geom, st->macro[pr], P[pr],
                                   m - st->set.offset[pr], q->x)))
        return status;
    }
  return LAC_SUCCESS;
}
