/* lac_macromesh.c -- the macro-mesh T^M of the slave contact boundary
 *                                                 [LAC Hyp. 1, §4.4, Fig. 2]
 *
 * Builds T^M in four steps (conventions and ownership in lac_macromesh.h);
 * this file holds steps 1 and 3 and the public functions, step 2 is in
 * lac_macromesh_gather.c, one refinement round in lac_refine.c and step 4
 * in lac_macromesh_nodes.c; the macro-elements under construction are a
 * lac_macro_list (lac_macro_list.c):
 *
 *   1. check the slave group: it exists, is a non-empty facet group, lists
 *      no facet twice, and every facet is on the boundary (a cut would
 *      otherwise break conformity with the cell on the other side); with
 *      several groups (several contact pairs), no facet is in two;
 *   2. start the macro-elements: one per facet, except for 2D linear
 *      segments, which are gathered two by two along their chains, the
 *      chains broken at the corners of the slave curve
 *      [LAC §4.4, item 1]:
 *
 *          chain of 5 segments:  o-----o-----o-----o-----o-----o
 *                                |    T^1    |       T^2       |
 *                                      ^            ^     (^)
 *                                  interior node    interior nodes: the
 *                                                   one with the largest
 *                                                   integral is fixed
 *
 *      a chain of odd length ends with one macro of three segments; a
 *      closed loop is cut anywhere; an isolated segment (no neighbour) has
 *      its cell cut at the segment's midpoint instead;
 *   3. cut, in rounds, the cells owning a facet that has no interior node
 *      (lac_refine.c): a round cuts at most one facet per cell, then every
 *      macro-element's facet list is remapped to the new mesh;
 *   4. for each T^m: its measure, its interior nodes (nodes of its
 *      sub-facets that are on no boundary edge of T^m and on no other
 *      macro-element), and the designated one x_{m*+1}: the largest
 *      int_{T^m} phi_i [LAC Remark 1, Def. 1].
 *
 * Several slave groups go through the steps together, as one list of
 * macro-elements (group after group): every round remaps all of them, so
 * that the macro-elements of the first group stay valid while the cells
 * of the second are cut (a cell owning facets of two groups is cut in two
 * rounds), and no node of one group's macro-element is taken as interior
 * to another's.  The list is split into one lac_macro per group at the
 * end.
 *
 * lac_macromesh_trace builds the raw trace mesh instead (one element per
 * slave facet, for comparisons only).
 */
#include "contact/lac_macromesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/lac_macro_list.h"
#include "contact/lac_macromesh_gather.h"
#include "contact/lac_macromesh_nodes.h"
#include "contact/lac_refine.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* ---- step 1: the slave group ------------------------------------------- */

typedef struct fkey
{
  int v[4];      /* vertex nodes of the facet, sorted, padded with -1 */
  size_t e;      /* entry of the group                                 */
} fkey;

static int
cmp_fkey (const void *a, const void *b)
{
  const fkey *p = a, *q = b;
  for (int i = 0; i < 4; i++)
    if (p->v[i] != q->v[i])
      return p->v[i] < q->v[i] ? -1 : 1;
  return 0;
}

static void
make_key (const lac_mesh *m, size_t c, int f, fkey *k)
{
  const lac_refelem *re = lac_refelem_get (m->type[c]);
  int nv = lac_refelem_get (re->face_type[f])->nvertices;
  for (int i = 0; i < 4; i++)
    k->v[i] = i < nv ? m->conn[m->ptr[c] + (size_t) re->face_node[f][i]] : -1;
  for (int i = 1; i < nv; i++)               /* insertion sort, nv <= 4 */
    for (int j = i; j > 0 && k->v[j - 1] > k->v[j]; j--)
      {
        int t = k->v[j];
        k->v[j] = k->v[j - 1];
        k->v[j - 1] = t;
      }
}

/* What facet e of G needs, from its face type. */
static int
classify (const lac_mesh *m, const lac_group *G, size_t e,
          const lac_macro_opts *opts, unsigned char *kind)
{
  const lac_refelem *re, *rf;
  int hex_cut = opts ? opts->hex_cut : LAC_MACRO_HEX_DEFAULT;

  if (G->cell[e] >= m->ncells)
    LAC_MACRO_ERROR (LAC_EINVAL, "facet %zu of group '%s': cell %zu out of "
                     "range", e, G->name, G->cell[e]);
  re = lac_refelem_get (m->type[G->cell[e]]);
  if (!re || re->dim != m->dim || G->face[e] < 0 || G->face[e] >= re->nfaces)
    LAC_MACRO_ERROR (LAC_EINVAL, "facet %zu of group '%s': cell %zu (tag "
                     "%zu) has no face %d", e, G->name, G->cell[e],
                     m->cell_tag[G->cell[e]], G->face[e]);
  rf = lac_refelem_get (re->face_type[G->face[e]]);
  switch (rf->type)
    {
    case LAC_SEG2:                           /* tri3, quad4 */
      *kind = opts && opts->cut_2d == 1 ? LAC_MACRO_CUT : LAC_MACRO_GATHER;
      return LAC_SUCCESS;
    case LAC_SEG3: case LAC_QUAD9:           /* mid / centre node exists */
      *kind = LAC_MACRO_KEEP;
      return LAC_SUCCESS;
    case LAC_TRI3: case LAC_QUAD4: case LAC_TRI6:
      *kind = LAC_MACRO_CUT;
      return LAC_SUCCESS;
    case LAC_QUAD8:
      if (hex_cut == LAC_MACRO_HEX_PYRAMIDS)
        LAC_MACRO_ERROR (LAC_EINVAL, "facet %zu of group '%s': a %s cannot "
                         "be cut into pyramids (its quad8 face would need "
                         "pyramid13 cells, which lac does not have); cut it "
                         "into six hexahedra (LAC_MACRO_HEX_SIX, a scene's "
                         "hex_cut = six)", e, G->name, re->name);
      *kind = LAC_MACRO_CUT;
      return LAC_SUCCESS;
    default:
      LAC_MACRO_ERROR (LAC_EINVAL, "facet %zu of group '%s': %s faces of %s "
                       "cells cannot be made into macro-elements", e,
                       G->name, rf->name, re->name);
    }
}

/* No facet twice, and none shared with another cell: the slave facets must
 * lie on the boundary (sorting the slave keys, then looking every face of
 * the mesh up among them). */
static int
check_boundary (const lac_mesh *m, const lac_group *G)
{
  fkey *key = lac_malloc (G->n * sizeof *key);
  int status = LAC_SUCCESS;

  if (!key)
    LAC_MACRO_ERROR (LAC_ENOMEM, "keys of %zu slave facets", G->n);
  for (size_t e = 0; e < G->n; e++)
    {
      make_key (m, G->cell[e], G->face[e], &key[e]);
      key[e].e = e;
    }
  qsort (key, G->n, sizeof *key, cmp_fkey);
  for (size_t e = 1; e < G->n && !status; e++)
    if (cmp_fkey (&key[e - 1], &key[e]) == 0)
      {
        size_t a = key[e - 1].e, b = key[e].e;
        if (G->cell[a] == G->cell[b])
          status = LAC_MACRO_ERRMSG (LAC_EINVAL, "group '%s' lists facet "
                                     "(cell %zu, face %d) twice (entries %zu "
                                     "and %zu)", G->name, G->cell[a],
                                     G->face[a], a, b);
        else
          status = LAC_MACRO_ERRMSG (LAC_EINVAL, "group '%s': facet %zu "
                                     "(cell %zu) and facet %zu (cell %zu) are "
                                     "the same face, interior to the mesh; a "
                                     "contact boundary must lie on the "
                                     "boundary", G->name, a, G->cell[a], b,
                                     G->cell[b]);
      }
  for (size_t c = 0; c < m->ncells && !status; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      for (int f = 0; f < re->nfaces && !status; f++)
        {
          fkey k;
          const fkey *hit;
          make_key (m, c, f, &k);
          hit = bsearch (&k, key, G->n, sizeof *key, cmp_fkey);
          if (hit && !(G->cell[hit->e] == c && G->face[hit->e] == f))
            status = LAC_MACRO_ERRMSG (LAC_EINVAL, "facet %zu of group '%s' "
                                       "(cell %zu, face %d) is shared with "
                                       "cell %zu (tag %zu): it is interior, "
                                       "a contact boundary must lie on the "
                                       "boundary", hit->e, G->name,
                                       G->cell[hit->e], G->face[hit->e], c,
                                       m->cell_tag[c]);
        }
    }
  lac_free (key);
  return status;
}

/* Several slave groups: no facet in two of them (a facet can carry the
 * multipliers of one pair only), found by sorting the keys of all (key
 * k of group grp[k], entry k - first[grp[k]]). */
static int
check_disjoint (const lac_mesh *m, size_t n, const lac_group *const *G)
{
  size_t nf = 0, k = 0;
  for (size_t p = 0; p < n; p++)
    nf += G[p]->n;
  fkey *key = lac_malloc ((nf + 1) * sizeof *key);
  size_t *grp = lac_malloc ((nf + 1) * sizeof *grp);
  int status = LAC_SUCCESS;
  if (!key || !grp)
    {
      lac_free (key);
      lac_free (grp);
      LAC_MACRO_ERROR (LAC_ENOMEM, "keys of %zu slave facets", nf);
    }
  for (size_t p = 0; p < n; p++)
    for (size_t e = 0; e < G[p]->n; e++, k++)
      {
        make_key (m, G[p]->cell[e], G[p]->face[e], &key[k]);
        key[k].e = k;
        grp[k] = p;
      }
  qsort (key, nf, sizeof *key, cmp_fkey);
  for (size_t j = 1; j < nf && !status; j++)
    if (cmp_fkey (&key[j - 1], &key[j]) == 0
        && grp[key[j - 1].e] != grp[key[j].e])
      {
        size_t a = grp[key[j - 1].e], b = grp[key[j].e], e = key[j - 1].e;
        for (size_t p = 0; p < a; p++)
          e -= G[p]->n;                     /* entry of the facet in a */
        status = LAC_MACRO_ERRMSG (LAC_EINVAL, "slave groups '%s' and '%s' "
                                   "share a facet (cell %zu, face %d, nodes "
                                   "%zu, %zu, ...): a facet carries the "
                                   "multipliers of one pair only",
                                   G[a]->name, G[b]->name,
                                   m->cell_tag[G[a]->cell[e]], G[a]->face[e],
                                   m->node_tag[key[j].v[0]],
                                   m->node_tag[key[j].v[1]]);
      }
  lac_free (key);
  lac_free (grp);
  return status;
}

/* ---- step 3: refinement rounds ----------------------------------------- */

/* Cut the pending facets, at most one per cell and round  [LAC §4.4];
 * macro-element k of L takes the template options opt[grp[k]], and a
 * round cuts the facets of one choice of options (the first pending
 * one's).  *cur is replaced by each new mesh; meshes other than `orig`
 * are freed.  ncut[g]: the cells cut for group g. */
static int
refine_rounds (lac_mesh **cur, const lac_mesh *orig, lac_macro_list *L,
               const size_t *grp, const lac_macro_opts *opt, size_t *ncut,
               int *nrounds, size_t *nnew)
{
  int status = LAC_SUCCESS;

  for (;;)
    {
      lac_mesh *m = *cur, *next = NULL;
      lac_refine_map *map = NULL;
      int *cut;
      size_t first = L->n;

      for (size_t k = 0; k < L->n && first == L->n; k++)
        if (L->pending[k])
          first = k;
      if (first == L->n)
        break;
      const lac_macro_opts *o = &opt[grp[first]];
      cut = lac_malloc (m->ncells * sizeof *cut);
      if (!cut)
        LAC_MACRO_ERROR (LAC_ENOMEM, "refinement round %d", *nrounds + 1);
      for (size_t c = 0; c < m->ncells; c++)
        cut[c] = -1;
      for (size_t k = first; k < L->n; k++)
        {
          size_t c = L->cell[L->ptr[k]];
          const lac_macro_opts *ok = &opt[grp[k]];
          if (L->pending[k] && cut[c] < 0 && ok->hex_cut == o->hex_cut
              && ok->cut_2d == o->cut_2d)
            {
              cut[c] = L->face[L->ptr[k]];
              L->pending[k] = 0;
              ncut[grp[k]]++;
            }
        }
      status = lac_refine_cut (m, cut, o, &next, &map);
      lac_free (cut);
      if (!status)
        status = lac_macro_list_remap (L, map);
      lac_refine_map_free (map);
      if (status)
        {
          lac_mesh_free (next);
          return status;
        }
      *nnew += next->nnodes - m->nnodes;
      (*nrounds)++;
      if (m != orig)
        lac_mesh_free (m);
      *cur = next;
    }
  return status;
}

/* ---- public ------------------------------------------------------------ */

void
lac_macromesh_free (lac_macro *M)
{
  if (!M)
    return;
  lac_free (M->ptr);
  lac_free (M->cell);
  lac_free (M->face);
  lac_free (M->inode);
  lac_free (M->meas);
  lac_free (M->phi);
  lac_free (M);
}

/* Step 1 of lac_macromesh_build: the slave group `slave` of m, which must
 * be a non-empty group of boundary facets. */
static int
slave_group (const lac_mesh *m, const char *slave, const lac_group **G)
{
  *G = lac_mesh_group (m, slave);
  if (!*G)
    {
      LAC_MACRO_ERROR (LAC_EINVAL, "slave contact group: %s",
                       lac_error_message ());
    }
  if ((*G)->dim != m->dim - 1)
    LAC_MACRO_ERROR (LAC_EINVAL, "slave contact group '%s' has dimension "
                     "%d; it must be a group of boundary facets (dimension "
                     "%d)", slave, (*G)->dim, m->dim - 1);
  if ((*G)->n == 0)
    LAC_MACRO_ERROR (LAC_EINVAL, "slave contact group '%s' is empty", slave);
  return LAC_SUCCESS;
}

/* Macro-elements k0 .. k1-1 of L, with their interior nodes, measures
 * and integrals (step 4, inode, meas, phi of all of L), as a lac_macro. */
static lac_macro *
split_macro (const lac_macro_list *L, size_t k0, size_t k1,
             const size_t *inode, const double *meas, const double *phi)
{
  size_t n = k1 - k0, j0 = L->ptr[k0], nf = L->ptr[k1] - j0;
  lac_macro *M = lac_calloc (1, sizeof *M);
  if (M)
    {
      M->n = n;
      M->ptr = lac_malloc ((n + 1) * sizeof *M->ptr);
      M->cell = lac_malloc ((nf + 1) * sizeof *M->cell);
      M->face = lac_malloc ((nf + 1) * sizeof *M->face);
      M->inode = lac_malloc ((n + 1) * sizeof *M->inode);
      M->meas = lac_malloc ((n + 1) * sizeof *M->meas);
      M->phi = lac_malloc ((n + 1) * sizeof *M->phi);
    }
  if (!M || !M->ptr || !M->cell || !M->face || !M->inode || !M->meas
      || !M->phi)
    {
      lac_macromesh_free (M);
      LAC_MACRO_ERRMSG (LAC_ENOMEM, "macro-mesh of %zu elements", n);
      return NULL;
    }
  for (size_t k = 0; k <= n; k++)
    M->ptr[k] = L->ptr[k0 + k] - j0;
  memcpy (M->cell, L->cell + j0, nf * sizeof *M->cell);
  memcpy (M->face, L->face + j0, nf * sizeof *M->face);
  memcpy (M->inode, inode + k0, n * sizeof *M->inode);
  memcpy (M->meas, meas + k0, n * sizeof *M->meas);
  memcpy (M->phi, phi + k0, n * sizeof *M->phi);
  return M;
}

/* Step 4: measures and interior nodes of the macro-elements L on mesh m
 * (the nodes of another macro-element, of any group, are not interior),
 * then one lac_macro per group (kofs[g] .. kofs[g+1]-1 of L). */
static int
fill_macros (const lac_mesh *m, const lac_macro_list *L, size_t n,
             const size_t *kofs, lac_macro **out)
{
  size_t *inode = lac_malloc ((L->n + 1) * sizeof *inode);
  double *meas = lac_malloc ((L->n + 1) * sizeof *meas);
  double *phi = lac_malloc ((L->n + 1) * sizeof *phi);
  int status = inode && meas && phi ? LAC_SUCCESS
               : LAC_MACRO_ERRMSG (LAC_ENOMEM, "macro-mesh of %zu elements",
                                   L->n);
  if (!status)
    status = lac_macromesh_finish (m, L, inode, meas, phi);
  for (size_t g = 0; g < n && !status; g++)
    if (!(out[g] = split_macro (L, kofs[g], kofs[g + 1], inode, meas, phi)))
      status = LAC_ENOMEM;
  lac_free (inode);
  lac_free (meas);
  lac_free (phi);
  return status;
}

/* Steps 1 and 2 for group g: its facets classified and checked, its
 * first macro-elements appended to L (grp: their group). */
static int
start_group (const lac_mesh *m, const lac_group *G, const lac_macro_opts *o,
             size_t g, lac_macro_list *L, size_t *grp)
{
  unsigned char *kind;
  size_t k0 = L->n;
  int status = LAC_SUCCESS;
  if (!(kind = lac_malloc (G->n * sizeof *kind)))
    LAC_MACRO_ERROR (LAC_ENOMEM, "macro-mesh of %zu facets", G->n);
  for (size_t e = 0; e < G->n && !status; e++)
    status = classify (m, G, e, o, &kind[e]);
  if (!status)
    status = check_boundary (m, G);
  if (!status)
    status = lac_macromesh_start (m, G, kind, o->cut_2d != 2, L);
  for (size_t k = k0; !status && k < L->n; k++)
    grp[k] = g;
  lac_free (kind);
  return status;
}

/* The options of group g: opts[g], or the defaults. */
static int
options (size_t n, const lac_macro_opts *opts, lac_macro_opts **opt)
{
  if (!(*opt = lac_calloc (n, sizeof **opt)))
    LAC_MACRO_ERROR (LAC_ENOMEM, "options of %zu groups", n);
  for (size_t g = 0; g < n; g++)
    {
      const lac_macro_opts *o = opts ? &opts[g] : NULL;
      if (o && (o->hex_cut < LAC_MACRO_HEX_DEFAULT
                || o->hex_cut > LAC_MACRO_HEX_SIX
                || o->cut_2d < 0 || o->cut_2d > 2))
        LAC_MACRO_ERROR (LAC_EINVAL, "options hex_cut = %d, cut_2d = %d out "
                         "of range", o->hex_cut, o->cut_2d);
      if (o)
        (*opt)[g] = *o;
    }
  return LAC_SUCCESS;
}

/* Steps 1-3 for the n groups on *cur: L, grp, kofs (the first
 * macro-element of each group) and the counts of M[0]. */
static int
build_list (lac_mesh **cur, const lac_mesh *orig, size_t n,
            const char *const *slave, const lac_macro_opts *opt,
            lac_macro_list *L, size_t **grp, size_t *kofs, size_t *ncut,
            int *nrounds, size_t *nnew)
{
  const lac_group **G = lac_calloc (n, sizeof *G);
  size_t nf = 0;
  int status = G ? LAC_SUCCESS
               : LAC_MACRO_ERRMSG (LAC_ENOMEM, "%zu slave groups", n);
  for (size_t g = 0; g < n && !status; g++)
    status = slave_group (*cur, slave[g], &G[g]);
  for (size_t g = 0; g < n && !status; g++)
    nf += G[g]->n;
  if (!status)
    status = lac_macro_list_init (L, nf);
  if (!status && !(*grp = lac_malloc ((nf + 1) * sizeof **grp)))
    status = LAC_MACRO_ERRMSG (LAC_ENOMEM, "macro-mesh of %zu facets", nf);
  for (size_t g = 0; g < n && !status; g++)
    {
      kofs[g] = L->n;
      status = start_group (*cur, G[g], &opt[g], g, L, *grp);
    }
  kofs[n] = L->n;
  if (!status && n > 1)
    status = check_disjoint (*cur, n, G);
  lac_free (G);
  if (!status)
    status = refine_rounds (cur, orig, L, *grp, opt, ncut, nrounds, nnew);
  return status;
}

/* lac_macromesh_build_set: T^M of each of n slave groups, in one pass
 * [LAC Hyp. 1, §4.4].
 *
 *   [in,out] mesh   *mesh is replaced by the refined mesh on success (the
 *                   old one is freed); unchanged on failure
 *   [in]     slave  n names of slave facet groups (n >= 1)
 *   [in]     opts   NULL or n template choices (lac_macromesh.h)
 *   [out]    out    n macro-meshes (free each with lac_macromesh_free)
 *   returns LAC_SUCCESS, LAC_EINVAL (message names the group, facet, cell
 *   or element type), LAC_ENOMEM, LAC_ESANITY */
int
lac_macromesh_build_set (lac_mesh **mesh, size_t n, const char *const *slave,
                         const lac_macro_opts *opts, lac_macro **out)
{
  lac_mesh *cur = NULL;
  lac_macro_list L = { 0 };
  lac_macro_opts *opt = NULL;
  size_t *grp = NULL, *kofs = NULL, *ncut = NULL, nnew = 0;
  int status, nrounds = 0;

  if (!out || n == 0)
    LAC_MACRO_ERROR (LAC_EINVAL, "no output pointer or no slave group");
  for (size_t g = 0; g < n; g++)
    out[g] = NULL;
  if (!mesh || !*mesh || !slave)
    LAC_MACRO_ERROR (LAC_EINVAL, "no mesh or no slave group name");
  for (size_t g = 0; g < n; g++)
    if (!slave[g])
      LAC_MACRO_ERROR (LAC_EINVAL, "no name for slave group %zu", g);
  cur = *mesh;
  kofs = lac_malloc ((n + 1) * sizeof *kofs);
  ncut = lac_calloc (n, sizeof *ncut);
  status = !kofs || !ncut ? LAC_MACRO_ERRMSG (LAC_ENOMEM, "%zu groups", n)
           : options (n, opts, &opt);
  if (!status)
    status = build_list (&cur, *mesh, n, slave, opt, &L, &grp, kofs, ncut,
                         &nrounds, &nnew);
  if (!status)
    status = fill_macros (cur, &L, n, kofs, out);
  for (size_t g = 0; g < n && !status; g++)
    {
      out[g]->ncut = ncut[g];
      out[g]->nnew = nnew;
      out[g]->nrounds = nrounds;
    }
  lac_macro_list_free (&L);
  lac_free (opt), lac_free (grp), lac_free (kofs), lac_free (ncut);
  if (status)
    {
      for (size_t g = 0; g < n; g++)
        {
          lac_macromesh_free (out[g]);
          out[g] = NULL;
        }
      if (cur != *mesh)
        lac_mesh_free (cur);
      return status;
    }
  if (cur != *mesh)
    {
      lac_mesh_free (*mesh);
      *mesh = cur;
    }
  return LAC_SUCCESS;
}

/* lac_macromesh_build: T^M on one facet group (lac_macromesh_build_set
 * with n = 1). */
int
lac_macromesh_build (lac_mesh **mesh, const char *slave,
                     const lac_macro_opts *opts, lac_macro **out)
{
  if (!out)
    LAC_MACRO_ERROR (LAC_EINVAL, "no output pointer");
  return lac_macromesh_build_set (mesh, 1, &slave, opts, out);
}

/* lac_macromesh_trace: the raw trace mesh as "macro-mesh": one element per
 * slave facet, nothing gathered or refined (the P0 multipliers of [LAC
 * §4.2], which violate Hypothesis 1 for linear elements: used only to
 * compare with LAC).  inode = (size_t) -1 where the facet has no interior
 * node; meas = phi = 0. */
int
lac_macromesh_trace (const lac_mesh *mesh, const char *slave, lac_macro **out)
{
  const lac_group *G = mesh ? lac_mesh_group (mesh, slave) : NULL;
  *out = NULL;
  if (!G)
    LAC_MACRO_ERROR (LAC_EINVAL, "slave contact group '%s' not found", slave);
  if (G->dim != mesh->dim - 1 || G->n == 0)
    LAC_MACRO_ERROR (LAC_EINVAL, "slave contact group '%s' is not a non-empty "
                     "group of boundary facets", slave);
  lac_macro *M = lac_calloc (1, sizeof *M);
  size_t n = G->n;
  if (M)
    {
      M->n = n;
      M->ptr = lac_malloc ((n + 1) * sizeof *M->ptr);
      M->cell = lac_malloc (n * sizeof *M->cell);
      M->face = lac_malloc (n * sizeof *M->face);
      M->inode = lac_malloc (n * sizeof *M->inode);
      M->meas = lac_calloc (n, sizeof *M->meas);
      M->phi = lac_calloc (n, sizeof *M->phi);
    }
  if (!M || !M->ptr || !M->cell || !M->face || !M->inode || !M->meas
      || !M->phi)
    {
      lac_macromesh_free (M);
      LAC_MACRO_ERROR (LAC_ENOMEM, "trace macro-mesh of %zu facets", n);
    }
  M->ptr[0] = 0;
  for (size_t e = 0; e < n; e++)
    {
      M->ptr[e + 1] = e + 1;
      M->cell[e] = G->cell[e];
      M->face[e] = G->face[e];
      size_t in[LAC_MACRO_MAXPATCH];
      M->inode[e] = lac_macromesh_interior (mesh, M, e, in,
                                            LAC_MACRO_MAXPATCH) > 0
                    ? in[0] : (size_t) -1;
    }
  *out = M;
  return LAC_SUCCESS;
}

/* lac_macromesh_interior: the interior nodes of the patch of sub-facets of
 * T^m (lac_macromesh_nodes.c). */
size_t
lac_macromesh_interior (const lac_mesh *mesh, const lac_macro *M, size_t m,
                        size_t *nodes, size_t nmax)
{
  if (!mesh || !M || m >= M->n)
    return 0;
  return lac_macromesh_patch_interior (mesh, M->cell + M->ptr[m],
                                       M->face + M->ptr[m],
                                       M->ptr[m + 1] - M->ptr[m], nodes,
                                       nmax);
}
