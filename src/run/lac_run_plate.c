/* lac_run_plate.c -- a total force through a rigid plate
 *                    (see lac_run_plate.h)
 */
#include "run/lac_run_plate.h"

#include <string.h>
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
