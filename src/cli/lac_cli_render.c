/* lac_cli_render.c -- `lac render RESULT_DIR [options]` (see the header)
 *
 * 1. read RESULT_DIR/solution.vtu back (lac_render_result_read), or the
 *    file of --vtu (a step_NNN.vtu of a large-deformation run with [steps]
 *    vtu_every), and RESULT_DIR/summary.txt (the title) when present;
 * 2. a field picture: the nodal field by name (lac_render_result_scalar),
 *    the mesh deformed by scale * u, lac_render_mesh;
 * 3. --contact, from RESULT_DIR/contact.csv (one row per macro-element,
 *    admissible ones with their centroid):
 *    2D: lambda (and the exact value when the run had one) and the mean gap
 *        against the curvilinear abscissa s along Gamma_C, piecewise
 *        constant per macro-element, drawn by gnuplot (pngcairo): the
 *        macro-elements are ordered along the curve by walking from an end
 *        to the nearest unvisited centroid, each spans its length
 *        (measure, or measure / (2 pi r) in the axisymmetric model), and
 *        non-admissible macro-elements between two of them leave a gap
 *        (from contact.csv's column s); the data (.dat) and the script
 *        (.gp) are left next to the PNG so that they can be edited and
 *        replotted; with friction a third panel, the tangential traction
 *        with Coulomb's bound and the stick zone; --compare FILE adds a
 *        curve, --srange S0:S1 zooms;
 *    3D: the mesh in light grey and, seen through it, one disc per
 *        admissible macro-element at its centroid (moved by scale times the
 *        displacement of the nearest node), of the macro-element's area,
 *        coloured by lambda, or by |lambda_t| with --field lambda_t
 *        (contact.csv has no facets, so the slave
 *        surface itself cannot be drawn from the result directory; the
 *        library can, with lac_render_facets).
 * Non-admissible macro-elements are left out of both contact views.
 *
 * This is command-line glue: it prints and runs gnuplot (fork, execvp);
 * the library files do not.
 */
#include "cli/lac_cli_render.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "base/lac_mem.h"
#include "cli/lac_cli.h"
#include "cli/lac_cli_render_curves.h"
#include "cli/lac_cli_result.h"
#include "render/lac_render.h"
#include "base/lac_status.h"

typedef struct render_args
{
  const char *dir, *field, *out;
  const char *vtu;          /* --vtu FILE, NULL: solution.vtu               */
  lac_render_opts opts;     /* the picture's options as given: --width,
                               --height, --scale, --edges, --az, --el,
                               --range, --box, --title, --units; the
                               defaults of lac_render_opts_init            */
  int auto_scale, contact, list;
  int height_given;         /* --height: the frictional curves keep it   */
  lac_cli_curves_opts curves;   /* --compare, --srange (2D --contact)    */
} render_args;

const char lac_cli_render_help[] =
  "usage: lac render RESULT_DIR [options]   draw a result of lac run as PNG\n"
  "\n"
  "lac render reads RESULT_DIR/solution.vtu (or the --vtu file, and\n"
  "summary.txt for the title) and draws the mesh -- a 2D mesh, or the\n"
  "boundary surface of a 3D mesh seen obliquely -- coloured by a nodal\n"
  "field (viridis colour map, colour bar with ticks), without a display\n"
  "(OSMesa).\n"
  "\n"
  "options of render:\n"
  "  --field NAME      the field (von_mises): any point array of the VTU\n"
  "                    (stress_xx, ...), a component or the magnitude of a\n"
  "                    vector (displacement_x, displacement_magnitude),\n"
  "                    radial_stress (n.sigma.n, n = x/|x|), x, y, z,\n"
  "                    displacement_error (|u - u_exact|); aliases vm, u,\n"
  "                    u_x, s_xx and the nodes.csv column names\n"
  "  --list            print the available fields and exit\n"
  "  --scale S|auto    draw the mesh at x + S u (0); auto: the largest\n"
  "                    displacement is drawn as 10% of the mesh size\n"
  "  --edges           draw the cell edges\n"
  "  --az A, --el E    3D view: azimuth and elevation in degrees, -360..360\n"
  "                    (35, 25; z up, azimuth 0 looks along +y)\n"
  "  --range MIN:MAX   fixed colour range (default: the field's range;\n"
  "                    the same range for several pictures compares them)\n"
  "  --box X0:X1:Y0:Y1[:Z0:Z1]  frame this box (model coordinates) with the\n"
  "                    drawing: the same box for several pictures (load\n"
  "                    steps) gives them one scale and position\n"
  "  --vtu FILE        read FILE instead of solution.vtu, relative to\n"
  "                    RESULT_DIR (absolute if it starts with /): e.g. the\n"
  "                    load step step_015.vtu of a run with [steps]\n"
  "                    vtu_every; default --out RESULT_DIR/step_015-FIELD.png\n"
  "                    (not with --contact: contact.csv is the last step)\n"
  "  --title TEXT      title line (default: the scene title and the scale)\n"
  "  --units TEXT      units shown with the field name over the colour bar\n"
  "  --width W, --height H   image size in pixels, 32..8192 (800 x 600)\n"
  "  --out FILE.png    output file (RESULT_DIR/FIELD.png, or\n"
  "                    RESULT_DIR/contact.png with --contact)\n"
  "  --contact         draw the contact results of RESULT_DIR/contact.csv:\n"
  "                    in 2D the multiplier lambda (and its exact value) and\n"
  "                    the mean gap per macro-element against the\n"
  "                    curvilinear abscissa s along Gamma_C (gnuplot; the\n"
  "                    .dat and .gp files are kept next to the PNG); s runs\n"
  "                    over the admissible macro-elements, from 0 at the end\n"
  "                    with the lower y (then the lower x), non-admissible\n"
  "                    ones between them a gap; a run with\n"
  "                    friction adds a third panel: the tangential traction\n"
  "                    lambda_t, mu |lambda| dashed (mu from summary.txt)\n"
  "                    and the sticking macro-elements shaded (900 pixels\n"
  "                    high unless --height); in 3D the mesh in grey with\n"
  "                    one disc per macro-element at its centroid, coloured\n"
  "                    by lambda, or by |lambda_t| with --field lambda_t\n"
  "  --compare FILE    with --contact in 2D: a black dashed curve from FILE\n"
  "                    (lines 's value', '#' comment lines, the first one\n"
  "                    the curve's title) in the lambda_t panel, or in the\n"
  "                    lambda panel without friction\n"
  "  --srange S0:S1    with --contact in 2D: the range of s in every panel\n"
  "                    (a zoom on the contact zone)\n"
  "\n"
  "The path of the file written is printed on stdout.  Exit status: 0\n"
  "success, 1 failure (message 'lac: ...' on stderr), 2 bad command line.\n"
  "\n"
  "example: lac run chapters/01-problem/sphere-axi.scene --out out/sph\n"
  "         lac render out/sph --field radial_stress --edges --units MPa\n";



static int
to_double (const char *s, double *v)
{
  char why[160];
  return lac_number_parse (s, NULL, v, why, sizeof why);
}

/* --box X0:X1:Y0:Y1[:Z0:Z1] into o->box_lo, o->box_hi; 1 if malformed (4
 * or 6 numbers, each lower bound below its upper one; 2D boxes get
 * z = 0:0). */
static int
parse_box (const char *v, lac_render_opts *o)
{
  char buf[256], *save = NULL, *tok;
  double b[6] = { 0 };      /* x0 x1 y0 y1 z0 z1 */
  int n = 0;
  snprintf (buf, sizeof buf, "%s", v);
  for (tok = strtok_r (buf, ":", &save); tok; tok = strtok_r (NULL, ":", &save))
    if (n == 6 || !to_double (tok, &b[n++]))
      return 1;
  for (int d = 0; d < 3; d++)
    {
      o->box_lo[d] = b[2 * d];
      o->box_hi[d] = b[2 * d + 1];
    }
  o->fixed_box = 1;
  return !(n == 4 || n == 6) || !(b[1] > b[0]) || !(b[3] > b[2])
         || (n == 6 && !(b[5] > b[4]));
}

/* "LO:HI", two finite numbers, LO below HI; 1 if malformed. */
static int
parse_interval (const char *v, double *lo, double *hi)
{
  char a[64];
  const char *c = strchr (v, ':');
  snprintf (a, sizeof a, "%.*s", c ? (int) (c - v) : 0, v);
  return !c || !to_double (a, lo) || !to_double (c + 1, hi) || !(*hi > *lo);
}

/* The numeric options; 1 if argv[*k] was one, -1 on a bad value (the
 * usage line printed, naming the limit broken). */
static int
numeric_option (int argc, char **argv, int *k, render_args *a, int *missing)
{
  static const char *const names[] = { "--az", "--el", "--width",
                                       "--height" };
  static const lac_number_spec angle = { -360, 360, 0, 0, 0 };
  static const lac_number_spec pixels = { 32, 8192, 0, 1, 0 };
  double *dst[2] = { &a->opts.azimuth, &a->opts.elevation }, v;
  const char *s;
  for (int i = 0; i < 4; i++)
    if ((s = lac_cli_option_value (argc, argv, k, names[i], missing)))
      {
        if (!lac_cli_number ("render", names[i], s, i < 2 ? &angle
                             : &pixels, &v))
          return -1;
        if (i < 2)
          *dst[i] = v;
        else
          *(i == 2 ? &a->opts.width : &a->opts.height) = (int) v;
        a->height_given |= i == 3;
        return 1;
      }
  return 0;
}

static int
parse_value_option (int argc, char **argv, int *k, render_args *a,
                    int *missing, int *bad)
{
  const char *v;
  if ((v = lac_cli_option_value (argc, argv, k, "--field", missing)))
    a->field = v;
  else if ((v = lac_cli_option_value (argc, argv, k, "--out", missing)))
    a->out = v;
  else if ((v = lac_cli_option_value (argc, argv, k, "--title", missing)))
    a->opts.title = v;
  else if ((v = lac_cli_option_value (argc, argv, k, "--units", missing)))
    a->opts.units = v;
  else if ((v = lac_cli_option_value (argc, argv, k, "--vtu", missing)))
    a->vtu = v;
  else if ((v = lac_cli_option_value (argc, argv, k, "--scale", missing)))
    {
      a->auto_scale = !strcmp (v, "auto");
      *bad = !a->auto_scale && !to_double (v, &a->opts.scale);
    }
  else if ((v = lac_cli_option_value (argc, argv, k, "--box", missing)))
    *bad = parse_box (v, &a->opts);
  else if ((v = lac_cli_option_value (argc, argv, k, "--range", missing)))
    {
      *bad = parse_interval (v, &a->opts.vmin, &a->opts.vmax);
      a->opts.fixed_range = 1;
    }
  else if ((v = lac_cli_option_value (argc, argv, k, "--srange", missing)))
    {
      *bad = parse_interval (v, &a->curves.s0, &a->curves.s1);
      a->curves.srange = 1;
    }
  else if ((v = lac_cli_option_value (argc, argv, k, "--compare", missing)))
    a->curves.compare = v;
  else
    return 0;
  return 1;
}

/* What a value option expects, for the usage line of a bad value. */
static const char *
expected (const char *opt)
{
  if (!strncmp (opt, "--scale", 7))
    return "expected a finite number (the displacement's scale) or auto";
  if (!strncmp (opt, "--box", 5))
    return "expected X0:X1:Y0:Y1 or X0:X1:Y0:Y1:Z0:Z1, finite numbers, each "
           "lower bound below its upper one";
  if (!strncmp (opt, "--range", 7))
    return "expected MIN:MAX, finite numbers, MIN below MAX";
  if (!strncmp (opt, "--srange", 8))
    return "expected S0:S1, finite numbers, S0 below S1 (the abscissa "
           "along Gamma_C)";
  return "bad value";
}

static int
parse_args (int argc, char **argv, render_args *a)
{
  memset (a, 0, sizeof *a);
  lac_render_opts_init (&a->opts);
  for (int k = 1; k < argc; k++)
    {
      int missing = 0, bad = 0, r = 0;
      const char *opt = argv[k];
      if (parse_value_option (argc, argv, &k, a, &missing, &bad)
          || (r = numeric_option (argc, argv, &k, a, &missing)) > 0)
        {
          if (bad)
            {
              char what[400];
              if (strchr (opt, '='))
                snprintf (what, sizeof what, "%.140s: %s", opt,
                          expected (opt));
              else
                snprintf (what, sizeof what, "%.40s '%.100s': %s", opt,
                          argv[k], expected (opt));
              return lac_cli_usage_error ("render", what, NULL);
            }
        }
      else if (r < 0)
        return LAC_CLI_USAGE;
      else if (missing)
        return lac_cli_usage_error ("render", "missing value after", opt);
      else if (!strcmp (opt, "--edges"))
        a->opts.edges = 1;
      else if (!strcmp (opt, "--contact"))
        a->contact = 1;
      else if (!strcmp (opt, "--list"))
        a->list = 1;
      else if (opt[0] == '-' && opt[1] != '\0')
        return lac_cli_usage_error ("render", "unknown option", opt);
      else if (a->dir)
        return lac_cli_usage_error ("render", "more than one result "
                                    "directory:", opt);
      else
        a->dir = opt;
    }
  if (!a->dir)
    return lac_cli_usage_error ("render", "no result directory given", NULL);
  if ((a->curves.compare || a->curves.srange) && !a->contact)
    return lac_cli_usage_error ("render", "--compare and --srange draw on "
                                "the contact curves: --contact is needed "
                                "with", a->curves.compare ? "--compare"
                                : "--srange");
  if (a->contact && a->field && strcmp (a->field, "lambda")
      && strcmp (a->field, "lambda_t"))
    return lac_cli_usage_error ("render", "with --contact, --field is "
                                "lambda or lambda_t, not", a->field);
  if (a->vtu && a->contact)
    return lac_cli_usage_error ("render", "--contact draws contact.csv, "
                                "the last step: not with", "--vtu");
  if (a->out && (strlen (a->out) < 5
                 || strcmp (a->out + strlen (a->out) - 4, ".png")))
    return lac_cli_usage_error ("render", "--out: expected a file name "
                                "ending in .png (a PNG is written there; "
                                "it must not replace a result file), got",
                                a->out);
  return 0;
}

/* ---- pictures ------------------------------------------------------------ */

/* 10% of the bounding box diagonal over the largest |u|. */
static double
auto_scale (const lac_mesh *m, const double *u)
{
  double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] =
    { -INFINITY, -INFINITY, -INFINITY }, diag = 0, umax = 0;
  size_t d = (size_t) m->dim;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double s = 0;
      for (size_t i = 0; i < d; i++)
        {
          lo[i] = fmin (lo[i], m->x[a * d + i]);
          hi[i] = fmax (hi[i], m->x[a * d + i]);
          s += u[a * d + i] * u[a * d + i];
        }
      umax = fmax (umax, sqrt (s));
    }
  for (size_t i = 0; i < d; i++)
    diag += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return umax > 0 ? 0.1 * sqrt (diag) / umax : 0;
}

/* The last name of a path. */
static const char *
base_name (const char *path)
{
  const char *p = strrchr (path, '/');
  return p ? p + 1 : path;
}

/* The VTU to read: RESULT_DIR/solution.vtu, or --vtu (relative to
 * RESULT_DIR unless absolute); the default PNG: RESULT_DIR/FIELD.png,
 * with --vtu RESULT_DIR/STEM-FIELD.png (STEM: the VTU's name less .vtu). */
static void
result_paths (const render_args *a, char *vtu, size_t vlen, char *out,
              size_t olen)
{
  const char *what = a->contact ? "contact"
                     : a->field ? a->field : "von_mises";
  if (!a->vtu)
    snprintf (vtu, vlen, "%s/solution.vtu", a->dir);
  else if (a->vtu[0] == '/')
    snprintf (vtu, vlen, "%s", a->vtu);
  else
    snprintf (vtu, vlen, "%s/%s", a->dir, a->vtu);
  if (a->out)
    snprintf (out, olen, "%s", a->out);
  else if (a->vtu)
    {
      const char *b = base_name (a->vtu);
      size_t n = strlen (b);
      if (n > 4 && !strcmp (b + n - 4, ".vtu"))
        n -= 4;
      snprintf (out, olen, "%s/%.*s-%s.png", a->dir, (int) n, b, what);
    }
  else
    snprintf (out, olen, "%s/%s.png", a->dir, what);
}

/* The options of the command line with the scale in use and, without
 * --title, the title: the scene's title (and the step file), `what`, the
 * scale (written into title[tlen]). */
static void
fill_opts (const render_args *a, double scale, const char *what,
           char *title, size_t tlen, lac_render_opts *o)
{
  char scene[512];
  *o = a->opts;
  o->scale = scale;
  if (o->title)                                  /* --title */
    return;
  lac_cli_result_title (a->dir, scene, sizeof scene);
  if (a->vtu)                                    /* name the step file */
    snprintf (scene + strlen (scene), sizeof scene - strlen (scene),
              ", %s", base_name (a->vtu));
  if (scale != 0)
    snprintf (title, tlen, "%s%s%s (u x %.3g)", scene,
              what ? ": " : "", what ? what : "", scale);
  else
    snprintf (title, tlen, "%s%s%s", scene, what ? ": " : "",
              what ? what : "");
  o->title = title;
}

static int
draw_field (const render_args *a, const lac_render_result *res,
            const double *u, double scale, const char *out)
{
  const char *field = a->field ? a->field : "von_mises";
  double *f = lac_malloc ((res->mesh->nnodes + 1) * sizeof *f);
  char title[1024];
  lac_render_opts o;
  int status;
  if (!f)
    return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
  status = lac_render_result_scalar (res, field, f);
  if (!status)
    {
      fill_opts (a, scale, NULL, title, sizeof title, &o);
      o.label = field;
      status = lac_render_mesh (res->mesh, u, f, &o, out);
    }
  lac_free (f);
  return status;
}

/* 3D: discs at the centroids, moved with the nearest node, coloured by
 * lambda, or by |lambda_t| with --field lambda_t. */
static int
draw_contact_3d (const render_args *a, const lac_render_result *res,
                 const double *u, double scale, const macro_rows *rows,
                 const char *out)
{
  const lac_mesh *m = res->mesh;
  double *xyz = lac_malloc (3 * rows->n * sizeof *xyz),
    *rad = lac_malloc (rows->n * sizeof *rad);
  char title[1024];
  lac_render_opts o;
  int status, tangential;
  if (!xyz || !rad)
    {
      lac_free (xyz);
      lac_free (rad);
      return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
    }
  for (size_t k = 0; k < rows->n; k++)
    {
      size_t best = 0;
      double dbest = INFINITY;
      for (size_t p = 0; scale != 0 && p < m->nnodes; p++)
        {
          double d = 0;
          for (int i = 0; i < 3; i++)
            d += (m->x[3 * p + (size_t) i] - rows->x[3 * k + (size_t) i])
                 * (m->x[3 * p + (size_t) i] - rows->x[3 * k + (size_t) i]);
          if (d < dbest)
            dbest = d, best = p;
        }
      for (int i = 0; i < 3; i++)
        xyz[3 * k + (size_t) i] = rows->x[3 * k + (size_t) i]
                                  + scale * u[3 * best + (size_t) i];
      rad[k] = 0.9 * sqrt (rows->meas[k] / 3.14159265358979323846);
    }
  tangential = a->field && !strcmp (a->field, "lambda_t");
  fill_opts (a, scale, tangential ? "|lambda_t| per macro-element"
             : "lambda per macro-element", title, sizeof title, &o);
  o.label = tangential ? "|lambda_t|" : "lambda";
  status = lac_render_points (m, u, rows->n, xyz, rad,
                              tangential ? rows->lt : rows->lam, &o, out);
  lac_free (xyz);
  lac_free (rad);
  return status;
}

/* 2D: lambda and the mean gap along Gamma_C, and with friction the
 * tangential traction (900 pixels high unless --height), drawn by
 * gnuplot. */
static int
draw_curves (const render_args *a, const lac_render_result *res,
             const macro_rows *rows, const char *out)
{
  char scene[512];
  lac_render_opts o = a->opts;
  lac_cli_curves_opts c = a->curves;
  lac_cli_result_title (a->dir, scene, sizeof scene);
  if (!o.title)
    o.title = scene;
  if (rows->friction && !a->height_given)
    o.height = 900;
  if (!lac_cli_result_mu (a->dir, &c.mu))
    c.mu = 0;
  return lac_cli_render_curves (rows, res, &o, &c, out);
}

/* What the options ask of the contact results that they cannot give: a
 * 2D option on a 3D result, lambda_t without friction. */
static int
contact_mismatch (const render_args *a, int dim, const macro_rows *rows)
{
  char csv[4200];
  if (dim == 3 && (a->curves.compare || a->curves.srange))
    return lac_error_place (LAC_EINVAL, a->curves.compare ? "--compare"
                            : "--srange", "the curves along Gamma_C are "
                            "drawn in 2D only, and %s is a 3D result",
                            a->dir);
  snprintf (csv, sizeof csv, "%s/contact.csv", a->dir);
  if (a->field && !strcmp (a->field, "lambda_t") && !rows->friction)
    return lac_error_place (LAC_EINVAL, csv, "no tangential multiplier "
                            "(columns lambda_t or lambda_t1, lambda_t2, and "
                            "status: a run with friction) for --field "
                            "lambda_t");
  return LAC_SUCCESS;
}

/* ---- the command ---------------------------------------------------------- */

static int
render_result (const render_args *a, const lac_render_result *res,
               const char *out)
{
  const lac_mesh *m = res->mesh;
  double *u = lac_malloc ((m->nnodes * (size_t) m->dim + 1) * sizeof *u),
    scale = a->opts.scale;
  macro_rows rows;
  int status;
  memset (&rows, 0, sizeof rows);
  if (!u)
    return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
  if ((status = lac_render_result_displacement (res, u)))
    {
      lac_free (u);
      return status;
    }
  if (a->auto_scale)
    scale = auto_scale (m, u);
  if (!a->contact)
    status = draw_field (a, res, u, scale, out);
  else if (!(status = lac_cli_result_contact (a->dir, &rows))
           && !(status = contact_mismatch (a, m->dim, &rows)))
    status = m->dim == 2 ? draw_curves (a, res, &rows, out)
             : draw_contact_3d (a, res, u, scale, &rows, out);
  lac_cli_result_contact_free (&rows);
  lac_free (u);
  return status;
}

int
lac_cli_render (int argc, char **argv)
{
  render_args a;
  lac_render_result *res = NULL;
  char path[4096], out[4096];
  int ret;
  for (int k = 1; k < argc; k++)
    if (!strcmp (argv[k], "--help") || !strcmp (argv[k], "-h"))
      {
        fputs (lac_cli_render_help, stdout);
        return 0;
      }
  if ((ret = parse_args (argc, argv, &a)))
    return ret;
  result_paths (&a, path, sizeof path, out, sizeof out);
  if ((ret = lac_render_result_read (path, &res)))
    {
      lac_cli_print_failure (path, ret);
      return LAC_CLI_FAILURE;
    }
  if (a.list)
    {
      char list[4096];
      lac_render_result_list (res, list, sizeof list);
      printf ("%s\n", list);
      lac_render_result_free (res);
      return lac_cli_flush_stdout ();
    }
  ret = render_result (&a, res, out);
  lac_render_result_free (res);
  if (ret)
    {
      lac_cli_print_failure (path, ret);
      return LAC_CLI_FAILURE;
    }
  printf ("%s\n", out);
  return lac_cli_flush_stdout ();
}
