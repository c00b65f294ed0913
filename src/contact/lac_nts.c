/* lac_nts.c -- node-to-segment / node-to-face contact, for comparison
 *                                                        [LAC §1, §4.2]
 *
 * The classical collocation of the non-penetration condition at the slave
 * nodes (see lac_contact.h, lac_contact_build_nts).  With non-matching
 * meshes it is known to fail the patch test and to make the pressure
 * oscillate [LAC §5.1]; lac keeps it to show that against LAC (chapter 11).
 */
#include <math.h>
#include <string.h>
#include "contact/lac_contact.h"
#include "contact/lac_contact_facet.h"
#include "contact/lac_pairing_project.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* Geometry of one slave node: tributary weight, nodal normal, position. */
typedef struct nts_node
{
  size_t node;
  double w, h, n[3], x[3];    /* h: the share without the 2 pi r weight */
} nts_node;

/* Collect the slave nodes, their weights and nodal normals. */
static int
slave_nodes (const lac_mesh *mesh, lac_model model, const lac_macro *M,
             const lac_pairing *P, long *idx, nts_node **out, size_t *nout)
{
  size_t nf = M->ptr[M->n], nn = 0, cap = 4 * nf + 4;
  nts_node *v = lac_calloc (cap, sizeof *v);
  int nodes[LAC_MAX_FACE_NODES], dim = mesh->dim;
  if (!v)
    LAC_ERROR (LAC_ENOMEM, "node-to-segment nodes");
  for (size_t j = 0; j < nf; j++)
    {
      lac_elem_type ft;
      int k = lac_mesh_facet_nodes (mesh, M->cell[j], M->face[j], nodes, &ft);
      const lac_refelem *re = lac_refelem_get (ft);
      for (int a = 0; a < k; a++)
        {
          lac_map mp;
          int st = -lac_contact_facet_eval (mesh, M->cell[j], M->face[j],
                                            re->xi + a * re->dim, nodes, &mp);
          if (st > 0)
            {
              lac_free (v);
              return st;
            }
          size_t g = (size_t) nodes[a];
          if (idx[g] < 0)
            {
              idx[g] = (long) nn;
              v[nn].node = g;
              memcpy (v[nn].x, mesh->x + g * dim, (size_t) dim * sizeof (double));
              nn++;
            }
          nts_node *q = &v[idx[g]];
          double wa = P->measure[j] / k;              /* lumped share */
          q->h += wa;
          wa *= lac_model_weight (model, q->x);      /* 2 pi r */
          q->w += wa;
          for (int c = 0; c < dim; c++)
            q->n[c] += wa * mp.normal[c];
        }
    }
  for (size_t a = 0; a < nn; a++)
    {
      double l = lac_vec_norm (dim, v[a].n);
      for (int c = 0; c < dim && l > 0; c++)
        v[a].n[c] /= l;                               /* unit nodal normal */
    }
  *out = v;
  *nout = nn;
  return LAC_SUCCESS;
}

/* Project node q along its normal onto the master candidates of facet j;
 * best = the candidate with the projection inside and the smallest |g|. */
static void
project_node (const lac_mesh *mesh, const lac_pairing *P,
              const lac_pairing_facets *master, size_t j, const nts_node *q,
              long *best, double *xi_best, double *g_best)
{
  int dim = mesh->dim, nodes[LAC_MAX_FACE_NODES];
  for (size_t p = P->pair_ptr[j]; p < P->pair_ptr[j + 1]; p++)
    {
      size_t f = P->pair_master[p];
      lac_elem_type ft;
      double xe[LAC_MAX_FACE_NODES * 3], xi[2] = { 0, 0 }, t;
      int k = lac_mesh_facet_nodes (mesh, master->cell[f], master->face[f],
                                    nodes, &ft);
      const lac_refelem *re = lac_refelem_get (ft);
      for (int a = 0; a < k; a++)
        memcpy (xe + a * dim, mesh->x + (size_t) nodes[a] * dim,
                (size_t) dim * sizeof (double));
      if (re->shape == LAC_SHAPE_TRI)
        xi[0] = xi[1] = 1.0 / 3.0;
      if (lac_pairing_project (re, dim, xe, q->x, q->n, xi, &t) != LAC_SUCCESS
          || !lac_refelem_contains (re, xi, 1e-10))
        continue;
      if (*best < 0 || fabs (t) < fabs (*g_best))
        {
          *best = (long) f;
          *g_best = t;
          xi_best[0] = xi[0], xi_best[1] = xi[1];
        }
    }
  lac_error_clear ();                    /* failed candidates are normal */
}

/* Column i of C for node q projected on master facet f at xi. */
static int
add_column (lac_triplet *T, const lac_mesh *mesh,
            const lac_pairing_facets *master, const nts_node *q, long f,
            const double *xi, size_t i)
{
  int dim = mesh->dim, nodes[LAC_MAX_FACE_NODES], st = LAC_SUCCESS;
  double N[LAC_MAX_NODES];
  lac_elem_type ft;
  int k = lac_mesh_facet_nodes (mesh, master->cell[f], master->face[f],
                                nodes, &ft);
  lac_refelem_eval (lac_refelem_get (ft), xi, N, NULL);
  for (int c = 0; !st && c < dim; c++)
    st = lac_triplet_add (T, q->node * dim + c, i, q->w * q->n[c]);
  for (int b = 0; !st && b < k; b++)
    for (int c = 0; !st && c < dim; c++)
      st = lac_triplet_add (T, (size_t) nodes[b] * dim + c, i,
                            -q->w * N[b] * q->n[c]);
  return st;
}

int
lac_contact_build_nts (const lac_mesh *mesh, lac_model model,
                       const lac_macro *M, const lac_pairing *P,
                       const lac_pairing_facets *master, lac_contact **out)
{
  size_t ndof = (size_t) mesh->dim * mesh->nnodes, nn = 0;
  long *idx = lac_malloc (mesh->nnodes * sizeof *idx);
  nts_node *v = NULL;
  lac_contact *c = NULL;
  lac_triplet *T = NULL;
  int st;
  *out = NULL;
  if (!idx)
    LAC_ERROR (LAC_ENOMEM, "node-to-segment index");
  for (size_t a = 0; a < mesh->nnodes; a++)
    idx[a] = -1;
  st = slave_nodes (mesh, model, M, P, idx, &v, &nn);
  if (!st && (!(c = lac_contact_alloc (nn))
              || !(c->xpt = lac_calloc (3 * nn, sizeof *c->xpt))
              || !(c->npt = lac_calloc (3 * nn, sizeof *c->npt))
              || !(T = lac_triplet_alloc (ndof, nn, 16 * nn + 16))))
    st = LAC_ERRMSG (LAC_ENOMEM, "node-to-segment data of %zu nodes", nn);
  for (size_t j = 0; !st && j < M->ptr[M->n]; j++)
    {
      int nodes[LAC_MAX_FACE_NODES];
      lac_elem_type ft;
      int k = lac_mesh_facet_nodes (mesh, M->cell[j], M->face[j], nodes, &ft);
      for (int a = 0; !st && a < k; a++)
        {
          size_t m = (size_t) idx[nodes[a]];
          nts_node *q = &v[m];
          double xi[2], g = 0;
          long f = -1;
          if (c->admissible[m])
            continue;                             /* done from another facet */
          c->meas[m] = q->w;
          c->inode[m] = q->node;
          project_node (mesh, P, master, j, q, &f, xi, &g);
          if (f < 0)
            continue;                             /* off the master: no multiplier */
          size_t i = c->k++;
          c->admissible[m] = 1;
          c->covered[m] = q->w;
          c->crit[m] = 1;
          c->macro[i] = m;
          c->G[i] = q->w * g;                     /* w_a g_a */
          c->area[i] = q->w;
          c->size[i] = q->h;
          memcpy (c->xpt + 3 * i, q->x, sizeof q->x);
          memcpy (c->npt + 3 * i, q->n, sizeof q->n);
          st = add_column (T, mesh, master, q, f, xi, i);
        }
    }
  for (size_t m = 0; !st && c && m < nn; m++)
    c->mult[m] = -1;
  for (size_t i = 0; !st && c && i < c->k; i++)
    c->mult[c->macro[i]] = (long) i;
  if (!st && c->k == 0)
    st = LAC_ERRMSG (LAC_EADMISS, "no slave node projects onto the master "
                     "surface (node-to-segment)");
  if (!st)
    {
      T->ncol = c->k;
      if (!(c->C = lac_csc_from_triplet (T)))
        st = LAC_ENOMEM;
    }
  lac_triplet_free (T);
  lac_free (v);
  lac_free (idx);
  if (st)
    {
      lac_contact_free (c);
      return st;
    }
  *out = c;
  return LAC_SUCCESS;
}
