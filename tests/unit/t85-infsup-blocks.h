/* t85-infsup-blocks.h -- two stacked blocks for the inf-sup tests
 *                                                   [LAC (10), §5.1, App. A]
 *
 * The Taylor set-up of t450 built in code: a lower (master) block
 * [0, Lm] x [0, 50] (x [0, 50] in 3D) with nlo cells per side and an upper
 * (slave) block [0, 50]^d shifted by 50 along the last axis, with nup
 * cells; symmetry on x = 0 (and y = 0 in 3D) for both, the lower block
 * held on its bottom.  Lm = 50 is the geometrically conforming case;
 * Lm < 50 cuts slave macro-elements (only x is shortened).  Then the whole
 * chain: macro-mesh, pairing, admissibility with `eps`, C with the
 * Dirichlet rows zeroed, and the two norms of lac_infsup.h: A = the H1
 * Gram matrix (ell = mesh diameter) and M = diag(h_i |T^m_i cap Gamma_C|).
 * Header-only, for t85x and t890.
 */
#ifndef T85_INFSUP_BLOCKS_H
#define T85_INFSUP_BLOCKS_H

#include <stdlib.h>
#include <string.h>
#include "fem/lac_assembly.h"
#include "contact/lac_contact.h"
#include "contact/lac_infsup.h"
#include "base/lac_status.h"

typedef struct blocks
{
  lac_mesh *m;
  lac_macro *M;
  lac_pairing *P;
  lac_contact *c;
  lac_csc *A, *Mn;      /* H1 Gram (Dirichlet eliminated), multiplier norm */
  double *h;            /* k: macro-element diameters                     */
  char *fixed;          /* ndof                                           */
  int dim;
} blocks;

static void
blocks_free (blocks *b)
{
  lac_csc_free (b->A);
  lac_csc_free (b->Mn);
  free (b->h);
  free (b->fixed);
  lac_contact_free (b->c);
  lac_pairing_free (b->P);
  lac_macromesh_free (b->M);
  lac_mesh_free (b->m);
}

static int
blocks_fix (lac_dirichlet *d, lac_mesh *m, const char *g, int comp)
{
  const lac_group *G = lac_mesh_group (m, g);
  return G ? lac_dirichlet_add_group (d, m, G, comp, 0.0) : LAC_EINVAL;
}

/* Build everything; returns a status (the message is set), *b zeroed
 * first so that blocks_free is always safe. */
static int
blocks_build (blocks *b, lac_elem_type type, size_t nlo, size_t nup,
              double Lm, double eps)
{
  int dim = lac_refelem_get (type)->dim, st;
  size_t nl[3] = { nlo, nlo, nlo }, nu[3] = { nup, nup, nup };
  double Llo[3] = { Lm, 50, 50 }, Lup[3] = { 50, 50, 50 };
  lac_mesh *lo = NULL, *up = NULL;
  lac_dirichlet *D = NULL;
  memset (b, 0, sizeof *b);
  b->dim = dim;
  if ((st = lac_mesh_box (type, nl, Llo, 0.0, &lo))
      || (st = lac_mesh_box (type, nu, Lup, 0.0, &up)))
    goto done;
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[a * (size_t) dim + (size_t) dim - 1] += 50.0;   /* stack on top */
  if ((st = lac_mesh_merge (lo, "lo.", up, "up.", &b->m))
      || (st = lac_macromesh_build (&b->m, dim == 2 ? "up.ymin" : "up.zmin",
                                    NULL, &b->M)))
    goto done;
  lac_pairing_facets S = { b->m, b->M->ptr[b->M->n], b->M->cell, b->M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (b->m, lac_mesh_group
                                                 (b->m, dim == 2 ? "lo.ymax"
                                                  : "lo.zmax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_model model = dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D;
  size_t ndof = (size_t) dim * b->m->nnodes;
  if ((st = lac_pairing_build (&S, &Mf, &po, &b->P))
      || (st = lac_contact_build (b->m, model, b->M, b->P, &Mf, eps, &b->c)))
    goto done;
  D = lac_dirichlet_alloc ();
  b->fixed = calloc (ndof, 1);
  b->h = calloc (b->c->k, sizeof *b->h);
  if (!D || !b->fixed || !b->h)
    {
      st = LAC_ENOMEM;
      goto done;
    }
  if ((st = blocks_fix (D, b->m, "lo.xmin", 0))
      || (st = blocks_fix (D, b->m, "up.xmin", 0))
      || (dim == 3 && (st = blocks_fix (D, b->m, "lo.ymin", 1)))
      || (dim == 3 && (st = blocks_fix (D, b->m, "up.ymin", 1)))
      || (st = blocks_fix (D, b->m, dim == 2 ? "lo.ymin" : "lo.zmin",
                           dim - 1)))
    goto done;
  for (size_t k = 0; k < D->n; k++)
    b->fixed[D->dof[k]] = 1;
  if ((st = lac_contact_apply_dirichlet (b->c, D->n, D->dof, D->val))
      || (st = lac_infsup_gram_h1 (b->m, model, b->fixed, 0.0, &b->A))
      || (st = lac_infsup_norm_lac (b->m, b->M, b->c, b->h, &b->Mn)))
    goto done;
done:
  lac_dirichlet_free (D);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  return st;
}

/* beta_h of the blocks by `path` (NULL on failure; message set). */
static lac_infsup *
blocks_infsup (const blocks *b, lac_infsup_path path)
{
  lac_infsup_opts o;
  lac_infsup *r = NULL;
  lac_infsup_opts_init (&o);
  o.path = path;
  if (lac_infsup_estimate (b->A, b->c->C, b->Mn, &o, &r))
    return NULL;
  return r;
}

#endif /* T85_INFSUP_BLOCKS_H */
