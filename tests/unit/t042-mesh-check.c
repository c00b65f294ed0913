/* t042: a mesh that can be trusted: lac_mesh_validate (arrays),
 * lac_mesh_check_topology (flat, repeated, overcrowded and folded cells)
 * and lac_msh_check_text (the lines of a .msh file); lac_geo_check_text
 * (the counts a .geo writes as numbers)                      [LAC §2, §3.1] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "base/lac_status.h"
#include "fem/lac_mesh_check.h"
#include "io/lac_mesh_geo_check.h"
#include "io/lac_mesh_msh_check.h"

/* The unit square cut into four triangles around its centre (node 5),
 * plus cells given as extra triples of 1-based nodes. */
static lac_mesh *
square (const int (*extra)[3], size_t nextra, double cx, double cy)
{
  static const double x[] = { 0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5, 0.7, 0.2 };
  static const int base[4][3] = { { 1, 2, 5 }, { 2, 3, 5 }, { 3, 4, 5 },
                                  { 4, 1, 5 } };
  size_t nc = 4 + nextra;
  lac_mesh *m = lac_mesh_alloc (2, 6, nc, 3 * nc);
  memcpy (m->x, x, sizeof x);
  m->x[8] = cx;
  m->x[9] = cy;
  for (size_t c = 0; c < nc; c++)
    {
      const int *v = c < 4 ? base[c] : extra[c - 4];
      m->type[c] = LAC_TRI3;
      for (int a = 0; a < 3; a++)
        m->conn[3 * c + (size_t) a] = v[a] - 1;
      m->ptr[c + 1] = 3 * (c + 1);
    }
  return m;
}

static void
topology (void)
{
  static const int dup[1][3] = { { 5, 2, 3 } }, three[1][3] = { { 1, 2, 6 } };
  lac_mesh *m = square (NULL, 0, 0.5, 0.5);
  check_status (lac_mesh_validate (m), LAC_SUCCESS, "square: valid");
  check_status (lac_mesh_check_topology (m), LAC_SUCCESS, "square: a mesh");
  lac_mesh_free (m);

  m = square (dup, 1, 0.5, 0.5);
  check_status (lac_mesh_check_topology (m), LAC_EINVAL, "a cell twice");
  check_message ("cells 2 and 5 have the same vertices", "a cell twice");
  m->cell_tag[4] = 2;
  check_status (lac_mesh_check_topology (m), LAC_EINVAL, "a tag twice");
  check_message ("cell 2 is listed twice", "a tag twice");
  lac_mesh_free (m);

  m = square (three, 1, 0.5, 0.5);   /* edge 1-2 then has cells 1 and 5 */
  m->x[10] = 0.5;                     /* node 6 outside, below          */
  m->x[11] = -0.5;
  check_status (lac_mesh_check_topology (m), LAC_SUCCESS, "a cell outside");
  m->conn[12] = 4;                     /* cell 5 = 5 2 6: edge 2-5 thrice */
  m->conn[13] = 1;
  m->conn[14] = 5;
  m->x[10] = 0.2;
  m->x[11] = 0.7;
  check_status (lac_mesh_check_topology (m), LAC_EINVAL, "three cells");
  check_message ("cells 1, 2 and 5 share a face", "three cells");
  lac_mesh_free (m);

  /* The centre moved past the right side: cells 2 and 3 fold over. */
  m = square (NULL, 0, 1.3, 0.5);
  check_status (lac_mesh_check_topology (m), LAC_EINVAL, "folded");
  check_message ("overlap", "folded");
  lac_mesh_free (m);

  /* The centre on the bottom side: cell 1 is flat (and tiny above it). */
  m = square (NULL, 0, 0.5, 0);
  check_status (lac_mesh_check_topology (m), LAC_EINVAL, "flat");
  check_message ("cell 1 (tri3) is degenerate", "flat");
  m->x[9] = 1e-200;
  check_status (lac_mesh_check_topology (m), LAC_EINVAL, "nearly flat");
  lac_mesh_free (m);
}

static void
validate (void)
{
  lac_mesh *m = square (NULL, 0, 0.5, 0.5);
  m->x[3] = NAN;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "nan");
  check_message ("node 2 has coordinate y = nan", "nan");
  m->x[3] = 2 * LAC_MESH_COORD_MAX;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "huge coordinate");
  m->x[3] = 0;
  m->conn[5] = 6;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "index out of range");
  check_message ("cell 2 (tri3): node index 6 out of range", "index");
  m->conn[5] = 4;
  m->type[3] = LAC_TET4;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "3D cell in 2D");
  m->type[3] = LAC_QUAD4;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "node count");
  check_message ("cell 4 (quad4) has 3 nodes, a quad4 has 4", "count");
  m->type[3] = (lac_elem_type) 999;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "no such type");
  m->type[3] = LAC_TRI3;
  m->body[1] = 3;
  check_status (lac_mesh_validate (m), LAC_EINVAL, "body out of range");
  m->body[1] = -1;
  check_status (lac_mesh_validate (m), LAC_SUCCESS, "repaired");
  lac_mesh_free (m);
}

/* A MSH 2.2 file of one tri3 with the given element line. */
static int
msh22 (const char *element_line, int count)
{
  char text[512];
  snprintf (text, sizeof text, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
            "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n"
            "%d\n%s\n$EndElements\n", count, element_line);
  return lac_msh_check_text ("t.msh", text, strlen (text));
}

static void
msh_lines (void)
{
  static const char v41[] =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n"
    "3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n"
    "1 1 2 3\n$EndElements\n";
  char t[sizeof v41];
  check_status (msh22 ("1 2 2 1 1 1 2 3", 1), LAC_SUCCESS, "2.2 good");
  check_status (msh22 ("1 2 1 1 1 1 2 3", 1), LAC_EIO, "2.2 numTags 1");
  check_message ("line 12: element 1 (type 2) has 4 nodes", "numTags");
  check_status (msh22 ("1 2 2 1 1 1 2", 1), LAC_EIO, "2.2 two nodes");
  check_message ("has 2 nodes after its tags, a type 2 element has 3",
                 "two nodes");
  check_status (msh22 ("1 2 2 1 1 1 2 3", 2), LAC_EIO, "2.2 count");
  check_message ("line 13: $EndElements before the end of the lines "
                 "$Elements declares", "count");
  check_status (msh22 ("1 2 2 1 1 1 2 x", 1), LAC_EIO, "2.2 word");
  check_message ("'x' is not an integer", "word");
  check_status (msh22 ("1 2 2 1 1 1 2 3\r4", 1), LAC_EIO, "2.2 CR");
  check_message ("carriage return", "CR");
  check_status (msh22 ("1 99 2 1 1 1 2 3", 1), LAC_EIO, "2.2 type 99");
  check_status (lac_msh_check_text ("t.msh", "$MeshFormat\n2.2 0 8\n"
                                    "$EndMeshFormat\n$Nodes\n999999999999\n",
                                    55), LAC_EIO, "huge count");
  check_message ("line 5: the file ends inside $Nodes", "huge count");
  check_status (lac_msh_check_text ("t.msh", "$Mesh\0Format\n", 13),
                LAC_EIO, "NUL");
  check_message ("NUL byte", "NUL");
  check_status (lac_msh_check_text ("t.msh", v41, sizeof v41 - 1),
                LAC_SUCCESS, "4.1 good");
  memcpy (t, v41, sizeof v41);
  *strstr (t, "1 1 2 3\n$End") = ' ';
  check_status (lac_msh_check_text ("t.msh", t, sizeof v41 - 1), LAC_EIO,
                "4.1 element line");
  memcpy (t, v41, sizeof v41);
  t[strstr (t, "2 1 0 3") - t + 6] = '4';
  check_status (lac_msh_check_text ("t.msh", t, sizeof v41 - 1), LAC_EIO,
                "4.1 block count");
}

/* The transfinite counts of a .geo: numbers from 2 to 2^31 - 1; other
 * numbers refused with their line; expressions, comments, strings and
 * other statements left alone. */
static void
test_geo (void)
{
  static const char *const good[] = {
    "Transfinite Curve{1, 3} = 2 * n + 1;\n",
    "Transfinite Curve {:} = 2147483647 Using Progression 1.1;\n",
    "// Transfinite Curve{1} = 3e9;\nTransfinite Line{2} = 2;",
    "/* Transfinite Curve{1} = 0;\n */ x = 1;",
    "Printf(\"Transfinite Curve{1} = 3e9;\");",
    "Transfinite Surface{1} = {1, 2, 3, 4};",
    "Transfinite Curve{1} = n;", "MyTransfinite Curve{1} = 1;",
    /* computed counts lac cannot tell, or fine ones */
    "n = 3e9; If (x > 1) n = 3; EndIf\nTransfinite Curve{1} = n;",
    "n = 3e9; For i In {1:2} n = n / 2; EndFor Transfinite Curve{1} = n;",
    "DefineConstant[ n = {3e9, Name \"n\"} ];\nTransfinite Curve{1} = n;",
    "n = 3e9; n += 1; Transfinite Curve{1} = n;",
    "n = 3e9; Transfinite Curve{1} = n / 1e9 + 1;",
    "L = 50; t = 5; m = t < L ? 2 : 3e9; Transfinite Curve{1} = m + 1;",
    "n[] = {3e9}; Transfinite Curve{1} = n[0];",
    "n = 3e9; Transfinite Curve{1} = Exists(n) ? 3 : n;",
  };
  static const char *const bad[][2] = {
    { "x = 1;\nTransfinite Curve{1, 3} = 3e9;", "line 2: Transfinite Curve "
      "{...} = 3e9: above the largest allowed value 2147483647" },
    { "Transfinite Line {1} =\n 1 Using Bump 2;", "line 2: Transfinite Curve"
      " {...} = 1: below the smallest allowed value 2" },
    { "Transfinite Curve{ {1} } = 10.5;", "= 10.5: not an integer" },
    { "Transfinite Curve{1} = 1e400;", "beyond the range of a double" },
    /* computed: gmsh makes a count beyond 32 bits 2 without a word */
    { "n = 3e9;\nTransfinite Curve{1, 3} = 2 * n + 1;", "line 2: Transfinite "
      "Curve {...} = 2 * n + 1: it computes to 6e+09, beyond 32-bit" },
    { "a = 2; b = a ^ 40;\nTransfinite Curve{1} = Floor(b) Using Bump 2;",
      "= Floor(b): it computes to 1.09951e+12" },
    { "z = 0; m = 1 / z; Transfinite Curve{1} = m;", "= m: it computes to "
      "inf, not a finite number" },
    { "L = 50; t = 60; m = t < L ? 2 : 3e9; Transfinite Curve{1} = m + 1;",
      "= m + 1: it computes to 3e+09" },
  };
  for (size_t i = 0; i < sizeof good / sizeof good[0]; i++)
    check_status (lac_geo_check_text ("t.geo", good[i], strlen (good[i]),
                                      NULL),
                  LAC_SUCCESS, "geo '%s'", good[i]);
  /* A text that ends inside a count, without a NUL after it (found by
   * fuzz_numbers: read past the end, seen under AddressSanitizer). */
  {
    static const char cut[] = "Transfinite Curve{1} = 5 Usi";
    char *t = malloc (sizeof cut - 1);
    if (t)
      {
        memcpy (t, cut, sizeof cut - 1);
        check_status (lac_geo_check_text ("t.geo", t, sizeof cut - 1, NULL),
                      LAC_SUCCESS, "geo cut inside 'Using'");
        free (t);
      }
  }
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
    {
      check_status (lac_geo_check_text ("t.geo", bad[i][0],
                                        strlen (bad[i][0]), NULL), LAC_EINVAL,
                    "geo '%s'", bad[i][0]);
      check_message (bad[i][1], "geo '%s'", bad[i][0]);
    }
  /* The scene's numbers: `level` and [mesh] numbers, which a default
   * under If (!Exists(...)) does not replace; parentheses too deep to
   * follow are left to gmsh (no stack overflow). */
  {
    static const char geo[] = "If (!Exists(n)) n = 10; EndIf\n"
                              "Transfinite Curve{1} = n * 2^level + 1;";
    lac_mesh_opts o = { 0 };
    char *deep = malloc (20001);
    o.level = 3;
    o.numbers = "n=20";
    check_status (lac_geo_check_text ("t.geo", geo, strlen (geo), &o),
                  LAC_SUCCESS, "geo n=20, level 3");
    o.numbers = "n=3e8";
    check_status (lac_geo_check_text ("t.geo", geo, strlen (geo), &o),
                  LAC_EINVAL, "geo n=3e8, level 3");
    check_message ("= n * 2^level + 1: it computes to 2.4e+09", "n=3e8");
    check_status (lac_geo_check_text ("t.geo", geo, strlen (geo), NULL),
                  LAC_SUCCESS, "geo without the scene's n");
    if (deep)
      {
        memcpy (deep, "Transfinite Curve{1} = ", 23);
        memset (deep + 23, '(', 20000 - 23);
        check_status (lac_geo_check_text ("t.geo", deep, 20000, NULL),
                      LAC_SUCCESS, "geo with 19977 parentheses");
        free (deep);
      }
  }
}

int
main (void)
{
  topology ();
  validate ();
  msh_lines ();
  test_geo ();
  return check_summary ();
}
