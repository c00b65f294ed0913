/* LAC chapter 03 -- The macro-mesh of the slave surface
 *                                          [LAC Hyp. 1, Remark 1, §4.4, Fig. 2]
 *
 * Build:        make build/chapters/03-macromesh
 * Sample runs:  build/chapters/03-macromesh          (hex8 -> 5 pyr5)
 *               build/chapters/03-macromesh --six    (hex8 -> 6 hex8)
 * Description:  Small box meshes of every family (tet4, hex8, tet10, hex20,
 *               hex27 in 3D; quad4, quad8 in 2D).  The macro-mesh T^M of
 *               the top face is built with lac_macromesh_build, and the
 *               program prints what it did: nodes and cells before and
 *               after the local refinement, the macro-elements, their
 *               sub-facets and interior nodes, the designated interior node
 *               x_{m*+1} of T^0 and the mean of its basis function [LAC
 *               Hyp. 1, Remark 1].  It then draws the refined cells of one
 *               hex8 face (the 5 pyramids of code_aster's default cut), the
 *               pairs and triple of a 2D chain of segments, and the rounds
 *               of a cube with two slave faces.  Short, deterministic
 *               output.
 * Read first:   chapter 02 (spaces: the averages of trace basis functions).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/lac_macromesh.h"
#include "fem/lac_mesh.h"
#include "base/lac_status.h"

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "ex03: %s failed: %s (%s)\n", what, lac_error_message (),
           lac_strerror (status));
  exit (1);
}

/* Turn -0 into +0 for a stable printout. */
static double
clean (double v)
{
  return fabs (v) < 1e-12 ? 0.0 : v;
}

/* Print node a as "(x, y[, z])". */
static void
print_point (const lac_mesh *m, size_t a)
{
  printf ("(");
  for (int k = 0; k < m->dim; k++)
    printf ("%s%.2f", k ? ", " : "", clean (m->x[(size_t) m->dim * a
                                                  + (size_t) k]));
  printf (")");
}

static int
cmp_size (const void *a, const void *b)
{
  size_t x = *(const size_t *) a, y = *(const size_t *) b;
  return x < y ? -1 : x > y;
}

/* One case of step 1: an element type, the box and what we expect of the
 * mean of the designated basis function (a closed form, derived in the
 * README). */
typedef struct box_case
{
  lac_elem_type type;
  size_t n[3];
  const char *mean;     /* the closed form, as text */
} box_case;

int
main (int argc, char **argv)
{
  lac_macro_opts opts = { LAC_MACRO_HEX_DEFAULT, 0 };
  for (int k = 1; k < argc; k++)
    {
      if (!strcmp (argv[k], "--six"))
        opts.hex_cut = LAC_MACRO_HEX_SIX;
      else
        {
          fprintf (stderr, "usage: ex03 [--six]\n");
          return 2;
        }
    }
  lac_init ();

  // @sect Macro-meshes of the top face, family by family
  /* 1. For each element type, a box of unit cubes (squares in 2D) whose top
   *    face ("zmax", "ymax" in 2D) is the slave surface $\Gamma_C^1$.
   *    lac_macromesh_build replaces the mesh by its refined version and
   *    returns $T^M$: macro-element $T^m$ has the sub-facets
   *    ptr[m] .. ptr[m+1]-1, the designated interior node inode[m] and
   *    phi[m] $= \int_{T^m} \phi_{m^*+1}\,d\Gamma$, so that the mean of
   *    the basis function is phi[m] / meas[m].
   *
   *    What to expect [LAC §4.4]: 2D linear segments are gathered two by
   *    two (a chain of odd length ends with a triple), 2D quadratic
   *    segments and hex27 faces are macro-elements as they are, and the
   *    other 3D cells that own a slave face are cut so that the face
   *    gets an interior node (tet4, tet10, hex8: cones from the face
   *    centre; hex20: six hexahedra). */
  static const box_case cases[] = {
    { LAC_TET4, { 2, 2, 1 }, "1/3" },  { LAC_HEX8, { 2, 2, 1 }, "1/3" },
    { LAC_TET10, { 2, 2, 1 }, "2/9" }, { LAC_HEX20, { 2, 2, 1 }, "5/36" },
    { LAC_HEX27, { 2, 2, 1 }, "4/9" }, { LAC_QUAD4, { 5, 1, 0 }, "1/2" },
    { LAC_QUAD8, { 5, 1, 0 }, "2/3" },
  };
  const size_t ncases = sizeof cases / sizeof cases[0];
  printf ("1. macro-meshes of the top face (%s cut for hex8)\n",
          opts.hex_cut == LAC_MACRO_HEX_SIX ? "six-hexahedra" : "pyramid");
  printf ("   type   facets  nodes       cells     rounds  T^m  sub-facets"
          "  interior  x_{m*+1} of T^0       mean of phi\n");
  lac_mesh *hex8 = NULL;           /* kept for step 2 */
  lac_macro *hex8_M = NULL;
  size_t hex8_nn0 = 0;             /* its nodes before refinement */
  for (size_t i = 0; i < ncases; i++)
    {
      const box_case *bc = &cases[i];
      const lac_refelem *re = lac_refelem_get (bc->type);
      double L[3] = { (double) bc->n[0], (double) bc->n[1],
                      (double) bc->n[2] };
      const char *top = re->dim == 3 ? "zmax" : "ymax";
      lac_mesh *m = NULL;
      lac_macro *M = NULL;
      check_status (lac_mesh_box (bc->type, bc->n, L, 0.0, &m),
                    "lac_mesh_box");
      size_t nn0 = m->nnodes, nc0 = m->ncells;
      size_t nf0 = lac_mesh_group (m, top)->n;
      check_status (lac_macromesh_build (&m, top, &opts, &M),
                    "lac_macromesh_build");

      /* Sub-facets per macro-element (smallest and largest) and interior
       * nodes of $T^0$. */
      size_t smin = (size_t) -1, smax = 0, inter[64];
      for (size_t k = 0; k < M->n; k++)
        {
          size_t s = M->ptr[k + 1] - M->ptr[k];
          smin = s < smin ? s : smin;
          smax = s > smax ? s : smax;
        }
      size_t ni = lac_macromesh_interior (m, M, 0, inter, 64);
      char sub[16];
      if (smin == smax)
        snprintf (sub, sizeof sub, "%zu", smin);
      else
        snprintf (sub, sizeof sub, "%zu or %zu", smin, smax);
      const char *mean = bc->type == LAC_HEX8
                         && opts.hex_cut == LAC_MACRO_HEX_SIX ? "7/48"
                                                              : bc->mean;
      printf ("   %-5s  %6zu  %3zu -> %3zu  %2zu -> %2zu  %6d  %3zu  %10s"
              "  %8zu  %3zu ", re->name, nf0, nn0, m->nnodes, nc0,
              m->ncells, M->nrounds, M->n, sub, ni, M->inode[0]);
      print_point (m, M->inode[0]);
      printf ("%*s%.6f = %s\n", re->dim == 3 ? 2 : 8, "",
              M->phi[0] / M->meas[0], mean);
      if (bc->type == LAC_HEX8)
        {
          hex8 = m;
          hex8_M = M;
          hex8_nn0 = nn0;
        }
      else
        {
          lac_macromesh_free (M);
          lac_mesh_free (m);
        }
    }

  // @sect Drawing the refined cells of one hex8 face
  /* 2. The first macro-element of the hex8 box.  With the default (pyramid)
   *    cut, the cell under its slave face became 5 pyramids whose common
   *    apex $c$ is the new node at the face centre: one pyramid over each
   *    of the 5 other faces of the hexahedron, which are left whole (so the
   *    neighbours still see the faces they saw).  The slave face became 4
   *    triangles around $c$, and $c$ is the interior node: its hat
   *    function lives on the 4 triangles only.  With --six, the cell became
   *    6 hexahedra and the face a central square and 4 trapezoids. */
  {
    const lac_mesh *m = hex8;
    const lac_macro *M = hex8_M;
    size_t c = M->inode[0], list[16], nlist = 0;
    printf ("2. the refined cells of one hex8 face (macro-element T^0)\n");
    printf ("   designated interior node %zu at ", c);
    print_point (m, c);
    printf (", mean of phi %.6f\n", M->phi[0] / M->meas[0]);
    /* The sub-cells of the cut cell: a cut cell is replaced, in place, by
     * its sub-cells, which keep its tag (cell_tag). */
    size_t tag = m->cell_tag[M->cell[M->ptr[0]]];
    for (size_t e = 0; e < m->ncells; e++)
      if (m->cell_tag[e] == tag && nlist < 16)
        list[nlist++] = e;
    printf ("   %zu sub-cells (gmsh node order):\n", nlist);
    for (size_t j = 0; j < nlist; j++)
      {
        size_t e = list[j];
        printf ("     cell %2zu  %-5s", e, lac_refelem_get (m->type[e])->name);
        for (size_t p = m->ptr[e]; p < m->ptr[e + 1]; p++)
          printf (" %2d", m->conn[p]);
        printf ("\n");
      }
    printf ("   %zu sub-facets of T^0 (outward):\n",
            M->ptr[1] - M->ptr[0]);
    for (size_t j = M->ptr[0]; j < M->ptr[1]; j++)
      {
        int fn[LAC_MAX_FACE_NODES];
        lac_elem_type ft;
        int nf = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], fn, &ft);
        printf ("     cell %2zu face %d  %-5s", M->cell[j], M->face[j],
                lac_refelem_get (ft)->name);
        for (int a = 0; a < nf; a++)
          printf (" %2d", fn[a]);
        printf ("\n");
      }
    /* The nodes of the cut cell: the parent's 8 vertices and the new
     * one(s), placed by the parent's isoparametric map. */
    size_t node[64], nnode = 0;
    for (size_t j = 0; j < nlist; j++)
      for (size_t p = m->ptr[list[j]]; p < m->ptr[list[j] + 1]; p++)
        {
          size_t a = (size_t) m->conn[p], q = 0;
          while (q < nnode && node[q] != a)
            q++;
          if (q == nnode && nnode < 64)
            node[nnode++] = a;
        }
    qsort (node, nnode, sizeof node[0], cmp_size);
    printf ("   their nodes (new: %zu and up):", hex8_nn0);
    for (size_t q = 0; q < nnode; q++)
      {
        printf ("%s%2zu ", q % 3 ? "   " : "\n     ", node[q]);
        print_point (m, node[q]);
      }
    printf ("\n");
  }
  lac_macromesh_free (hex8_M);
  lac_mesh_free (hex8);

  // @sect Gathering a 2D chain of segments
  /* 3. In 2D with linear elements nothing is refined: the top of a row of
   *    5 quad4 is a chain of 5 seg2, gathered into a pair and a triple
   *    [LAC §4.4, item 1].  The pair has one interior node (the shared
   *    vertex, mean 1/2); the triple has two, and the designated one is
   *    the one with the largest integral (on equal segments: a tie, won by
   *    the lowest node index) [LAC Remark 1]. */
  {
    size_t n[2] = { 5, 1 };
    double L[2] = { 5, 1 };
    lac_mesh *m = NULL;
    lac_macro *M = NULL;
    check_status (lac_mesh_box (LAC_QUAD4, n, L, 0.0, &m), "lac_mesh_box");
    check_status (lac_macromesh_build (&m, "ymax", NULL, &M),
                  "lac_macromesh_build");
    printf ("3. a chain of 5 seg2 (top of 5 quad4): %zu macro-elements\n",
            M->n);
    for (size_t k = 0; k < M->n; k++)
      {
        size_t in[8], ni = lac_macromesh_interior (m, M, k, in, 8);
        double x0 = INFINITY, x1 = -INFINITY;
        for (size_t j = M->ptr[k]; j < M->ptr[k + 1]; j++)
          {
            int fn[LAC_MAX_FACE_NODES];
            int nf = lac_mesh_facet_nodes (m, M->cell[j], M->face[j], fn,
                                           NULL);
            for (int a = 0; a < nf; a++)
              {
                x0 = fmin (x0, m->x[2 * (size_t) fn[a]]);
                x1 = fmax (x1, m->x[2 * (size_t) fn[a]]);
              }
          }
        printf ("   T^%zu: x in [%.0f, %.0f], %zu segments, interior nodes",
                k, x0, x1, M->ptr[k + 1] - M->ptr[k]);
        for (size_t q = 0; q < ni; q++)
          printf (" %zu", in[q]);
        printf (", designated %zu ", M->inode[k]);
        print_point (m, M->inode[k]);
        printf (", mean %.6f\n", M->phi[k] / M->meas[k]);
      }
    lac_macromesh_free (M);
    lac_mesh_free (m);
  }

  // @sect A cell with two slave faces: rounds
  /* 4. One hexahedron whose top (zmax) and side (xmax) faces are both
   *    slave.  A round cuts at most one face per cell: round 1 cuts the
   *    top (5 pyramids), and the side face is now the base of one of the
   *    pyramids, which round 2 cuts into 4 tetrahedra (with --six: round 2
   *    cuts the trapezoidal hexahedron on the side into 6).  The volume is
   *    unchanged: no cell was lost or overlaps another. */
  {
    size_t n[3] = { 1, 1, 1 };
    double L[3] = { 1, 1, 1 };
    lac_mesh *m = NULL;
    lac_macro *M = NULL;
    check_status (lac_mesh_box (LAC_HEX8, n, L, 0.0, &m), "lac_mesh_box");
    const lac_group *top = lac_mesh_group (m, "zmax");
    const lac_group *side = lac_mesh_group (m, "xmax");
    size_t cell[2] = { top->cell[0], side->cell[0] };
    int face[2] = { top->face[0], side->face[0] };
    check_status (lac_mesh_add_group (m, "top+side", 2, 0, 2, cell, face),
                  "lac_mesh_add_group");
    size_t nn0 = m->nnodes, nc0 = m->ncells;
    double vol0 = lac_mesh_measure (m);
    check_status (lac_macromesh_build (&m, "top+side", &opts, &M),
                  "lac_macromesh_build");
    printf ("4. one hex8, top and side slave: %d rounds, nodes %zu -> %zu, "
            "cells %zu -> %zu,\n   %zu macro-elements of %zu and %zu "
            "sub-facets, volume %.6f -> %.6f\n", M->nrounds, nn0, m->nnodes,
            nc0, m->ncells, M->n, M->ptr[1] - M->ptr[0],
            M->ptr[2] - M->ptr[1], vol0, lac_mesh_measure (m));
    lac_macromesh_free (M);
    lac_mesh_free (m);
  }

  lac_finalize ();
  return 0;
}
