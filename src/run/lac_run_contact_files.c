/* lac_run_contact_files.c -- contact.csv and contact.vtu
 *                            (see lac_run_contact_files.h)
 */
#include "run/lac_run_contact_files.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_file.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "io/lac_vtu.h"

/* ",value" or "," for a value that does not exist (NAN). */
static void
field (FILE *f, double v)
{
  if (isnan (v))
    fputc (',', f);
  else
    fprintf (f, ",%.10e", v);
}

/* The pair of row m (node-to-segment: its one pair). */
static size_t
pair_of (const lac_run_contact_data *d, size_t m)
{
  const lac_contact_set *set = &d->setup->set;
  return d->contact->xpt ? 0 : lac_contact_set_pair_of (set, m);
}

/* The multiplier columns of row m (empty without a multiplier). */
static void
multiplier_fields (FILE *f, const lac_run_contact_data *d, size_t m)
{
  const lac_contact *c = d->contact;
  long i = c->mult[m];
  if (i < 0)
    {
      fprintf (f, ",,,,,");
      return;
    }
  fprintf (f, ",%ld", i);
  field (f, d->newton->lambda[m]);
  field (f, d->has_exact ? d->mult->exact[i] : NAN);
  field (f, c->area[i] > 0 ? d->newton->d[m] / c->area[i] : NAN);
  fprintf (f, ",%d", d->newton->active[m]);
}

/* Friction's columns of row m: lambda_t (per component), the status and
 * the slip (the mean tangential jump, per component) of its multiplier;
 * empty without a multiplier. */
static void
friction_fields (FILE *f, const lac_run_contact_data *d, size_t m)
{
  const lac_contact *c = d->contact;
  const lac_newton *s = d->newton;
  size_t nt = (size_t) c->ntan;
  long i = c->mult[m];
  static const char *const words[] = { "inactive", "stick", "slip" };
  for (size_t b = 0; b < nt; b++)
    field (f, i >= 0 ? s->lambda_t[m * nt + b] : NAN);
  fprintf (f, ",%s", i >= 0 && s->active[m] >= 0 && s->active[m] <= 2
           ? words[(int) s->active[m]] : "");
  for (size_t b = 0; b < nt; b++)
    field (f, i >= 0 && c->area[i] > 0 ? s->slip_conv[m * nt + b]
              / c->area[i] : NAN);
}

int
lac_run_contact_csv (const lac_run_contact_data *d, const char *path)
{
  const lac_contact *c = d->contact;
  const lac_run_contact *w = d->where;
  int dim = d->mesh->dim;
  FILE *f;
  int status = lac_file_create (path, "w", &f);
  if (status)
    return status;
  fprintf (f, "macro,x,y,z,measure,covered,criterion,admissible,"
           "multiplier,lambda,lambda_exact,mean_gap,active,s,force_x,"
           "force_y,force_z,%spair\n", c->ntan == 1
           ? "lambda_t,status,slip," : c->ntan == 2
           ? "lambda_t1,lambda_t2,status,slip1,slip2," : "");
  for (size_t m = 0; m < c->nmacro; m++)
    {
      long i = c->mult[m];
      fprintf (f, "%zu", m);
      for (int k = 0; k < 3; k++)
        field (f, k < dim ? w->x[3 * m + (size_t) k] : NAN);
      fprintf (f, ",%.10e,%.10e,%.10e,%d", c->meas[m], c->covered[m],
               c->crit[m], c->admissible[m]);
      multiplier_fields (f, d, m);
      field (f, w->s[m]);
      for (int k = 0; k < 3; k++)
        field (f, i >= 0 && k < dim ? w->force[3 * (size_t) i + (size_t) k]
                                    : NAN);
      if (c->ntan)
        friction_fields (f, d, m);
      fprintf (f, ",%s\n", d->sc->contact[pair_of (d, m)].sec.name);
    }
  return lac_file_close (f, path);
}

/* ---- contact.vtu ------------------------------------------------------- */

typedef struct surface
{
  size_t nf, np;        /* facets, points                            */
  long *local;          /* owned, nnodes: point of a mesh node, -1   */
  long *conn, *off;     /* owned: VTK cells                          */
  unsigned char *type;  /* owned                                     */
  int *node;            /* owned, np: the mesh node of a point       */
} surface;

static void
surface_free (surface *s)
{
  lac_free (s->local), lac_free (s->conn), lac_free (s->off);
  lac_free (s->type), lac_free (s->node);
}

/* The slave sub-facets of every pair, pair after pair, as VTK cells on
 * their own points. */
static int
surface_build (const lac_mesh *m, const lac_run_setup *st, surface *s)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  size_t nc = 0, j = 0;
  s->nf = 0;
  for (size_t p = 0; p < st->npairs; p++)
    s->nf += st->macro[p]->ptr[st->macro[p]->n];
  s->local = lac_malloc ((m->nnodes + 1) * sizeof *s->local);
  s->conn = lac_malloc ((s->nf * LAC_MAX_FACE_NODES + 1) * sizeof *s->conn);
  s->off = lac_malloc ((s->nf + 1) * sizeof *s->off);
  s->type = lac_malloc (s->nf + 1);
  s->node = lac_malloc ((s->nf * LAC_MAX_FACE_NODES + 1) * sizeof *s->node);
  if (!s->local || !s->conn || !s->off || !s->type || !s->node)
    LAC_ERROR (LAC_ENOMEM, "contact surface of %zu facets", s->nf);
  for (size_t a = 0; a < m->nnodes; a++)
    s->local[a] = -1;
  for (size_t p = 0; p < st->npairs; p++)
    for (size_t q = 0; q < st->macro[p]->ptr[st->macro[p]->n]; q++, j++)
      {
        const lac_macro *M = st->macro[p];
        int n = lac_mesh_facet_nodes (m, M->cell[q], M->face[q], nodes, &ft);
        const lac_refelem *re = lac_refelem_get (ft);
        if (n <= 0 || !re)
          LAC_ERROR (LAC_ESANITY, "slave facet %zu has no nodes", q);
        for (int k = 0; k < n; k++)            /* VTK node k = gmsh node */
          {
            int a = nodes[re->vtk_perm[k]];
            if (s->local[a] < 0)
              {
                s->node[s->np] = a;
                s->local[a] = (long) s->np++;
              }
            s->conn[nc++] = s->local[a];
          }
        s->off[j] = (long) nc;
        s->type[j] = (unsigned char) re->vtk_type;
      }
  return LAC_SUCCESS;
}

/* Per facet (LAC) or per node (nts): lambda, mean gap, status. */
static void
status_of (const lac_run_contact_data *d, size_t m, double *lam, double *gap,
           int *st)
{
  const lac_contact *c = d->contact;
  long i = m < c->nmacro ? c->mult[m] : -1;
  *lam = i >= 0 ? d->newton->lambda[m] : NAN;
  *gap = i >= 0 && c->area[i] > 0 ? d->newton->d[m] / c->area[i] : NAN;
  *st = i >= 0 ? d->newton->active[m] : -1;
}

/* The macro-element (slot) and the pair of every facet of the surface. */
static void
facet_slots (const lac_run_setup *st, int *mac, int *pair)
{
  size_t j = 0;
  for (size_t p = 0; p < st->npairs; p++)
    for (size_t m = 0; m < st->macro[p]->n; m++)
      for (size_t q = st->macro[p]->ptr[m]; q < st->macro[p]->ptr[m + 1];
           q++, j++)
        {
          mac[j] = (int) (st->set.offset[p] + m);
          pair[j] = (int) p;
        }
}

/* Friction: lambda_t and the slip (the mean tangential jump of the last
 * converged step per unit measure) of every facet's macro-element, ntan
 * components each in the tangent frame of contact/lac_tangential.h (NAN
 * without a multiplier). */
static int
friction_vtu (const lac_run_contact_data *d, size_t n, const int *mac,
              lac_vtu *v)
{
  const lac_contact *c = d->contact;
  size_t nt = (size_t) c->ntan;
  double *lt = lac_malloc ((n * nt + 1) * sizeof *lt);
  double *sl = lac_malloc ((n * nt + 1) * sizeof *sl);
  int status = lt && sl ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "contact.vtu friction fields");
  for (size_t j = 0; !status && j < n; j++)
    for (size_t b = 0; b < nt; b++)
      {
        size_t m = (size_t) (mac[j] >= 0 ? mac[j] : 0);
        long i = mac[j] >= 0 ? c->mult[m] : -1;
        lt[j * nt + b] = i >= 0 ? d->newton->lambda_t[m * nt + b] : NAN;
        sl[j * nt + b] = i >= 0 && c->area[i] > 0
                         ? d->newton->slip_conv[m * nt + b] / c->area[i] : NAN;
      }
  if (!status)
    status = lac_vtu_f64 (v, LAC_VTU_CELL_DATA, "lambda_t", (int) nt, lt,
                          (int) nt, 0);
  if (!status)
    status = lac_vtu_f64 (v, LAC_VTU_CELL_DATA, "slip", (int) nt, sl,
                          (int) nt, 0);
  lac_free (lt);
  lac_free (sl);
  return status;
}

static int
surface_fields (const lac_run_contact_data *d, const surface *s, lac_vtu *v)
{
  const lac_contact *c = d->contact;
  int nts = c->xpt != NULL, dim = d->mesh->dim, status;
  size_t n = nts ? s->np : s->nf;
  double *u = lac_calloc (3 * s->np + 1, sizeof *u);
  double *lam = lac_malloc ((n + 1) * sizeof *lam);
  double *gap = lac_malloc ((n + 1) * sizeof *gap);
  int *st = lac_malloc ((n + 1) * sizeof *st), *mac = lac_malloc ((n + 1)
                                                                 * sizeof *mac);
  int *pair = lac_malloc ((s->nf + 1) * sizeof *pair);
  int *fmac = lac_malloc ((s->nf + 1) * sizeof *fmac);
  lac_vtu_section sec = nts ? LAC_VTU_POINT_DATA : LAC_VTU_CELL_DATA;
  status = u && lam && gap && st && mac && pair && fmac ? LAC_SUCCESS
           : LAC_ERRMSG (LAC_ENOMEM, "contact.vtu fields");
  if (!status)
    facet_slots (d->setup, fmac, pair);
  for (size_t p = 0; !status && p < s->np; p++)
    for (int k = 0; k < dim; k++)
      u[3 * p + (size_t) k] = d->u[(size_t) s->node[p] * (size_t) dim
                                   + (size_t) k];
  for (size_t j = 0; !status && j < n; j++)
    mac[j] = -1;
  for (size_t j = 0; !status && !nts && j < n; j++)    /* its facets */
    mac[j] = fmac[j];
  for (size_t m = 0; !status && nts && m < c->nmacro; m++)
    if (c->admissible[m] && s->local[c->inode[m]] >= 0)   /* its node */
      mac[s->local[c->inode[m]]] = (int) m;
  for (size_t j = 0; !status && j < n; j++)
    status_of (d, mac[j] >= 0 ? (size_t) mac[j] : SIZE_MAX, lam + j,
               gap + j, st + j);
  if (!status)
    status = lac_vtu_f64 (v, LAC_VTU_POINT_DATA, "displacement", 3, u, 3, 0);
  if (!status)
    status = lac_vtu_i32 (v, sec, "macro", mac);
  if (!status)
    status = lac_vtu_f64 (v, sec, "lambda", 1, lam, 1, 0);
  if (!status)
    status = lac_vtu_f64 (v, sec, "mean_gap", 1, gap, 1, 0);
  if (!status)
    status = lac_vtu_i32 (v, sec, "status", st);
  if (!status)
    status = lac_vtu_i32 (v, LAC_VTU_CELL_DATA, "pair", pair);
  if (!status && c->Ct && !nts)
    status = friction_vtu (d, n, mac, v);
  lac_free (u), lac_free (lam), lac_free (gap), lac_free (st), lac_free (mac);
  lac_free (pair), lac_free (fmac);
  return status;
}

int
lac_run_contact_vtu (const lac_run_contact_data *d, int ascii,
                     const char *path)
{
  surface s;
  lac_vtu *v = NULL;
  double *x = NULL;
  int status, dim = d->mesh->dim;
  memset (&s, 0, sizeof s);
  status = surface_build (d->mesh, d->setup, &s);
  if (!status && (!(v = lac_vtu_alloc (s.np, s.nf, ascii))
                  || !(x = lac_malloc ((3 * s.np + 1) * sizeof *x))))
    status = LAC_ERRMSG (LAC_ENOMEM, "contact.vtu of %zu points", s.np);
  for (size_t p = 0; !status && p < s.np; p++)
    for (int k = 0; k < 3; k++)
      x[3 * p + (size_t) k] = k < dim ? d->mesh->x[(size_t) s.node[p]
                                                   * (size_t) dim
                                                   + (size_t) k] : 0.0;
  if (!status)
    {
      lac_vtu_defaults (v, "displacement", d->contact->xpt ? "lambda" : NULL,
                        d->contact->xpt ? NULL : "lambda");
      if (!(status = lac_vtu_points (v, x, 3))
          && !(status = lac_vtu_cells (v, s.conn, s.off, s.type))
          && !(status = surface_fields (d, &s, v)))
        status = lac_vtu_write (v, path);
    }
  lac_free (x);
  lac_vtu_free (v);
  surface_free (&s);
  return status;
}
