/* lac_run_reaction.c -- the reaction force of every Dirichlet section
 *                       (see lac_run_reaction.h)      [LAC (4), (8), (17)]
 */
#include "run/lac_run_reaction.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_frames.h"
#include "run/lac_run_roller.h"

/* ---- r = f_int(u) - F - C lambda at the fixed nodes ------------------- */

/* r += f_int of cell c (K_e u_e, or the hyperelastic internal force). */
static int
cell_force (const lac_run_reaction_in *in, size_t c, double *work, double *r)
{
  const lac_mesh *m = in->mesh;
  size_t dofs[LAC_MAX_NODES * 3];
  int n = lac_mesh_cell_dofs (m, c, dofs), status;
  double *fe = work, *Ke = work + n;
  memset (fe, 0, (size_t) n * sizeof *fe);
  if (in->large)
    status = lac_hyper_cell (m, &in->mat->hyper, c, in->u, fe, NULL);
  else if (!(status = lac_assembly_cell_stiffness (m, &in->mat->elastic, c,
                                                   Ke)))
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
        fe[i] += Ke[i * n + j] * in->u[dofs[j]];          /* K_e u_e */
  for (int i = 0; !status && i < n; i++)
    r[dofs[i]] += fe[i];
  return status;
}

/* r = f_int(u) - F over the cells with a node in `fixed` (E > 0). */
static int
internal_force (const lac_run_reaction_in *in, const char *fixed, double *r)
{
  const lac_mesh *m = in->mesh;
  size_t nmax = LAC_MAX_NODES * 3;
  double *work = lac_malloc ((nmax + nmax * nmax) * sizeof *work);
  int status = work ? LAC_SUCCESS : LAC_ERRMSG (LAC_ENOMEM, "reactions");
  for (size_t k = 0; k < (size_t) m->dim * m->nnodes; k++)
    r[k] = -in->F[k];
  for (size_t c = 0; !status && c < m->ncells; c++)
    {
      int touch = 0;
      for (size_t k = m->ptr[c]; k < m->ptr[c + 1]; k++)
        touch |= fixed[m->conn[k]];
      if (touch && in->mat->E[c] > 0)
        status = cell_force (in, c, work, r);
    }
  lac_free (work);
  return status;
}

/* r -= C lambda, C of every pair at x = X + u (large) or X, side by
 * side (contact/lac_contact_set.h), in the axes. */
static int
contact_force (const lac_run_reaction_in *in, double *r)
{
  const lac_mesh *m = in->mesh;
  size_t n = (size_t) m->dim * m->nnodes;
  double *x = in->large ? lac_malloc (n * sizeof *x) : NULL;
  lac_contact_set_data d = { 0 };
  int status = !in->large || x ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "reactions");
  for (size_t k = 0; x && k < n; k++)
    x[k] = m->x[k] + in->u[k];
  if (!status)
    status = lac_contact_set_build (in->set, x, &d);
  const lac_contact *c = d.all;
  for (size_t i = 0; !status && c && i < c->k; i++)
    for (int q = c->C->p[i]; q < c->C->p[i + 1]; q++)
      r[c->C->i[q]] -= c->C->x[q] * in->lambda[c->macro[i]];
  lac_contact_set_data_clear (&d);
  lac_free (x);
  return status;
}

/* ---- r_a split among the conditions at node a -------------------------- */

/* Room for the conditions of one node: directions, values (0), flags. */
typedef struct split_work
{
  double *d, *v;
  char *indep;
} split_work;

/* R[sec] += mu_j d_j, r_a = sum_j mu_j d_j over the conditions at a that
 * fix a new direction (mu: M^T mu = rho, M[s][k] = d_s . q_k lower
 * triangular, rho_k = q_k . r_a). */
static int
split (int dim, const lac_run_condition *c, size_t n, const double *ra,
       split_work *ws, double *R)
{
  double Q[9], w[3], M[3][3], rho[3], mu[3];
  size_t idx[3], bad, with;
  int rank = 0, t = 0;
  for (size_t j = 0; j < n; j++)
    memcpy (ws->d + 3 * j, c[j].d, sizeof c[j].d), ws->v[j] = 0;
  if (lac_frames_basis (dim, n, ws->d, ws->v, Q, w, ws->indep, &rank, &bad,
                        &with))
    LAC_ERROR (LAC_ESANITY, "zero values contradict each other");
  for (size_t j = 0; j < n; j++)
    if (ws->indep[j])
      idx[t++] = j;
  for (int k = 0; k < rank; k++)
    {
      rho[k] = 0;
      for (int i = 0; i < 3; i++)
        rho[k] += Q[3 * i + k] * ra[i];                  /* q_k . r_a */
      for (int s = 0; s < rank; s++)
        {
          M[s][k] = 0;
          for (int i = 0; i < 3; i++)
            M[s][k] += ws->d[3 * idx[s] + i] * Q[3 * i + k];
        }
    }
  for (int s = rank - 1; s >= 0; s--)           /* M^T mu = rho, upper */
    {
      mu[s] = rho[s];
      for (int z = s + 1; z < rank; z++)
        mu[s] -= M[z][s] * mu[z];
      mu[s] /= M[s][s];
    }
  for (int s = 0; s < rank; s++)
    for (int i = 0; i < 3; i++)
      R[3 * c[idx[s]].sec + (size_t) i] += mu[s] * ws->d[3 * idx[s] + i];
  return LAC_SUCCESS;
}

/* ---- rigid plates: their nodes as one --------------------------------- */

/* The conditions of node a (in cs) moved to node owner[a], in the order
 * of the sections, into out (a new list). */
static int
move_conditions (const lac_run_conditions *cs, const size_t *owner,
                 lac_run_conditions *out)
{
  size_t n = cs->nnodes, tot = cs->ptr[n], *fill;
  out->nnodes = n;
  out->ptr = lac_calloc (n + 1, sizeof *out->ptr);
  out->c = lac_malloc ((tot + 1) * sizeof *out->c);
  fill = lac_malloc ((n + 1) * sizeof *fill);
  if (!out->ptr || !out->c || !fill)
    {
      lac_free (fill);
      LAC_ERROR (LAC_ENOMEM, "reactions of the rigid plates");
    }
  for (size_t a = 0; a < n; a++)
    out->ptr[owner[a] + 1] += cs->ptr[a + 1] - cs->ptr[a];
  for (size_t a = 0; a < n; a++)
    out->ptr[a + 1] += out->ptr[a];
  for (size_t a = 0; a < n; a++)
    fill[a] = out->ptr[a];
  for (size_t a = 0; a < n; a++)
    for (size_t j = cs->ptr[a]; j < cs->ptr[a + 1]; j++)
      {                                  /* insertion: by section, stable */
        size_t o = owner[a], k = fill[o]++;
        while (k > out->ptr[o] && out->c[k - 1].sec > cs->c[j].sec)
          {
            out->c[k] = out->c[k - 1];
            k--;
          }
        out->c[k] = cs->c[j];
      }
  lac_free (fill);
  return LAC_SUCCESS;
}

/* Each tied node's residual and conditions moved to its plate node. */
static int
fold_plates (const lac_mesh *m, const lac_run_ties *t, double *r,
             lac_run_conditions *cs)
{
  size_t dim = (size_t) m->dim, *owner;
  lac_run_conditions moved = { 0, NULL, NULL };
  if (!t || t->n == 0)
    return LAC_SUCCESS;
  if (!(owner = lac_malloc ((m->nnodes + 1) * sizeof *owner)))
    LAC_ERROR (LAC_ENOMEM, "reactions of the rigid plates");
  for (size_t a = 0; a < m->nnodes; a++)
    owner[a] = a;
  for (size_t k = 0; k < t->n; k++)
    {
      owner[t->dof[k] / dim] = t->to[k] / dim;
      r[t->to[k]] += r[t->dof[k]];          /* r_P = sum over the plate */
      r[t->dof[k]] = 0;
    }
  int status = move_conditions (cs, owner, &moved);
  lac_free (owner);
  if (status)
    {
      lac_run_conditions_clear (&moved);
      return status;
    }
  lac_run_conditions_clear (cs);
  *cs = moved;
  return LAC_SUCCESS;
}

/* Split r at every fixed node (the room for its largest list first). */
static int
split_all (const lac_mesh *m, const lac_run_conditions *cs, const double *r,
           double *R)
{
  size_t nmax = 1, dim = (size_t) m->dim;
  int status = LAC_SUCCESS;
  for (size_t a = 0; a < m->nnodes; a++)
    nmax = cs->ptr[a + 1] - cs->ptr[a] > nmax ? cs->ptr[a + 1] - cs->ptr[a]
                                              : nmax;
  split_work ws = { lac_malloc (3 * nmax * sizeof (double)),
                    lac_malloc (nmax * sizeof (double)), lac_malloc (nmax) };
  if (!ws.d || !ws.v || !ws.indep)
    status = LAC_ERRMSG (LAC_ENOMEM, "reactions");
  for (size_t a = 0; !status && a < m->nnodes; a++)
    if (cs->ptr[a + 1] > cs->ptr[a])
      {
        double ra[3] = { 0, 0, 0 };
        memcpy (ra, r + dim * a, dim * sizeof *ra);
        status = split (m->dim, cs->c + cs->ptr[a], cs->ptr[a + 1]
                        - cs->ptr[a], ra, &ws, R);
      }
  lac_free (ws.d);
  lac_free (ws.v);
  lac_free (ws.indep);
  return status;
}

static int
add_lines (const lac_run_reaction_in *in, const double *R, lac_summary *sum)
{
  const lac_scene *sc = in->sc;
  int status = LAC_SUCCESS;
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      char key[160];
      const double *Rk = R + 3 * k;
      snprintf (key, sizeof key, "reaction.%s", sc->dirichlet[k].sec.name);
      status = lac_summary_add_vector (sum, key, Rk, in->mesh->dim);
    }
  return status;
}

int
lac_run_reactions (const lac_run_reaction_in *in, lac_summary *sum)
{
  const lac_mesh *m = in->mesh;
  size_t n = (size_t) m->dim * m->nnodes;
  lac_run_conditions cs = { 0, NULL, NULL };
  char *fixed = lac_calloc (m->nnodes + 1, 1);
  double *r = lac_malloc ((n + 1) * sizeof *r);
  double *R = lac_calloc (3 * in->sc->ndirichlet + 1, sizeof *R);
  int status = fixed && r && R ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "reactions");
  int contact = 0;
  if (!status)
    status = lac_run_conditions_build (in->sc, in->model, m, NULL, &cs);
  for (size_t a = 0; !status && a < m->nnodes; a++)
    {
      fixed[a] = cs.ptr[a + 1] > cs.ptr[a];
      contact |= fixed[a] && in->on_contact && in->on_contact[a];
    }
  for (size_t k = 0; !status && in->ties && k < in->ties->n; k++)
    fixed[in->ties->dof[k] / (size_t) m->dim] = 1;  /* the plates' nodes */
  if (!status)
    status = internal_force (in, fixed, r);
  if (!status && contact && in->set && in->lambda)
    status = contact_force (in, r);
  if (!status)
    status = fold_plates (m, in->ties, r, &cs);
  if (!status)
    status = split_all (m, &cs, r, R);
  if (!status)
    status = add_lines (in, R, sum);
  lac_run_conditions_clear (&cs);
  lac_free (fixed);
  lac_free (r);
  lac_free (R);
  return status;
}
