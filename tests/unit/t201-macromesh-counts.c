/* t201: node/cell counts of the macro-mesh refinement   [LAC §4.4, Hyp. 1]
 *
 * Per slave face, with lac_mesh storing only top-dimensional cells:
 *   tet4  +1 node  (face centroid), 1 -> 3 tet4: +2 cells, face -> 3 tri3
 *   tet10 +5 nodes (centroid, 3 centroid-vertex midpoints, 1 centroid-apex
 *         midpoint), 1 -> 3 tet10: +2 cells, face -> 3 tri6, 4 interior nodes
 *   hex8  +1 node (face centre), 1 -> 5 pyr5: +4 cells, face -> 4 tri3.
 *         (chapter 03 counts faces and edges as gmsh does: 8 nodes/19 cells
 *         -> 9/26 = 5 pyramids + 5 old faces + 4 triangles + 12 edges.)
 *   hex8 SIX  +8 nodes, 1 -> 6 hex8: +5 cells, face -> 5 quad4, 4 interior
 *   hex20 +28 nodes (8 vertices, 20 new edge mid-nodes), 1 -> 6 hex20,
 *         face -> 5 quad8, 12 interior nodes
 *   hex27, tri6, quad8, quad9: nothing (centre / mid node exists)
 *   pyr5  base: +1 node, 1 -> 4 tet4; side: +1 node, 1 -> pyr5 + 3 tet4
 *   tri3 / quad4 isolated segment: +1 node, 1 -> 2 tri3 / 3 tri3;
 *   2D linear chains: gathered, nothing refined.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "contact/lac_macromesh.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* One cell of type t with its reference nodes mapped by x = A xi + b, and
 * the facet group "s" = face f. */
static lac_mesh *
one_cell (lac_elem_type t, int f)
{
  static const double A[3][3] = { { 1.0, 0.2, 0.1 }, { -0.1, 0.9, 0.15 },
                                  { 0.05, -0.2, 1.1 } };
  const lac_refelem *re = lac_refelem_get (t);
  int d = re->dim;
  lac_mesh *m = lac_mesh_alloc (d, (size_t) re->nnodes, 1,
                                (size_t) re->nnodes);
  size_t cell = 0;
  for (int a = 0; a < re->nnodes; a++)
    {
      for (int i = 0; i < d; i++)
        {
          double x = 0.3 * i;
          for (int k = 0; k < d; k++)
            x += A[i][k] * re->xi[a * d + k];
          m->x[a * d + i] = x;
        }
      m->conn[a] = a;
    }
  m->type[0] = t;
  m->ptr[1] = (size_t) re->nnodes;
  lac_mesh_add_group (m, "s", d - 1, 0, 1, &cell, &f);
  return m;
}

/* Group "u" = union of the facet groups a and b. */
static void
union_group (lac_mesh *m, const char *a, const char *b)
{
  const lac_group *A = lac_mesh_group (m, a), *B = lac_mesh_group (m, b);
  size_t n = A->n + B->n, *cell = malloc (n * sizeof *cell);
  int *face = malloc (n * sizeof *face);
  for (size_t e = 0; e < n; e++)
    {
      cell[e] = e < A->n ? A->cell[e] : B->cell[e - A->n];
      face[e] = e < A->n ? A->face[e] : B->face[e - A->n];
    }
  lac_mesh_add_group (m, "u", A->dim, 0, n, cell, face);
  free (cell);
  free (face);
}

typedef struct expect
{
  long dnodes, dcells;   /* change of node and cell counts               */
  long nmacro;           /* macro-elements                                */
  long nsub;             /* sub-facets of macro 0                         */
  long ninter;           /* interior nodes of macro 0                     */
  long rounds;
} expect;

static void
check_build (lac_mesh *m, const char *group, const lac_macro_opts *opts,
             expect w, const char *what)
{
  size_t nn0 = m->nnodes, nc0 = m->ncells, inter[64];
  lac_macro *M = NULL;
  int status = lac_macromesh_build (&m, group, opts, &M);
  check_status (status, LAC_SUCCESS, "%s: build", what);
  if (status)
    {
      lac_mesh_free (m);
      return;
    }
  check_int ((long) (m->nnodes - nn0), w.dnodes, "%s: new nodes", what);
  check_int ((long) (m->ncells - nc0), w.dcells, "%s: new cells", what);
  check_int ((long) M->n, w.nmacro, "%s: macro-elements", what);
  check_int ((long) (M->ptr[1] - M->ptr[0]), w.nsub, "%s: sub-facets", what);
  check_int ((long) lac_macromesh_interior (m, M, 0, inter, 64), w.ninter,
             "%s: interior nodes", what);
  check_int (M->nrounds, w.rounds, "%s: rounds", what);
  check_int ((long) M->nnew, w.dnodes, "%s: M->nnew", what);
  check_int ((long) lac_mesh_group (m, group)->n, (long) M->ptr[M->n],
             "%s: slave group = all sub-facets", what);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

static lac_mesh *
box (lac_elem_type t, size_t n0, size_t n1, size_t n2)
{
  size_t n[3] = { n0, n1, n2 };
  double L[3] = { 1, 1, 1 };
  lac_mesh *m = NULL;
  int status = lac_mesh_box (t, n, L, 0.1, &m);
  check_status (status, LAC_SUCCESS, "box %s", lac_refelem_get (t)->name);
  return m;
}

/* The 4 sides of a 2x1 quad4 box as one group "loop" (6 segments). */
static lac_mesh *
loop6 (void)
{
  lac_mesh *m = box (LAC_QUAD4, 2, 1, 0);
  const lac_group *G[4] = { lac_mesh_group (m, "xmin"),
                            lac_mesh_group (m, "ymin"),
                            lac_mesh_group (m, "xmax"),
                            lac_mesh_group (m, "ymax") };
  size_t cell[6], n = 0;
  int face[6];
  for (int g = 0; g < 4; g++)
    for (size_t e = 0; e < G[g]->n; e++, n++)
      cell[n] = G[g]->cell[e], face[n] = G[g]->face[e];
  lac_mesh_add_group (m, "loop", 1, 0, n, cell, face);
  return m;
}

int
main (void)
{
  lac_macro_opts six = { LAC_MACRO_HEX_SIX, 0 }, cut2d = { 0, 1 };
  lac_macro_opts across = { 0, 2 };
  char what[64];

  lac_init ();

  /* 1. One cell, each face in turn. */
  for (int f = 0; f < 4; f++)
    {
      snprintf (what, sizeof what, "tet4 face %d", f);
      check_build (one_cell (LAC_TET4, f), "s", NULL,
                   (expect) { 1, 2, 1, 3, 1, 1 }, what);
      snprintf (what, sizeof what, "tet10 face %d", f);
      check_build (one_cell (LAC_TET10, f), "s", NULL,
                   (expect) { 5, 2, 1, 3, 4, 1 }, what);
    }
  for (int f = 0; f < 6; f++)
    {
      snprintf (what, sizeof what, "hex8 face %d", f);
      check_build (one_cell (LAC_HEX8, f), "s", NULL,
                   (expect) { 1, 4, 1, 4, 1, 1 }, what);
      snprintf (what, sizeof what, "hex8 six face %d", f);
      check_build (one_cell (LAC_HEX8, f), "s", &six,
                   (expect) { 8, 5, 1, 5, 4, 1 }, what);
      snprintf (what, sizeof what, "hex20 face %d", f);
      check_build (one_cell (LAC_HEX20, f), "s", NULL,
                   (expect) { 28, 5, 1, 5, 12, 1 }, what);
      snprintf (what, sizeof what, "hex27 face %d", f);
      check_build (one_cell (LAC_HEX27, f), "s", NULL,
                   (expect) { 0, 0, 1, 1, 1, 0 }, what);
    }
  check_build (one_cell (LAC_PYR5, 0), "s", NULL,
               (expect) { 1, 3, 1, 4, 1, 1 }, "pyr5 base");
  for (int f = 1; f < 5; f++)
    {
      snprintf (what, sizeof what, "pyr5 face %d", f);
      check_build (one_cell (LAC_PYR5, f), "s", NULL,
                   (expect) { 1, 3, 1, 3, 1, 1 }, what);
    }
  for (int f = 0; f < 3; f++)
    {
      snprintf (what, sizeof what, "tri3 lone edge %d", f);
      check_build (one_cell (LAC_TRI3, f), "s", NULL,
                   (expect) { 1, 1, 1, 2, 1, 1 }, what);
      snprintf (what, sizeof what, "tri6 edge %d", f);
      check_build (one_cell (LAC_TRI6, f), "s", NULL,
                   (expect) { 0, 0, 1, 1, 1, 0 }, what);
    }
  for (int f = 0; f < 4; f++)
    {
      snprintf (what, sizeof what, "quad4 lone edge %d", f);
      check_build (one_cell (LAC_QUAD4, f), "s", NULL,
                   (expect) { 1, 2, 1, 2, 1, 1 }, what);
      snprintf (what, sizeof what, "quad8 edge %d", f);
      check_build (one_cell (LAC_QUAD8, f), "s", NULL,
                   (expect) { 0, 0, 1, 1, 1, 0 }, what);
      snprintf (what, sizeof what, "quad9 edge %d", f);
      check_build (one_cell (LAC_QUAD9, f), "s", NULL,
                   (expect) { 0, 0, 1, 1, 1, 0 }, what);
    }

  /* 2. Box meshes, slave = zmax: no cell owns two slave faces, so the
   *    counts are per face.  2x2x2 tet4: 4 top boxes, 2 tets each. */
  check_build (box (LAC_TET4, 2, 2, 2), "zmax", NULL,
               (expect) { 8, 16, 8, 3, 1, 1 }, "tet4 box");
  check_build (box (LAC_TET10, 2, 2, 2), "zmax", NULL,
               (expect) { 40, 16, 8, 3, 4, 1 }, "tet10 box");
  check_build (box (LAC_HEX8, 2, 2, 1), "zmax", NULL,
               (expect) { 4, 16, 4, 4, 1, 1 }, "hex8 box");
  check_build (box (LAC_HEX8, 2, 2, 1), "zmax", &six,
               (expect) { 32, 20, 4, 5, 4, 1 }, "hex8 six box");
  check_build (box (LAC_HEX20, 2, 2, 1), "zmax", NULL,
               (expect) { 112, 20, 4, 5, 12, 1 }, "hex20 box");
  check_build (box (LAC_HEX27, 2, 2, 1), "zmax", NULL,
               (expect) { 0, 0, 4, 1, 1, 0 }, "hex27 box");

  /* 3. One cell with two slave faces (zmax and xmax): two rounds.
   *    hex8: 5 pyramids, then the pyramid on xmax -> 4 tets: 8 cells.
   *    hex8 six / hex20: 6 hexes, then the trapezoid hex on xmax -> 6.
   *    tet4 (Kuhn, 6 tets): no tet owns both faces: one round. */
  {
    struct { lac_elem_type t; const lac_macro_opts *o; expect w;
             const char *name; } c2[] = {
      { LAC_HEX8, NULL, { 2, 7, 2, 4, 1, 2 }, "hex8 2 faces" },
      { LAC_HEX8, &six, { 16, 10, 2, 5, 4, 2 }, "hex8 six 2 faces" },
      { LAC_HEX20, NULL, { 56, 10, 2, 5, 12, 2 }, "hex20 2 faces" },
      { LAC_TET4, NULL, { 4, 8, 4, 3, 1, 1 }, "tet4 2 faces" },
      { LAC_TET10, NULL, { 20, 8, 4, 3, 4, 1 }, "tet10 2 faces" },
    };
    for (size_t i = 0; i < sizeof c2 / sizeof c2[0]; i++)
      {
        lac_mesh *m = box (c2[i].t, 1, 1, 1);
        union_group (m, "zmax", "xmax");
        check_build (m, "u", c2[i].o, c2[i].w, c2[i].name);
      }
    /* all six faces of one hex8: 5 pyramids, then (round 2) each of them
     * cut on its base into 4 tets */
    {
      lac_mesh *m = box (LAC_HEX8, 1, 1, 1);
      size_t cell[6] = { 0, 0, 0, 0, 0, 0 };
      int face[6] = { 0, 1, 2, 3, 4, 5 };
      lac_mesh_add_group (m, "all", 2, 0, 6, cell, face);
      check_build (m, "all", NULL, (expect) { 6, 4 + 5 * 3, 6, 4, 1, 2 },
                   "hex8 6 faces");
    }
  }

  /* 4. 2D.  Gathering: ymax of a 2x2 tri3 box is one chain of 2 -> one
   *    macro; 3x1 quad4: a chain of 3 -> one macro of 3 (2 interior
   *    nodes); 1x1: a lone segment -> its cell is cut.  Two chains
   *    (ymin, ymax) of 3 -> 2 macros.  Closed loop (4 sides of a 2x1
   *    box, 6 segments) gathered across its corners (cut_2d = 2) -> 3
   *    macros; broken at its corners (the default) -> pieces of 2, 1, 2,
   *    1 segments: 2 macros and 2 cells cut (2 x 3 tri3, 2 nodes).
   *    Quadratic: one macro per segment. */
  check_build (box (LAC_TRI3, 2, 2, 0), "ymax", NULL,
               (expect) { 0, 0, 1, 2, 1, 0 }, "tri3 chain 2");
  check_build (box (LAC_QUAD4, 3, 1, 0), "ymax", NULL,
               (expect) { 0, 0, 1, 3, 2, 0 }, "quad4 chain 3");
  check_build (box (LAC_TRI3, 1, 1, 0), "ymax", NULL,
               (expect) { 1, 1, 1, 2, 1, 1 }, "tri3 lone segment");
  check_build (box (LAC_QUAD4, 1, 1, 0), "ymax", NULL,
               (expect) { 1, 2, 1, 2, 1, 1 }, "quad4 lone segment");
  check_build (box (LAC_TRI3, 2, 1, 0), "ymax", &cut2d,
               (expect) { 2, 2, 2, 2, 1, 1 }, "tri3 cut_2d");
  {
    lac_mesh *m = box (LAC_QUAD4, 3, 2, 0);
    union_group (m, "ymin", "ymax");
    check_build (m, "u", NULL, (expect) { 0, 0, 2, 3, 2, 0 }, "two chains");
  }
  check_build (loop6 (), "loop", &across, (expect) { 0, 0, 3, 2, 1, 0 },
               "loop 6");
  check_build (loop6 (), "loop", NULL, (expect) { 2, 4, 4, 2, 1, 1 },
               "loop 6, corners");
  check_build (box (LAC_TRI6, 3, 1, 0), "ymax", NULL,
               (expect) { 0, 0, 3, 1, 1, 0 }, "tri6 box");
  check_build (box (LAC_QUAD8, 3, 1, 0), "ymax", NULL,
               (expect) { 0, 0, 3, 1, 1, 0 }, "quad8 box");
  check_build (box (LAC_QUAD9, 3, 1, 0), "ymax", NULL,
               (expect) { 0, 0, 3, 1, 1, 0 }, "quad9 box");

  lac_finalize ();
  return check_summary ();
}
