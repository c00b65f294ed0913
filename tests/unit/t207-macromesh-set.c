/* t207: several slave groups in one pass; corners        [LAC Hyp. 1, §4.4]
 *
 * lac_macromesh_build_set on box meshes:
 *   - two or three slave groups whose cells are cut in the same pass (a
 *     hex8 box one cell thick: every cell owns a facet of zmin and of
 *     zmax): each macro-mesh lists exactly the facets of its group in the
 *     mesh returned, every index valid; the options of each group (pyramids
 *     for one, six hexahedra for another) are its own;
 *   - Hypothesis 1 for all of them: the designated node of every
 *     macro-element is interior to it and on no macro-element of any
 *     group;
 *   - a facet in two groups is an error naming both;
 *   - corners: a slave surface turning 90 degrees (xmax and ymax of a
 *     quad4 box, xmax and zmax of hex8 / hex20 / tet4 boxes) gives no
 *     macro-element whose sub-facets have two normals; a quad4 cell with
 *     two lone slave edges at a corner is cut twice.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "base/lac_status.h"

static lac_mesh *
box (lac_elem_type t, size_t n0, size_t n1, size_t n2)
{
  size_t n[3] = { n0, n1, n2 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  check_status (lac_mesh_box (t, n, L, 0.0, &m), LAC_SUCCESS, "box %s",
                lac_refelem_get (t)->name);
  return m;
}

/* Group `name` = groups a and b. */
static void
union_group (lac_mesh *m, const char *name, const char *a, const char *b)
{
  const lac_group *A = lac_mesh_group (m, a), *B = lac_mesh_group (m, b);
  size_t n = A->n + B->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      const lac_group *G = e < A->n ? A : B;
      size_t i = e < A->n ? e : e - A->n;
      cell[e] = G->cell[i];
      face[e] = G->face[i];
    }
  lac_mesh_add_group (m, name, m->dim - 1, 0, n, cell, face);
  free (cell);
  free (face);
}

/* The unit outward normal of facet (cell, face) (straight facets). */
static void
facet_normal (const lac_mesh *m, size_t cell, int face, double *n)
{
  int nodes[LAC_MAX_FACE_NODES], d = m->dim;
  lac_mesh_facet_nodes (m, cell, face, nodes, NULL);
  const double *x0 = m->x + (size_t) nodes[0] * d;
  const double *x1 = m->x + (size_t) nodes[1] * d;
  double a[3] = { 0, 0, 0 }, b[3] = { 0, 0, 0 };
  for (int k = 0; k < d; k++)
    a[k] = x1[k] - x0[k];
  if (d == 2)
    n[0] = a[1], n[1] = -a[0], n[2] = 0;
  else
    {
      const double *x2 = m->x + (size_t) nodes[2] * d;
      for (int k = 0; k < 3; k++)
        b[k] = x2[k] - x0[k];
      n[0] = a[1] * b[2] - a[2] * b[1];
      n[1] = a[2] * b[0] - a[0] * b[2];
      n[2] = a[0] * b[1] - a[1] * b[0];
    }
  double s = sqrt (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int k = 0; k < 3; k++)
    n[k] /= s;
}

/* Macro-elements of M whose sub-facets do not all have one normal. */
static long
straddling (const lac_mesh *m, const lac_macro *M)
{
  long bad = 0;
  for (size_t k = 0; k < M->n; k++)
    {
      double n0[3], n[3];
      facet_normal (m, M->cell[M->ptr[k]], M->face[M->ptr[k]], n0);
      int same = 1;
      for (size_t j = M->ptr[k] + 1; j < M->ptr[k + 1]; j++)
        {
          facet_normal (m, M->cell[j], M->face[j], n);
          same &= n[0] * n0[0] + n[1] * n0[1] + n[2] * n0[2] > 1 - 1e-12;
        }
      bad += !same;
    }
  return bad;
}

/* 1 if the sub-facets of M are exactly the facets of group G. */
static int
same_facets (const lac_macro *M, const lac_group *G)
{
  size_t nf = M->ptr[M->n];
  if (nf != G->n)
    return 0;
  for (size_t j = 0; j < nf; j++)
    {
      int found = 0;
      for (size_t e = 0; e < G->n && !found; e++)
        found = G->cell[e] == M->cell[j] && G->face[e] == M->face[j];
      if (!found)
        return 0;
    }
  return 1;
}

/* Does node a lie on a sub-facet of macro-element k of M? */
static int
on_macro (const lac_mesh *m, const lac_macro *M, size_t k, size_t a)
{
  int nodes[LAC_MAX_FACE_NODES];
  for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
    {
      int nn = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], nodes, NULL);
      for (int i = 0; i < nn; i++)
        if ((size_t) nodes[i] == a)
          return 1;
    }
  return 0;
}

/* Hypothesis 1 over all macro-meshes M[0..n-1]: every designated node is
 * interior to its macro-element and on no other one. */
static void
check_hypothesis (const lac_mesh *m, lac_macro **M, size_t n,
                  const char *what)
{
  long bad = 0;
  for (size_t g = 0; g < n; g++)
    for (size_t k = 0; k < M[g]->n; k++)
      {
        size_t in[64], ni = lac_macromesh_interior (m, M[g], k, in, 64), a;
        int is_in = 0;
        a = M[g]->inode[k];
        for (size_t i = 0; i < ni; i++)
          is_in |= in[i] == a;
        for (size_t h = 0; h < n; h++)
          for (size_t l = 0; l < M[h]->n; l++)
            if ((h != g || l != k) && on_macro (m, M[h], l, a))
              is_in = 0;
        bad += !is_in;
      }
  check_int (bad, 0, "%s: designated nodes not interior to one "
             "macro-element", what);
}

/* Build the macro-meshes of the n groups and check them all. */
static void
check_set (lac_mesh *m, size_t n, const char *const *g,
           const lac_macro_opts *o, const long *want_macros,
           const char *what)
{
  lac_macro *M[4] = { NULL, NULL, NULL, NULL };
  int status = lac_macromesh_build_set (&m, n, g, o, M);
  check_status (status, LAC_SUCCESS, "%s", what);
  for (size_t k = 0; !status && k < n; k++)
    {
      check_true (same_facets (M[k], lac_mesh_group (m, g[k])), "%s: "
                  "macro-mesh %zu = the facets of '%s' in the mesh "
                  "returned", what, k, g[k]);
      check_int (straddling (m, M[k]), 0, "%s: macro-elements of '%s' "
                 "across an edge", what, g[k]);
      if (want_macros)
        check_int ((long) M[k]->n, want_macros[k], "%s: macro-elements of "
                   "'%s'", what, g[k]);
    }
  if (!status)
    check_hypothesis (m, M, n, what);
  for (size_t k = 0; k < n; k++)
    lac_macromesh_free (M[k]);
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();

  /* 1. Two and three groups in one pass, a cell owning facets of two. */
  {
    const char *g[3] = { "zmin", "zmax", "xmax" };
    lac_macro_opts o[3] = { { LAC_MACRO_HEX_PYRAMIDS, 0 },
                            { LAC_MACRO_HEX_SIX, 0 },
                            { LAC_MACRO_HEX_DEFAULT, 0 } };
    long w[3] = { 4, 4, 2 };
    check_set (box (LAC_HEX8, 2, 2, 1), 2, g, o, w, "hex8 zmin+zmax");
    check_set (box (LAC_HEX8, 2, 2, 1), 3, g, o, w, "hex8 three groups");
    check_set (box (LAC_TET4, 2, 2, 1), 3, g, NULL, NULL, "tet4 three");
    check_set (box (LAC_HEX20, 1, 1, 1), 3, g, NULL, NULL, "hex20 three");
    const char *g2[2] = { "ymin", "ymax" };
    long w2[2] = { 1, 1 };
    check_set (box (LAC_QUAD4, 1, 1, 0), 2, g2, NULL, w2, "quad4 one cell");
    check_set (box (LAC_TRI6, 3, 1, 0), 2, g2, NULL, NULL, "tri6 ymin+ymax");
  }

  /* 2. The six hexahedra of one group leave the other's face whole: a
   *    pyramid cut of zmax after a six-hexahedra cut of xmax. */
  {
    const char *g[2] = { "xmax", "zmax" };
    lac_macro_opts o[2] = { { LAC_MACRO_HEX_SIX, 0 },
                            { LAC_MACRO_HEX_PYRAMIDS, 0 } };
    long w[2] = { 1, 1 };
    check_set (box (LAC_HEX8, 1, 1, 1), 2, g, o, w, "six then pyramids");
  }

  /* 3. A facet in two groups. */
  {
    lac_mesh *m = box (LAC_HEX8, 2, 2, 2);
    lac_macro *M[2] = { NULL, NULL };
    union_group (m, "u", "xmax", "zmax");
    const char *g[2] = { "zmax", "u" };
    check_status (lac_macromesh_build_set (&m, 2, g, NULL, M), LAC_EINVAL,
                  "shared facet");
    check_message ("'zmax' and 'u' share a facet", "shared facet: names "
                   "both groups");
    check_true (!M[0] && !M[1], "shared facet: no macro-mesh");
    lac_mesh_free (m);
  }

  /* 4. Corners: one slave surface turning 90 degrees. */
  {
    const char *g[1] = { "u" };
    static const lac_elem_type t3[] = { LAC_HEX8, LAC_HEX20, LAC_TET4,
                                        LAC_TET10, LAC_HEX27 };
    lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 }, across = { 0, 2 };
    long w3 = 6, w1 = 2;
    lac_mesh *m = box (LAC_QUAD4, 3, 3, 0);
    union_group (m, "u", "xmax", "ymax");
    check_set (m, 1, g, NULL, &w1, "quad4 corner, chains of 3");
    m = box (LAC_QUAD4, 2, 2, 0);
    union_group (m, "u", "xmax", "ymax");
    check_set (m, 1, g, NULL, &w1, "quad4 corner, chains of 2");
    m = box (LAC_QUAD4, 1, 1, 0);
    union_group (m, "u", "xmax", "ymax");
    check_set (m, 1, g, NULL, &w1, "quad4 corner, lone segments");
    m = box (LAC_TRI3, 3, 2, 0);
    union_group (m, "u", "xmax", "ymax");
    check_set (m, 1, g, NULL, NULL, "tri3 corner");
    for (size_t t = 0; t < sizeof t3 / sizeof *t3; t++)
      {
        char what[64];
        m = box (t3[t], 1, 2, 2);
        union_group (m, "u", "xmax", "zmax");
        snprintf (what, sizeof what, "%s corner",
                  lac_refelem_get (t3[t])->name);
        check_set (m, 1, g, NULL, t3[t] == LAC_TET4 || t3[t] == LAC_TET10
                   ? NULL : &w3, what);
      }
    m = box (LAC_HEX8, 1, 2, 2);
    union_group (m, "u", "xmax", "zmax");
    check_set (m, 1, g, &six, &w3, "hex8 corner, six hexahedra");
    /* Gathered across the corner on request: a macro-element spans it. */
    lac_macro *M = NULL;
    m = box (LAC_QUAD4, 3, 3, 0);
    union_group (m, "u", "xmax", "ymax");
    check_status (lac_macromesh_build (&m, "u", &across, &M), LAC_SUCCESS,
                  "across");
    check_int (M ? straddling (m, M) : -1, 1, "quad4 corner gathered "
               "across it (cut_2d = 2): one macro-element spans it");
    lac_macromesh_free (M);
    lac_mesh_free (m);
  }
  lac_finalize ();
  return check_summary ();
}
