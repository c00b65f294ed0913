/* fig02-refine.c -- the data of the paper's Figure 2: the refinement of
 * the first layer of elements for contact, per element type
 *                                          [LAC Hyp. 1, §4.4, Remark 3]
 *
 *   build/figures/fig02-refine DIR
 *
 * For every element type a small box mesh (lac_mesh_box) gets its top
 * face ("ymax" in 2D, "zmax" in 3D) as the slave surface, and
 * lac_macromesh_build (contact/lac_macromesh.h, contact/lac_refine.h)
 * builds the macro-mesh, cutting the cells of the first layer where
 * Hypothesis 1 needs an interior node.  For case NAME the program writes,
 * in DIR, the whitespace-separated columns gnuplot reads:
 *
 *   NAME.edges   every edge of every cell after the refinement, as
 *                polylines (x y z; quadratic edges through their
 *                mid-node), one blank line after each;
 *   NAME.slave   the edges of the slave sub-facets (x y z m), m the index
 *                of their macro-element T^m (gnuplot colours by it);
 *   NAME.inode   the designated interior node of each T^m (x y z m);
 *   NAME.new     the nodes the refinement added (x y z);
 *
 * and one line per case on stdout: name, cells before -> after, nodes
 * added, macro-elements, the mean of the designated basis function of
 * T^0 (figures/make-figures.sh draws the PNGs from these files).
 * Cases: 2D tri3, quad4, tri6, quad8 (gathered segments; nothing cut),
 * tri3 and quad4 with cut_2d (each cell of the first layer cut), 3D tet4,
 * hex8 (5 pyramids), hex8 (six hexahedra), tet10, hex20, hex27.
 * Exit status 0, or 1 with one line on stderr.
 */
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "contact/lac_macromesh.h"
#include "fem/lac_mesh.h"

typedef struct fig_case
{
  const char *name;
  lac_elem_type type;
  size_t n[3];
  int hex_cut, cut_2d;
} fig_case;

static const fig_case cases[] = {
  { "tri3", LAC_TRI3, { 5, 2, 0 }, 0, 0 },
  { "quad4", LAC_QUAD4, { 5, 2, 0 }, 0, 0 },
  { "tri6", LAC_TRI6, { 5, 2, 0 }, 0, 0 },
  { "quad8", LAC_QUAD8, { 5, 2, 0 }, 0, 0 },
  { "tri3-cut", LAC_TRI3, { 5, 2, 0 }, 0, 1 },
  { "quad4-cut", LAC_QUAD4, { 5, 2, 0 }, 0, 1 },
  { "tet4", LAC_TET4, { 1, 1, 1 }, 0, 0 },
  { "hex8", LAC_HEX8, { 1, 1, 1 }, LAC_MACRO_HEX_PYRAMIDS, 0 },
  { "hex8-six", LAC_HEX8, { 1, 1, 1 }, LAC_MACRO_HEX_SIX, 0 },
  { "tet10", LAC_TET10, { 1, 1, 1 }, 0, 0 },
  { "hex20", LAC_HEX20, { 1, 1, 1 }, LAC_MACRO_HEX_SIX, 0 },
  { "hex27", LAC_HEX27, { 1, 1, 1 }, 0, 0 },
};

/* Node a as "x y z" (z = 0 in 2D). */
static void
put_node (FILE *fp, const lac_mesh *m, int a)
{
  const double *x = m->x + (size_t) m->dim * (size_t) a;
  fprintf (fp, "%.6f %.6f %.6f", x[0], x[1], m->dim == 3 ? x[2] : 0.0);
}

/* The boundary of facet (cell, face) as polylines: corner i, the mid-node
 * of edge (i, i+1) if quadratic, corner i+1.  A seg2/seg3 facet (2D) is
 * one edge.  tag >= 0 is written as a fourth column. */
static int
put_facet (FILE *fp, const lac_mesh *m, size_t cell, int face, long tag)
{
  int nodes[LAC_MAX_FACE_NODES];
  lac_elem_type ft;
  int nn = lac_mesh_facet_nodes (m, cell, face, nodes, &ft);
  if (nn < 0)
    return -nn;
  const lac_refelem *re = lac_refelem_get (ft);
  int nv = re->nvertices, ne = re->dim == 1 ? 1 : nv;
  for (int i = 0; i < ne; i++)
    {
      int path[3] = { nodes[i], -1, nodes[(i + 1) % nv] };
      if (re->order == 2)
        path[1] = nodes[nv + i];
      for (int k = 0; k < 3; k++)
        if (path[k] >= 0)
          {
            put_node (fp, m, path[k]);
            if (tag >= 0)
              fprintf (fp, " %ld", tag);
            fprintf (fp, "\n");
          }
      fprintf (fp, "\n");
    }
  return LAC_SUCCESS;
}

static FILE *
open_file (const char *dir, const char *name, const char *ext)
{
  char path[1024];
  snprintf (path, sizeof path, "%s/%s.%s", dir, name, ext);
  FILE *fp = fopen (path, "w");
  if (!fp)
    fprintf (stderr, "fig02-refine: cannot write %s\n", path);
  return fp;
}

/* One case: build, refine, write its four files. */
static int
draw_case (const char *dir, const fig_case *fc)
{
  const lac_refelem *re = lac_refelem_get (fc->type);
  double L[3] = { (double) fc->n[0], (double) fc->n[1], (double) fc->n[2] };
  lac_macro_opts opts = { fc->hex_cut, fc->cut_2d };
  lac_mesh *m = NULL;
  lac_macro *M = NULL;
  int st = lac_mesh_box (fc->type, fc->n, L, 0.0, &m);
  size_t nn0 = m ? m->nnodes : 0, nc0 = m ? m->ncells : 0;
  if (!st)
    st = lac_macromesh_build (&m, re->dim == 3 ? "zmax" : "ymax", &opts, &M);
  if (st)
    {
      fprintf (stderr, "fig02-refine: %s: %s\n", fc->name,
               lac_error_message ());
      lac_mesh_free (m);
      return 1;
    }
  FILE *fe = open_file (dir, fc->name, "edges");
  FILE *fs = open_file (dir, fc->name, "slave");
  FILE *fi = open_file (dir, fc->name, "inode");
  FILE *fn = open_file (dir, fc->name, "new");
  int bad = !fe || !fs || !fi || !fn;
  for (size_t c = 0; !bad && c < m->ncells; c++)
    {
      const lac_refelem *rc = lac_refelem_get (m->type[c]);
      for (int f = 0; f < rc->nfaces && !bad; f++)
        bad = put_facet (fe, m, c, f, -1) != LAC_SUCCESS;
    }
  for (size_t k = 0; !bad && k < M->n; k++)
    {
      for (size_t j = M->ptr[k]; j < M->ptr[k + 1] && !bad; j++)
        bad = put_facet (fs, m, M->cell[j], M->face[j], (long) k)
              != LAC_SUCCESS;
      put_node (fi, m, (int) M->inode[k]);
      fprintf (fi, " %zu\n", k);
    }
  for (size_t a = nn0; !bad && a < m->nnodes; a++)
    {
      put_node (fn, m, (int) a);
      fprintf (fn, "\n");
    }
  if (nn0 == m->nnodes && fn)   /* gnuplot refuses an empty file */
    fprintf (fn, "NaN NaN NaN\n");
  if (!bad)
    printf ("%-9s cells %2zu -> %2zu  nodes +%-2zu  macro-elements %zu  "
            "mean of phi %.6f\n", fc->name, nc0, m->ncells, m->nnodes - nn0,
            M->n, M->phi[0] / M->meas[0]);
  FILE *all[4] = { fe, fs, fi, fn };
  for (int k = 0; k < 4; k++)
    if (all[k] && fclose (all[k]) != 0)
      bad = 1;
  if (bad)
    fprintf (stderr, "fig02-refine: %s: could not write its files in %s\n",
             fc->name, dir);
  lac_macromesh_free (M);
  lac_mesh_free (m);
  return bad;
}

int
main (int argc, char **argv)
{
  if (argc != 2)
    {
      fprintf (stderr, "usage: fig02-refine DIR\n");
      return 1;
    }
  lac_init ();
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    if (draw_case (argv[1], &cases[i]))
      return 1;
  return 0;
}
