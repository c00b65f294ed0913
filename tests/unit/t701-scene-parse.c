/* t701: scene files -- values, line numbers, overrides, one-line errors
 *
 * Scenes are parsed from strings with the path tests/bad/t701.scene, so
 * that the mesh file box.geo (tests/bad/box.geo) resolves and exists.
 */
#include <math.h>
#include <string.h>
#include "check.h"
#include "linalg/lac_linalg.h"
#include "base/lac_mem.h"
#include "io/lac_scene.h"
#include "base/lac_status.h"

#define PATH "tests/bad/t701.scene"

static const char *good =
  "# a comment\n"
  "[scene]\n"                               /* 2 */
  "title = two bodies\n"                    /* 3 */
  "model = axisymmetric   # inline\n"       /* 4 */
  "solver = umfpack ; inline\n"             /* 5 */
  "\n"
  "[mesh]\n"                                /* 7 */
  "file = box.geo\n"                        /* 8 */
  "  level = 1\n"                           /* 9 (indented) */
  "inverted = reject\n"                     /* 10 */
  "[material steel]\n"                      /* 11 */
  "group = body\n"                          /* 12 */
  "E = 2.1e5\n"                             /* 13 */
  "nu = 0.3\n"                              /* 14 */
  "[dirichlet axis]\n"                      /* 15 */
  "group = left\n"                          /* 16 */
  "symmetry = r\n"                          /* 17 */
  "[dirichlet top]\n"                       /* 18 */
  "group = top\n"                           /* 19 */
  "uz = -0.5\n"                             /* 20 */
  "[load in]\n"                             /* 21 */
  "group = right\n"                         /* 22 */
  "pressure = 3\n"                          /* 23 */
  "[load g]\n"                              /* 24 */
  "force = 0, -9.81\n"                      /* 25 */
  "[output]\n"                              /* 26 */
  "matrix = yes\n"                          /* 27 */
  "csv = off\n";                            /* 28 */

static void
test_good (void)
{
  lac_scene *sc = NULL;
  int status = lac_scene_read_string (good, PATH, 0, NULL, &sc);
  check_status (status, LAC_SUCCESS, "good scene");
  if (status)
    return;
  check_true (strcmp (sc->scene.title, "two bodies") == 0, "title");
  check_int (sc->scene.model, LAC_AXISYMMETRIC, "model");
  check_int (sc->scene.solver, LAC_SOLVER_UMFPACK, "solver");
  check_int (sc->scene.element, LAC_ELEM_NONE, "element not given");
  check_true (strcmp (sc->mesh.path, "tests/bad/box.geo") == 0,
              "mesh path relative to the scene");
  check_int (sc->mesh.level, 1, "level");
  check_int (sc->mesh.inverted, 1, "inverted = reject");
  check_rel (sc->mesh.size, 1, 0, "size default");
  check_int ((long) sc->nmaterial, 1, "materials");
  check_rel (sc->material[0].E, 2.1e5, 0, "E");
  check_int (lac_scene_key_line (&sc->material[0].sec, "E"), 13, "line E");
  check_int (sc->material[0].sec.line, 11, "line [material steel]");
  check_int (lac_scene_key_line (&sc->mesh.sec, "level"), 9, "line level");
  check_int ((long) sc->ndirichlet, 2, "dirichlet");
  check_int (sc->dirichlet[0].kind, LAC_BC_SYMMETRY, "symmetry");
  check_true (sc->dirichlet[0].fixed[0] && !sc->dirichlet[0].fixed[1],
              "symmetry = r fixes u_r");
  check_true (!sc->dirichlet[1].fixed[0] && sc->dirichlet[1].fixed[1]
              && sc->dirichlet[1].value[1] == -0.5, "uz = -0.5 (axi: comp 1)");
  check_int ((long) sc->nload, 2, "loads");
  check_int (sc->load[0].kind, LAC_LOAD_PRESSURE, "pressure");
  check_int (sc->load[1].kind, LAC_LOAD_FORCE, "force");
  check_rel (sc->load[1].vec[1], -9.81, 0, "force y");
  check_true (sc->load[1].group == NULL, "force without group");
  check_true (sc->output.vtu && !sc->output.csv && sc->output.matrix,
              "output flags");
  check_true (strcmp (sc->basename, "t701") == 0, "basename");
  lac_scene_free (sc);
}

static void
test_set (void)
{
  const char *set[] = { "mesh.level=3", "material.steel.E = 7",
                        "solver=dense", "output.vtu=no", "exact.solution="
                        "thick_sphere", "exact.a=1", "exact.b=2",
                        "exact.p=1", "exact.E=1", "exact.nu=0.3" };
  lac_scene *sc = NULL;
  int status = lac_scene_read_string (good, PATH, 10, set, &sc);
  check_status (status, LAC_SUCCESS, "overrides");
  if (status)
    return;
  check_int (sc->mesh.level, 3, "--set mesh.level");
  check_int (lac_scene_key_line (&sc->mesh.sec, "level"), LAC_SCENE_FROM_SET,
             "line of an override");
  check_rel (sc->material[0].E, 7, 0, "--set material.steel.E");
  check_int (sc->scene.solver, LAC_SOLVER_DENSE, "alias solver");
  check_int (sc->output.vtu, 0, "--set output.vtu");
  check_int (sc->exact.solution, LAC_EXACT_THICK_SPHERE, "[exact] created");
  lac_scene_free (sc);
}

/* The scene `text` (or `good` with overrides) fails with a message that
 * contains every one of the needles. */
static void
bad (const char *text, const char *set, const char *n1, const char *n2,
     const char *n3)
{
  lac_scene *sc = NULL;
  const char *sets[1] = { set };
  int status = lac_scene_read_string (text ? text : good, PATH, set ? 1 : 0,
                                      sets, &sc);
  const char *msg = lac_error_message ();
  check_true (status != LAC_SUCCESS && sc == NULL, "fails: %s",
              text ? text : set);
  check_true (strchr (msg, '\n') == NULL, "one line: %s", msg);
  check_message (n1, "message");
  if (n2)
    check_message (n2, "message");
  if (n3)
    check_message (n3, "message");
  lac_scene_free (sc);
}

#define MESH "[mesh]\nfile = box.geo\n"
#define MAT "[material m]\nE = 1\nnu = 0.3\n"

static void
test_errors (void)
{
  bad (MESH MAT "[meshh]\nx = 1\n", NULL, PATH ":6:", "[meshh]",
       "unknown section");
  bad (MESH MAT "[mesh]\nlevle = 2\n", NULL, ":6:", "section given twice",
       "first at line 1");
  bad (MESH "levle = 2\n" MAT, NULL, PATH ":3:", "levle", "unknown key");
  bad (MESH MAT "[material s]\nE = abc\n", NULL, ":7:", "E = 'abc'",
       "expected a number > 0");
  bad (MESH MAT "[material s]\nE = -5\nnu = 0.3\n", NULL, ":7:",
       "E = '-5'", "> 0");
  bad (MESH MAT "[material s]\nE = 5\nnu = 0.5\n", NULL, ":8:",
       "nu = '0.5'", "(-1, 0.5)");
  bad (MESH "[material s]\nE = 5\n", NULL, ":3:", "[material s]",
       "missing key 'nu'");
  bad ("[scene]\nelement = tri7\n" MESH MAT, NULL, ":2:", "element = 'tri7'",
       "tri6");
  bad ("[scene]\nmodel = 3d\nelement = tri6\n" MESH MAT, NULL, ":3:",
       "2D element", "tet4");
  bad ("[mesh]\nfile = nothere.msh\n" MAT, NULL, ":2:",
       "file = 'nothere.msh'", "tests/bad/nothere.msh");
  bad (MAT, NULL, PATH, "no [mesh] section", NULL);
  bad (MESH, NULL, PATH, "no [material", NULL);
  bad (MESH MAT "[dirichlet d]\ngroup = left\nur = 0\n", NULL, ":8:",
       "ur = '0'", "ux, uy");
  bad (MESH MAT "[dirichlet d]\ngroup = left\nclamp = yes\nux = 1\n", NULL,
       ":6:", "[dirichlet d]", "not both");
  bad (MESH MAT "[dirichlet d]\ngroup = left\n", NULL, ":6:",
       "nothing to impose", NULL);
  bad (MESH MAT "[load l]\ngroup = right\ntraction = 1 2 3\n", NULL, ":8:",
       "traction", "expected 2 numbers");
  bad (MESH MAT "[load l]\ngroup = right\ntraction = 1 x\n", NULL, ":8:",
       "traction = '1 x'", "2 or 3 numbers");
  bad (MESH MAT "[load l]\ngroup = right\npressure = 1\nforce = 1 1\n",
       NULL, ":6:", "exactly one", NULL);
  bad (MESH MAT "[material]\nE = 1\n", NULL, ":6:", "needs a name", NULL);
  bad (MESH MAT "[output]\nvtu = maybe\n", NULL, ":7:", "vtu = 'maybe'",
       "yes or no");
  bad (MESH MAT "[mesh\n", NULL, ":6:", "syntax error", NULL);
  bad (MESH MAT "novalue\n", NULL, ":6:", "syntax error", NULL);
  bad ("x = 1\n" MESH MAT, NULL, ":1:", "outside any", NULL);
  bad (MESH MAT "[output]\nvtu = yes\nvtu = no\n", NULL, ":8:", "twice",
       "line 7");
  bad (MESH MAT "[exact]\nsolution = thick_sphere\n", NULL, ":6:",
       "missing key 'a'", NULL);
  bad (NULL, "mesh.levle=2", "--set", "levle", "unknown key");
  bad (NULL, "mesh.level=x", "--set", "level = 'x'", "integer");
  bad (NULL, "material.copper.E=1", "--set", "no section [material copper]",
       PATH);
  bad (NULL, "levels", "--set", "KEY=VALUE", NULL);
  bad (NULL, "foo.bar=1", "--set", "unknown section 'foo'", NULL);
  bad (NULL, "solver=mumps", "--set", "solver = 'mumps'", "cholmod");
}

/* Byte order mark, CRLF line ends, blanks inside headers, long lines. */
static void
test_syntax (void)
{
  const char *text = "\xEF\xBB\xBF[ mesh ]\r\nfile = box.geo\r\n"
    "[material    steel]\r\nE = 1 ; inline\r\nnu = 0.25\r\n";
  char longline[400];
  lac_scene *sc = NULL;
  int status = lac_scene_read_string (text, PATH, 0, NULL, &sc);
  check_status (status, LAC_SUCCESS, "BOM, CRLF");
  if (!status)
    check_true (strcmp (sc->material[0].sec.name, "steel") == 0
                && sc->material[0].nu == 0.25, "[material    steel]");
  lac_scene_free (sc);
  snprintf (longline, sizeof longline, MESH MAT "[scene]\ntitle = %0300d\n",
            0);
  bad (longline, NULL, ":7:", "line too long", NULL);
}

/* Fail the k-th allocation for k = 0, 1, ...: LAC_ENOMEM with a message
 * (or success once k passes the last allocation), never a crash or leak. */
static void
test_mem (void)
{
  const char *set[] = { "mesh.level=2", "output.csv=no" };
  int status = LAC_ENOMEM, bad_status = 0;
  long k;
  for (k = 0; k < 10000 && status == LAC_ENOMEM; k++)
    {
      lac_scene *sc = NULL;
      lac_mem_fail_after (k);
      status = lac_scene_read_string (good, PATH, 2, set, &sc);
      lac_mem_fail_after (-1);
      if (status != LAC_SUCCESS && (status != LAC_ENOMEM || sc))
        bad_status = status;
      lac_scene_free (sc);
    }
  check_status (status, LAC_SUCCESS, "succeeds after %ld failures", k - 1);
  check_int (bad_status, 0, "only LAC_ENOMEM while allocations fail");
}

int
main (void)
{
  test_mem ();
  test_syntax ();
  test_good ();
  test_set ();
  test_errors ();
  return check_summary ();
}
