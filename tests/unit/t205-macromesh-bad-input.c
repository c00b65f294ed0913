/* t205: bad input to the macro-mesh builder gives a clear error  [LAC §4.4]
 *
 * Missing, empty or cell (not facet) slave group; a facet listed twice; an
 * interior facet; a type that cannot be refined (hex20 with the pyramid cut:
 * no pyramid13; a quad9 coned by lac_refine_cut would lose its centre
 * node); bad options; NULL arguments.  Each returns LAC_EINVAL, leaves the
 * mesh alone, and stores a message naming the culprit.  Last, every
 * allocation is made to fail in turn: the result is LAC_ENOMEM with the
 * mesh untouched, or success.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_refine.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

static lac_mesh *
box (lac_elem_type t, size_t nb)
{
  size_t n[3] = { nb, nb, nb };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  lac_mesh_box (t, n, L, 0, &m);
  return m;
}

/* Build must fail with `want` and a message containing `needle`, leaving
 * the mesh pointer and its sizes unchanged. */
static void
expect_fail (lac_mesh *m, const char *slave, const lac_macro_opts *opts,
             int want, const char *needle, const char *what)
{
  lac_mesh *m0 = m;
  size_t nn = m->nnodes, nc = m->ncells;
  lac_macro *M = (lac_macro *) 1;
  lac_error_clear ();
  check_status (lac_macromesh_build (&m, slave, opts, &M), want, "%s", what);
  check_message (needle, "%s: message names '%s'", what, needle);
  check_true (M == NULL, "%s: no macro-mesh returned", what);
  check_true (m == m0 && m->nnodes == nn && m->ncells == nc,
              "%s: mesh unchanged", what);
}

int
main (void)
{
  lac_init ();

  /* 1. The group. */
  {
    lac_mesh *m = box (LAC_TET4, 1);
    expect_fail (m, "contact", NULL, LAC_EINVAL, "contact", "missing group");
    expect_fail (m, "contact", NULL, LAC_EINVAL, "zmax",
                 "missing group lists the groups");
    lac_mesh_add_group (m, "empty", 2, 0, 0, NULL, NULL);
    expect_fail (m, "empty", NULL, LAC_EINVAL, "'empty' is empty",
                 "empty group");
    expect_fail (m, "body", NULL, LAC_EINVAL, "dimension 3",
                 "cell group as slave");
    lac_mesh_free (m);
  }

  /* 2. Facets: twice, interior. */
  {
    lac_mesh *m = box (LAC_TET4, 1);
    const lac_group *Z = lac_mesh_group (m, "zmax");
    size_t cell[2] = { Z->cell[0], Z->cell[0] };
    int face[2] = { Z->face[0], Z->face[0] }, interior = -1;
    lac_mesh_add_group (m, "twice", 2, 0, 2, cell, face);
    expect_fail (m, "twice", NULL, LAC_EINVAL, "twice", "facet twice");
    /* an interior face of cell 0: not on any side of the box */
    for (int f = 0; f < 4 && interior < 0; f++)
      {
        int side = 0;
        for (size_t g = 0; g < m->ngroups; g++)
          for (size_t e = 0; e < m->group[g].n; e++)
            side |= m->group[g].dim == 2 && m->group[g].cell[e] == 0
                    && m->group[g].face[e] == f;
        if (!side)
          interior = f;
      }
    cell[0] = 0;
    lac_mesh_add_group (m, "inner", 2, 0, 1, cell, &interior);
    expect_fail (m, "inner", NULL, LAC_EINVAL, "interior", "interior facet");
    lac_mesh_free (m);
  }

  /* 3. Types that cannot be refined. */
  {
    lac_mesh *m = box (LAC_HEX20, 1);
    lac_macro_opts pyr = { LAC_MACRO_HEX_PYRAMIDS, 0 };
    expect_fail (m, "zmax", &pyr, LAC_EINVAL, "hex20",
                 "hex20 into pyramids");
    check_message ("pyramid13", "hex20 into pyramids: says why");
    lac_mesh_free (m);
  }
  {
    lac_mesh *m = box (LAC_QUAD9, 1), *r = NULL;
    lac_refine_map *map = NULL;
    int cut[1] = { 0 };
    lac_error_clear ();
    check_status (lac_refine_cut (m, cut, NULL, &r, &map), LAC_EINVAL,
                  "quad9 coned");
    check_message ("quad9", "quad9 coned: names the type");
    check_true (!r && !map, "quad9 coned: no output");
    cut[0] = 7;
    check_status (lac_refine_cut (m, cut, NULL, &r, &map), LAC_EINVAL,
                  "face out of range");
    check_message ("no face 7", "face out of range: names the face");
    lac_mesh_free (m);
  }
  {
    lac_mesh *m = box (LAC_HEX27, 1), *r = NULL;
    lac_refine_map *map = NULL;
    lac_macro_opts pyr = { LAC_MACRO_HEX_PYRAMIDS, 0 };
    int cut[1] = { 5 };
    check_status (lac_refine_cut (m, cut, &pyr, &r, &map), LAC_EINVAL,
                  "hex27 into pyramids");
    check_message ("hex27", "hex27 into pyramids: names the type");
    lac_mesh_free (m);
  }

  /* 4. Options and NULL arguments. */
  {
    lac_mesh *m = box (LAC_HEX8, 1), *null = NULL;
    lac_macro_opts bad = { 7, 0 };
    lac_macro *M = NULL;
    expect_fail (m, "zmax", &bad, LAC_EINVAL, "hex_cut = 7", "bad options");
    check_status (lac_macromesh_build (&m, NULL, NULL, &M), LAC_EINVAL,
                  "NULL group name");
    check_status (lac_macromesh_build (&null, "zmax", NULL, &M), LAC_EINVAL,
                  "NULL mesh");
    check_status (lac_macromesh_build (NULL, "zmax", NULL, &M), LAC_EINVAL,
                  "NULL mesh pointer");
    check_status (lac_macromesh_build (&m, "zmax", NULL, NULL), LAC_EINVAL,
                  "NULL output");
    check_true (lac_macromesh_interior (m, NULL, 0, NULL, 0) == 0,
                "interior of no macro-mesh");
    lac_macromesh_free (NULL);
    lac_refine_map_free (NULL);
    lac_mesh_free (m);
  }

  /* 5. Allocation failures, one after the other. */
  {
    struct { lac_elem_type t; size_t nb; const char *slave; } c[] = {
      { LAC_HEX8, 1, "all" }, { LAC_TET10, 2, "zmax" },
      { LAC_TRI3, 3, "all" }, { LAC_HEX20, 1, "zmax" } };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
      {
        int done = 0;
        for (long k = 0; k < 1000 && !done; k++)
          {
            lac_mesh *m = box (c[i].t, c[i].nb), *m0 = m;
            lac_macro *M = NULL;
            int status;
            if (!strcmp (c[i].slave, "all"))
              {
                /* every boundary facet: several per cell, several rounds */
                size_t cell[64], n = 0;
                int face[64];
                for (size_t g = 0; g < m->ngroups; g++)
                  if (m->group[g].dim == m->dim - 1)
                    for (size_t e = 0; e < m->group[g].n && n < 64; e++, n++)
                      cell[n] = m->group[g].cell[e],
                      face[n] = m->group[g].face[e];
                lac_mesh_add_group (m, "all", m->dim - 1, 0, n, cell, face);
              }
            lac_mem_fail_after (k);
            status = lac_macromesh_build (&m, c[i].slave, NULL, &M);
            lac_mem_fail_after (-1);
            if (status == LAC_SUCCESS)
              done = 1;
            else
              {
                check_status (status, LAC_ENOMEM, "%s: allocation %ld fails",
                              lac_refelem_get (c[i].t)->name, k);
                check_true (m == m0 && !M, "%s: allocation %ld fails: mesh "
                            "kept", lac_refelem_get (c[i].t)->name, k);
              }
            lac_macromesh_free (M);
            lac_mesh_free (m);
          }
        check_true (done, "%s: builds once allocations succeed",
                    lac_refelem_get (c[i].t)->name);
      }
  }

  lac_finalize ();
  return check_summary ();
}
