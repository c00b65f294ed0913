/* lac_run_plate.c -- a total force through a rigid plate
 *                    (see lac_run_plate.h)
 */
#include "run/lac_run_plate.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "io/lac_scene_query.h"

void
lac_run_plate_clear (lac_run_ties *t)
{
  lac_free (t->dof);
  lac_free (t->to);
  memset (t, 0, sizeof *t);
}

void
lac_run_plate_untie (const lac_run_ties *t, double *u)
{
  for (size_t k = 0; k < t->n; k++)
    u[t->dof[k]] = u[t->to[k]];
}

/* Fix dof `dof` of mesh m to v (a group of one node). */
static int
fix_dof (lac_dirichlet *dir, const lac_mesh *m, size_t dof, double v)
{
  size_t node = dof / (size_t) m->dim;
  lac_group one = { "plate", 0, 0, 0, NULL, NULL, 1, &node };
  return lac_dirichlet_add_group (dir, m, &one, (int) (dof % (size_t) m->dim),
                                  v);
}

/* The plate node of group g (the most fixed components, else the first)
 * and the components fixed somewhere on the group (has, val). */
static size_t
plate_node (const lac_mesh *m, const lac_group *g, const lac_dirichlet *dir,
            const char *in, int *has, double *val)
{
  size_t best = g->node[0];
  int nbest = 0, dim = m->dim;
  for (size_t q = 0; q < g->nnodes; q++)
    {
      int n = 0;
      for (size_t k = 0; k < dir->n; k++)
        n += dir->dof[k] / (size_t) dim == g->node[q];
      if (n > nbest)
        nbest = n, best = g->node[q];
    }
  for (size_t k = 0; k < dir->n; k++)
    if (in[dir->dof[k] / (size_t) dim])
      {
        has[dir->dof[k] % (size_t) dim] = 1;
        val[dir->dof[k] % (size_t) dim] = dir->val[k];
      }
  return best;
}

/* One plate: map[] of its dofs to those of its plate node. */
static int
plate_one (const lac_scene *sc, const lac_scene_load *l, const lac_mesh *m,
           const lac_run_setup *setup, size_t *map, lac_dirichlet *dir,
           char *in)
{
  const lac_group *g = lac_mesh_group (m, l->group);
  int dim = m->dim, has[3] = { 0, 0, 0 }, status = LAC_SUCCESS;
  double val[3] = { 0, 0, 0 };
  memset (in, 0, m->nnodes);
  for (size_t q = 0; q < g->nnodes; q++)
    {
      size_t a = g->node[q];
      if (setup->on_contact && setup->on_contact[a])
        return lac_scene_error (sc, &l->sec, "group", LAC_EINVAL, "a rigid "
                                "plate on a contact surface (node %zu)",
                                m->node_tag[a]);
      if (map[a * (size_t) dim] != a * (size_t) dim)
        return lac_scene_error (sc, &l->sec, "group", LAC_EINVAL, "node %zu "
                                "is on two rigid plates", m->node_tag[a]);
      in[a] = 1;
    }
  size_t P = plate_node (m, g, dir, in, has, val);
  for (int i = 0; i < dim && !status; i++)
    if (has[i])                        /* fixed for the whole plate */
      status = fix_dof (dir, m, P * (size_t) dim + (size_t) i, val[i]);
  for (size_t q = 0; q < g->nnodes; q++)
    for (int i = 0; i < dim && g->node[q] != P; i++)
      map[g->node[q] * (size_t) dim + (size_t) i] = P * (size_t) dim
                                                    + (size_t) i;
  return status;
}

/* K <- P^T K P on the triplets (a tied diagonal keeps a copy), F <- P^T F,
 * the tied dofs fixed. */
static int
condense (const lac_mesh *m, const size_t *map, lac_triplet *T, double *F,
          lac_dirichlet *dir, lac_run_ties *t)
{
  size_t ndof = (size_t) m->dim * m->nnodes, nz = T ? T->nz : 0;
  int status = LAC_SUCCESS;
  for (size_t k = 0; k < nz && !status; k++)
    {
      size_t i = (size_t) T->i[k], j = (size_t) T->j[k];
      if (i == j && map[i] != i)
        status = lac_triplet_add (T, i, i, T->x[k]);
      T->i[k] = (int) map[i];
      T->j[k] = (int) map[j];
    }
  for (size_t s = 0; s < ndof; s++)
    t->n += map[s] != s;
  t->dof = lac_malloc ((t->n + 1) * sizeof *t->dof);
  t->to = lac_malloc ((t->n + 1) * sizeof *t->to);
  if (!status && (!t->dof || !t->to))
    status = LAC_ERRMSG (LAC_ENOMEM, "rigid plates of %zu dofs", t->n);
  for (size_t s = 0, k = 0; s < ndof && !status; s++)
    if (map[s] != s)
      {
        F[map[s]] += F[s];
        F[s] = 0;
        t->dof[k] = s;
        t->to[k++] = map[s];
        status = fix_dof (dir, m, s, 0.0);
      }
  return status;
}

int
lac_run_plate_tie (const lac_scene *sc, const lac_mesh *m,
                   const lac_run_setup *setup, lac_triplet *T, double *F,
                   lac_dirichlet *dir, lac_run_ties *t)
{
  size_t ndof = (size_t) m->dim * m->nnodes, *map;
  char *in;
  int status = LAC_SUCCESS;
  memset (t, 0, sizeof *t);
  for (size_t k = 0; k < sc->nload; k++)
    t->nplates += sc->load[k].plate != 0;
  if (!t->nplates)
    return LAC_SUCCESS;
  map = lac_malloc (ndof * sizeof *map);
  in = lac_malloc (m->nnodes + 1);
  if (!map || !in)
    status = LAC_ERRMSG (LAC_ENOMEM, "rigid plates");
  for (size_t s = 0; !status && s < ndof; s++)
    map[s] = s;
  for (size_t k = 0; k < sc->nload && !status; k++)
    if (sc->load[k].plate)
      status = plate_one (sc, &sc->load[k], m, setup, map, dir, in);
  if (!status)
    status = condense (m, map, T, F, dir, t);
  lac_free (map);
  lac_free (in);
  return status;
}

/* ---- the rigid motions a plate forbids ---------------------------------- */

/* H += d d^T over the plates' nodes in body b, d_f = N_f(a) - N_f(a0)
 * (a0 the first node of the plate in b), N the nf free motions of b. */
static void
plate_gram (const lac_scene *sc, const lac_mesh *m, const lac_bodies *B,
            size_t b, const double *N, int nf, double *H)
{
  size_t ndof = (size_t) m->dim * m->nnodes, dim = (size_t) m->dim;
  for (size_t k = 0; k < sc->nload; k++)
    {
      const lac_group *g = sc->load[k].plate ? lac_mesh_group
                           (m, sc->load[k].group) : NULL;
      size_t a0 = SIZE_MAX;
      for (size_t q = 0; g && q < g->nnodes; q++)
        {
          size_t a = g->node[q];
          if (B->node_body[a] != b)
            continue;
          if (a0 == SIZE_MAX)
            a0 = a;
          for (size_t i = 0; i < dim && a != a0; i++)
            for (int f = 0; f < nf; f++)
              for (int e = 0; e < nf; e++)
                H[f * nf + e] += (N[f * ndof + a * dim + i]
                                  - N[f * ndof + a0 * dim + i])
                                 * (N[e * ndof + a * dim + i]
                                    - N[e * ndof + a0 * dim + i]);
        }
    }
}

/* The words of body b's free motions, "free: ...; ..." as fem/lac_rigid.c
 * writes them (the part in parentheses of each of `what`). */
static void
describe (const lac_bodies *B, const lac_mesh *m, size_t b, char **what,
          size_t nf)
{
  lac_body *y = &B->body[b];
  const char *name = lac_bodies_name (B, m, b);
  size_t len = 0, skip = name ? strlen ("body '") + strlen (name)
                                + strlen ("' (") : 0;
  y->desc[0] = '\0';
  for (size_t j = 0; j < nf && len < sizeof y->desc; j++)
    {
      const char *w = name ? what[j] + skip : strstr (what[j], " (") + 2;
      int n = snprintf (y->desc + len, sizeof y->desc - len, "%s%.*s",
                        j ? "; " : "free: ", (int) strlen (w) - 1, w);
      len += n > 0 ? (size_t) n : 0;
    }
}

/* Body b's free motions less those its plates forbid (H: their Gram
 * matrix of plate_gram, nf x nf): the null space of H. */
static int
restrict_body (lac_bodies *B, size_t b, double *H, int nf)
{
  gsl_matrix_view A = gsl_matrix_view_array (H, (size_t) nf, (size_t) nf);
  gsl_vector *ev = gsl_vector_alloc ((size_t) nf);
  gsl_matrix *V = gsl_matrix_alloc ((size_t) nf, (size_t) nf);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc ((size_t) nf);
  lac_body *y = &B->body[b];
  double mode[6][6];
  int kept = 0, status = ev && V && w ? LAC_SUCCESS
             : LAC_ERRMSG (LAC_ENOMEM, "rigid motions under the plates");
  if (!status && gsl_eigen_symmv (&A.matrix, ev, V, w))
    status = LAC_ERRMSG (LAC_EDEP, "rigid motions under the plates: GSL's "
                         "eigensolver failed");
  for (int j = 0; !status && j < nf; j++)
    if (gsl_vector_get (ev, (size_t) j) <= 1e-10)    /* moves no plate */
      {
        for (int k = 0; k < 6; k++)
          {
            mode[kept][k] = 0;
            for (int f = 0; f < nf; f++)
              mode[kept][k] += gsl_matrix_get (V, (size_t) f, (size_t) j)
                               * y->mode[f][k];
          }
        kept++;
      }
  if (!status)
    {
      memcpy (y->mode, mode, sizeof mode);
      y->nfree = kept;
    }
  gsl_eigen_symmv_free (w);
  gsl_matrix_free (V);
  gsl_vector_free (ev);
  return status;
}

/* Free the n words of lac_bodies_free_motions. */
static void
free_words (char **what, size_t n)
{
  for (size_t j = 0; what && j < n; j++)
    lac_free (what[j]);
  lac_free (what);
}

/* Body b with its plates' constraint: its modes, then their words. */
static int
plate_body (const lac_scene *sc, const lac_mesh *m, lac_bodies *B, size_t b,
            char *which)
{
  size_t nf = 0;
  double *N = NULL, H[36] = { 0 };
  char **what = NULL;
  int status;
  which[b] = 1;                   /* this body's motions only */
  status = lac_bodies_free_motions (B, m, which, &nf, &N, &what);
  free_words (what, nf);
  what = NULL;
  if (!status && nf > 0)
    {
      plate_gram (sc, m, B, b, N, (int) nf, H);
      status = restrict_body (B, b, H, (int) nf);
    }
  lac_free (N);
  N = NULL;
  if (!status && B->body[b].nfree > 0
      && !(status = lac_bodies_free_motions (B, m, which, &nf, &N, &what)))
    describe (B, m, b, what, nf);
  which[b] = 0;
  free_words (what, nf);
  lac_free (N);
  return status;
}

int
lac_run_plate_motions (const lac_scene *sc, const lac_mesh *m,
                       lac_bodies *B)
{
  char *which = lac_calloc (B->n + 1, 1), *plated = lac_calloc (B->n + 1, 1);
  int status = which && plated ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "rigid motions under the plates");
  for (size_t k = 0; !status && k < sc->nload; k++)
    {
      const lac_group *g = sc->load[k].plate ? lac_mesh_group
                           (m, sc->load[k].group) : NULL;
      for (size_t q = 0; g && q < g->nnodes; q++)
        if (B->node_body[g->node[q]] < B->n)
          plated[B->node_body[g->node[q]]] = 1;
    }
  for (size_t b = 0; !status && b < B->n; b++)
    if (plated[b] && B->body[b].nfree > 0)
      status = plate_body (sc, m, B, b, which);
  lac_free (which);
  lac_free (plated);
  return status;
}
