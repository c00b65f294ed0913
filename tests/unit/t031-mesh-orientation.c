/* t031: inverted cells are flipped (facet groups follow) or rejected with
 * the cell tag; tangled cells are rejected, hexahedra with a word on
 * how to mesh them  [LAC §2] */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "fem/lac_mesh.h"
#include "base/lac_status.h"

/* Mirror images written out by hand (independent of lac_mesh.c, which
 * swaps xi and eta): node a of the mirrored cell is node mirror[a]. */
static const int mirror[LAC_NELEM_TYPES][LAC_MAX_NODES] = {
  [LAC_TRI3] = { 1, 0, 2 },                      /* swap vertices 0, 1 */
  [LAC_TRI6] = { 1, 0, 2, 3, 5, 4 },
  [LAC_QUAD4] = { 1, 0, 3, 2 },                  /* xi -> -xi */
  [LAC_QUAD8] = { 1, 0, 3, 2, 4, 7, 6, 5 },
  [LAC_QUAD9] = { 1, 0, 3, 2, 4, 7, 6, 5, 8 },
  [LAC_TET4] = { 0, 1, 3, 2 },                   /* swap vertices 2, 3 */
  [LAC_TET10] = { 0, 1, 3, 2, 4, 9, 7, 6, 8, 5 },
  [LAC_HEX8] = { 4, 5, 6, 7, 0, 1, 2, 3 },       /* zeta -> -zeta */
  [LAC_HEX20] = { 4, 5, 6, 7, 0, 1, 2, 3, 16, 17, 10, 18, 12, 19, 14, 15,
                  8, 9, 11, 13 },
  [LAC_HEX27] = { 4, 5, 6, 7, 0, 1, 2, 3, 16, 17, 10, 18, 12, 19, 14, 15,
                  8, 9, 11, 13, 25, 21, 22, 23, 24, 20, 26 },
};

static void
mirror_cell (lac_mesh *m, size_t c)
{
  int tmp[LAC_MAX_NODES], *cn = m->conn + m->ptr[c];
  int nn = (int) (m->ptr[c + 1] - m->ptr[c]);
  memcpy (tmp, cn, (size_t) nn * sizeof *tmp);
  for (int a = 0; a < nn; a++)
    cn[a] = tmp[mirror[m->type[c]][a]];
}

/* sum of the node indices and their squares: a signature of a node set */
static long
set_signature (const int *v, int n)
{
  long s = 0;
  for (int i = 0; i < n; i++)
    s += v[i] + 1000L * v[i] * v[i];
  return s;
}

static void
check_type (lac_elem_type t)
{
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 2, 2, 2 }, nflip = 0, ninv = 0;
  double L[3] = { 1, 2, 3 }, vol = re->dim == 2 ? 2 : 6;
  lac_mesh *m = NULL;
  long sig[64][6] = { { 0 } };
  char name[32], tag[32];
  int status;

  snprintf (name, sizeof name, "%s", re->name);
  if (lac_mesh_box (t, n, L, 0.1, &m))
    {
      check_true (0, "%s: box", name);
      return;
    }
  for (size_t c = 0; c < m->ncells; c++)
    m->cell_tag[c] = 1000 + c;
  /* the node sets of the group facets before the cells are touched */
  for (size_t g = 0; g < m->ngroups; g++)
    for (size_t e = 0; e < m->group[g].n && g < 6 && e < 64; e++)
      if (m->group[g].dim == m->dim - 1)
        {
          int v[LAC_MAX_FACE_NODES];
          int k = lac_mesh_facet_nodes (m, m->group[g].cell[e],
                                        m->group[g].face[e], v, NULL);
          sig[e][g] = set_signature (v, k);
        }
  /* mirror every other cell: they turn inside out; the group facets are
   * renumbered to keep their nodes, as in a mesh read with inverted cells */
  for (size_t c = 1; c < m->ncells; c += 2)
    {
      mirror_cell (m, c);
      ninv++;
    }
  for (size_t g = 0; g < m->ngroups && g < 6; g++)
    for (size_t e = 0; e < m->group[g].n && e < 64; e++)
      if (m->group[g].dim == m->dim - 1 && m->group[g].cell[e] % 2 == 1)
        for (int f = 0; f < re->nfaces; f++)
          {
            int v[LAC_MAX_FACE_NODES];
            int k = lac_mesh_facet_nodes (m, m->group[g].cell[e], f, v, NULL);
            if (set_signature (v, k) == sig[e][g])
              m->group[g].face[e] = f;
          }
  status = lac_mesh_check_orientation (m, 0, &nflip);
  check_status (status, LAC_EINVAL, "%s: inverted cells rejected", name);
  snprintf (tag, sizeof tag, "tag 1001");
  check_message (tag, "%s: message names the first inverted cell's tag",
                 name);
  check_int ((long) nflip, 0, "%s: nothing flipped when rejecting", name);

  status = lac_mesh_check_orientation (m, 1, &nflip);
  check_status (status, LAC_SUCCESS, "%s: inverted cells flipped", name);
  check_int ((long) nflip, (long) ninv, "%s: number flipped", name);
  check_rel (lac_mesh_measure (m), vol, 1e-13, "%s: measure after flip",
             name);
  status = lac_mesh_check_orientation (m, 0, &nflip);
  check_status (status, LAC_SUCCESS, "%s: positive after flip", name);
  check_int ((long) nflip, 0, "%s: second pass flips nothing", name);
  /* facets of flipped cells still hold the same nodes */
  {
    int bad = 0;
    for (size_t g = 0; g < m->ngroups && g < 6; g++)
      for (size_t e = 0; e < m->group[g].n && e < 64; e++)
        if (m->group[g].dim == m->dim - 1)
          {
            int v[LAC_MAX_FACE_NODES];
            int k = lac_mesh_facet_nodes (m, m->group[g].cell[e],
                                          m->group[g].face[e], v, NULL);
            bad += set_signature (v, k) != sig[e][g];
          }
    check_int (bad, 0, "%s: group facets follow the flip", name);
  }
  lac_mesh_free (m);
}

/* One quad4 [0,1]^2 (or with nodes 2 and 3 swapped: a bow tie). */
static lac_mesh *
one_quad (int bowtie)
{
  static const double x[8] = { 0, 0, 1, 0, 1, 1, 0, 1 };
  lac_mesh *m = lac_mesh_alloc (2, 4, 1, 4);
  memcpy (m->x, x, sizeof x);
  m->type[0] = LAC_QUAD4;
  m->ptr[1] = 4;
  for (int a = 0; a < 4; a++)
    m->conn[a] = a;
  if (bowtie)
    {
      m->conn[2] = 3;
      m->conn[3] = 2;
    }
  m->cell_tag[0] = 77;
  return m;
}

int
main (void)
{
  static const lac_elem_type types[] = {
    LAC_TRI3, LAC_TRI6, LAC_QUAD4, LAC_QUAD8, LAC_QUAD9,
    LAC_TET4, LAC_TET10, LAC_HEX8, LAC_HEX20, LAC_HEX27 };
  lac_mesh *m;
  size_t nflip = 99;

  for (size_t i = 0; i < sizeof types / sizeof *types; i++)
    check_type (types[i]);

  /* a tangled cell (bow tie) is rejected even with flipping on */
  m = one_quad (1);
  check_status (lac_mesh_check_orientation (m, 1, &nflip), LAC_ESING,
                "bow tie rejected");
  check_message ("tag 77", "bow tie message names the tag");
  lac_mesh_free (m);
  /* a tangled hexahedron: the message says how to mesh in hexahedra */
  {
    static const double x[24] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
    m = lac_mesh_alloc (3, 8, 1, 8);
    memcpy (m->x, x, sizeof x);
    m->type[0] = LAC_HEX8;
    m->ptr[1] = 8;
    for (int a = 0; a < 8; a++)
      m->conn[a] = a;
    m->conn[6] = 7;                       /* top face a bow tie */
    m->conn[7] = 6;
    m->cell_tag[0] = 78;
    check_status (lac_mesh_check_orientation (m, 1, &nflip), LAC_ESING,
                  "tangled hex8 rejected");
    check_message ("tag 78", "tangled hex8 message names the tag");
    check_message ("transfinite", "tangled hex8 message says how to mesh");
    check_message ("chapter 10", "tangled hex8 message names the chapter");
    lac_mesh_free (m);
  }
  /* a degenerate cell (two nodes at one place) too */
  m = one_quad (0);
  m->x[4] = m->x[6] = 0;
  m->x[5] = m->x[7] = 1;
  check_status (lac_mesh_check_orientation (m, 1, &nflip), LAC_ESING,
                "degenerate quad rejected");
  lac_mesh_free (m);

  /* a pyramid (base [-1,1]^2 x {0}, apex (0,0,1)): volume 4/3, flipped */
  {
    static const double x[15] = { -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0,
                                  0, 0, 1 };
    static const int inv[5] = { 0, 3, 2, 1, 4 };
    m = lac_mesh_alloc (3, 5, 1, 5);
    memcpy (m->x, x, sizeof x);
    m->type[0] = LAC_PYR5;
    m->ptr[1] = 5;
    for (int a = 0; a < 5; a++)
      m->conn[a] = inv[a];
    check_status (lac_mesh_check_orientation (m, 0, &nflip), LAC_EINVAL,
                  "inverted pyramid rejected");
    check_status (lac_mesh_check_orientation (m, 1, &nflip), LAC_SUCCESS,
                  "inverted pyramid flipped");
    check_int ((long) nflip, 1, "one pyramid flipped");
    check_rel (lac_mesh_measure (m), 4.0 / 3.0, 1e-13, "pyramid volume");
    lac_mesh_free (m);
  }
  /* a mesh whose cells do not match its dimension */
  m = one_quad (0);
  m->type[0] = LAC_HEX8;
  check_status (lac_mesh_check_orientation (m, 1, NULL), LAC_EINVAL,
                "hex8 in a 2D mesh");
  lac_mesh_free (m);
  check_status (lac_mesh_check_orientation (NULL, 1, NULL), LAC_EINVAL,
                "no mesh");
  return check_summary ();
}
