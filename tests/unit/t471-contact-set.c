/* t471: several contact pairs as one contact problem (lac_contact_set)
 *                                    [LAC §4.3, §4.6, Def. 1, (16)-(18)]
 *
 * Three stacked boxes (2D quad4 and 3D hex8, 4, 3 and 5 cells across, so
 * that neither interface matches): pair 0 the middle box's bottom on the
 * lower box's top, pair 1 the upper box's bottom on the middle box's top
 * (the middle box slave of one pair, master of the other).  The macro-
 * meshes come from one pass (lac_macromesh_build_set).  The set must give
 *   - the slots: pair p's macro-elements are offset[p] .., and pair_of
 *     inverts it (n for a slot out of range);
 *   - the contact data of each pair exactly as lac_contact_pair_build
 *     makes it alone, and their concatenation `all`: C = [C_0 C_1] entry
 *     by entry, G, area stacked, macro[i] = offset[p] + the pair's
 *     macro-element, mult[slot] = col[p] + the pair's multiplier;
 *   - with one pair, `all` is that pair's data itself;
 *   - node-to-segment among two pairs refused (LAC_EINVAL).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "contact/lac_contact_set.h"
#include "contact/lac_macromesh.h"

/* Three boxes of type t stacked along the last axis, 20 high each. */
static lac_mesh *
stack (lac_elem_type t, int dim)
{
  size_t n[3][3] = { { 4, 4, 2 }, { 3, 3, 2 }, { 5, 5, 2 } };
  double L[3] = { 50, 50, 20 };
  lac_mesh *b[3] = { NULL, NULL, NULL }, *ab = NULL, *m = NULL;
  for (int k = 0; k < 3; k++)
    {
      if (dim == 2)
        n[k][1] = 2;
      double Lk[3] = { L[0], dim == 2 ? L[2] : L[1], L[2] };
      check_status (lac_mesh_box (t, n[k], Lk, 0.0, &b[k]), LAC_SUCCESS,
                    "box %d", k);
      for (size_t a = 0; b[k] && a < b[k]->nnodes; a++)
        b[k]->x[a * (size_t) dim + (size_t) dim - 1] += 20.0 * k;
    }
  if (b[0] && b[1] && b[2])
    {
      lac_mesh_merge (b[0], "lo.", b[1], "mid.", &ab);
      if (ab)
        lac_mesh_merge (ab, "", b[2], "up.", &m);
    }
  for (int k = 0; k < 3; k++)
    lac_mesh_free (b[k]);
  lac_mesh_free (ab);
  return m;
}

/* Column i of a and column j of b are the same, entry by entry. */
static int
same_column (const lac_csc *a, size_t i, const lac_csc *b, size_t j)
{
  if (a->p[i + 1] - a->p[i] != b->p[j + 1] - b->p[j])
    return 0;
  for (int q = 0; q < a->p[i + 1] - a->p[i]; q++)
    if (a->i[a->p[i] + q] != b->i[b->p[j] + q]
        || a->x[a->p[i] + q] != b->x[b->p[j] + q])
      return 0;
  return 1;
}

/* The set's data against each pair built alone. */
static void
check_against_alone (const lac_contact_set *s, const lac_contact_set_data *d,
                     const char *what)
{
  const lac_contact *all = d->all;
  for (size_t p = 0; p < s->n; p++)
    {
      lac_pairing *P = NULL;
      lac_contact *c = NULL;
      check_status (lac_contact_pair_build (&s->pair[p], NULL, &P, &c),
                    LAC_SUCCESS, "%s: pair %zu alone", what, p);
      if (!c)
        continue;
      check_int ((long) (d->col[p + 1] - d->col[p]), (long) c->k,
                 "%s: columns of pair %zu", what, p);
      size_t bad = 0;
      for (size_t i = 0; i < c->k; i++)
        {
          size_t j = d->col[p] + i;
          bad += !same_column (all->C, j, c->C, i) || all->G[j] != c->G[i]
                 || all->area[j] != c->area[i]
                 || all->macro[j] != s->offset[p] + c->macro[i];
        }
      for (size_t m = 0; m < c->nmacro; m++)
        bad += all->mult[s->offset[p] + m]
               != (c->mult[m] < 0 ? -1 : (long) d->col[p] + c->mult[m]);
      check_int ((long) bad, 0, "%s: pair %zu's columns and slots in all",
                 what, p);
      lac_pairing_free (P);
      lac_contact_free (c);
    }
}

static void
run (lac_elem_type t, int dim, const char *what)
{
  lac_mesh *m = stack (t, dim);
  const char *top = dim == 2 ? "ymax" : "zmax", *bot = dim == 2 ? "ymin"
                                                                : "zmin";
  char g[4][32];
  snprintf (g[0], sizeof g[0], "mid.%s", bot);
  snprintf (g[1], sizeof g[1], "up.%s", bot);
  snprintf (g[2], sizeof g[2], "lo.%s", top);
  snprintf (g[3], sizeof g[3], "mid.%s", top);
  const char *slave[2] = { g[0], g[1] };
  lac_macro *M[2] = { NULL, NULL };
  check_true (m != NULL, "%s: mesh", what);
  if (!m)
    return;
  int status = lac_macromesh_build_set (&m, 2, slave, NULL, M);
  check_status (status, LAC_SUCCESS, "%s: macro-meshes", what);
  if (status)
    {
      lac_mesh_free (m);
      return;
    }
  lac_pairing_facets Mf[2] = {
    lac_pairing_facets_of (m, lac_mesh_group (m, g[2])),
    lac_pairing_facets_of (m, lac_mesh_group (m, g[3])) };
  lac_contact_pair pr[2];
  for (int p = 0; p < 2; p++)
    {
      pr[p] = (lac_contact_pair) { m, dim == 2 ? LAC_PLANE_STRAIN
                                   : LAC_SOLID3D, M[p], &Mf[p], NULL,
                                   LAC_EPSILON_DEFAULT, 0, { 0 }, 0, 0, 0, 0 };
      lac_pairing_opts_init (&pr[p].popts);
    }
  lac_contact_set s;
  lac_contact_set_data d = { 0 };
  check_status (lac_contact_set_init (&s, pr, 2), LAC_SUCCESS, "%s: init",
                what);
  check_int ((long) s.offset[1], (long) M[0]->n, "%s: offset of pair 1",
             what);
  check_int ((long) lac_contact_set_nslot (&s), (long) (M[0]->n + M[1]->n),
             "%s: slots", what);
  check_int ((long) lac_contact_set_pair_of (&s, M[0]->n - 1), 0,
             "%s: last slot of pair 0", what);
  check_int ((long) lac_contact_set_pair_of (&s, M[0]->n), 1,
             "%s: first slot of pair 1", what);
  check_int ((long) lac_contact_set_pair_of (&s, M[0]->n + M[1]->n), 2,
             "%s: a slot out of range", what);
  check_status (lac_contact_set_build (&s, NULL, &d), LAC_SUCCESS,
                "%s: build", what);
  check_true (d.all && d.all != d.c[0] && d.all->k == d.c[0]->k + d.c[1]->k
              && d.all->nmacro == lac_contact_set_nslot (&s),
              "%s: all = the columns of both pairs", what);
  if (d.all)
    check_against_alone (&s, &d, what);
  lac_contact_set_data_clear (&d);
  lac_contact_set_clear (&s);

  /* one pair: all is its data */
  check_status (lac_contact_set_init (&s, pr + 1, 1), LAC_SUCCESS,
                "%s: one pair", what);
  check_status (lac_contact_set_build (&s, NULL, &d), LAC_SUCCESS,
                "%s: one pair, build", what);
  check_true (d.all && d.all == d.c[0], "%s: one pair: all is c[0]", what);
  lac_contact_set_data_clear (&d);
  lac_contact_set_clear (&s);

  /* node-to-segment among two */
  pr[1].nts = 1;
  check_status (lac_contact_set_init (&s, pr, 2), LAC_EINVAL, "%s: nts",
                what);
  check_message ("node-to-segment", "%s: nts message", what);
  lac_contact_set_clear (&s);
  lac_macromesh_free (M[0]);
  lac_macromesh_free (M[1]);
  lac_mesh_free (m);
}

int
main (void)
{
  run (LAC_QUAD4, 2, "quad4");
  run (LAC_QUAD8, 2, "quad8");
  run (LAC_HEX8, 3, "hex8");
  run (LAC_TET10, 3, "tet10");
  return check_summary ();
}
