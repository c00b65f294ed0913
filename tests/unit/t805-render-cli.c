/* t805: `lac render` on result directories built in the test
 *
 * A 2D axisymmetric result (quad8 quarter annulus, contact.csv along the
 * inner arc listed out of order) and a 3D one (hex8 box, contact.csv on
 * the top face) are written with lac_output_vtu plus small summary.txt and
 * contact.csv files; lac_cli_render draws the fields and the contact views
 * (2D through gnuplot when it is installed: the macro-elements come out
 * ordered along the arc from the equator, each spanning its length), lists
 * the fields, frames a given --box, and rejects bad command lines (exit
 * status 2) and bad
 * results (1).  Its stdout and stderr go to /dev/null.
 *
 * With friction (contact.csv with lambda_t and status, mu in summary.txt's
 * effects line) the 2D curves have a third panel: the .dat carries
 * lambda_t and the stick flag of each macro-element as contact.csv has
 * them, the .gp draws lambda_t, mu |lambda| and one shaded rectangle per
 * run of sticking macro-elements; --compare FILE adds its curve (to the
 * lambda panel without friction), --srange fixes the range of s; a bad
 * compare file or range leaves the earlier picture, data and script as
 * they were.  In 3D, --field lambda_t colours the discs by |lambda_t|.
 */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "check.h"
#include "cli/lac_cli_render.h"
#include "base/lac_mem.h"
#include "io/lac_output.h"
#include "render/lac_render.h"
#include "base/lac_status.h"
#include "t8-render.h"

static const double PI = 3.14159265358979323846;

/* Run lac_cli_render with stdout and stderr sent to /dev/null. */
static int
cli (const char *a0, const char *a1, const char *a2, const char *a3,
     const char *a4, const char *a5)
{
  char *argv[7] = { (char *) "render", (char *) a0, (char *) a1, (char *) a2,
                    (char *) a3, (char *) a4, (char *) a5 };
  int argc = 1, out, err, null, ret;
  while (argc < 7 && argv[argc])
    argc++;
  fflush (stdout);
  fflush (stderr);
  out = dup (1);
  err = dup (2);
  null = open ("/dev/null", O_WRONLY);
  dup2 (null, 1);
  dup2 (null, 2);
  ret = lac_cli_render (argc, argv);
  fflush (stdout);
  fflush (stderr);
  dup2 (out, 1);
  dup2 (err, 2);
  close (out);
  close (err);
  close (null);
  return ret;
}

static int
have_gnuplot (void)
{
  const char *path = getenv ("PATH");
  char buf[4200], dir[4096];
  while (path && *path)
    {
      size_t n = strcspn (path, ":");
      snprintf (dir, sizeof dir, "%.*s", (int) n, path);
      snprintf (buf, sizeof buf, "%s/gnuplot", dir);
      if (access (buf, X_OK) == 0)
        return 1;
      path += n + (path[n] == ':');
    }
  return 0;
}

static void
write_file (const char *dir, const char *name, const char *text)
{
  char path[600];
  FILE *fp;
  snprintf (path, sizeof path, "%s/%s", dir, name);
  if ((fp = fopen (path, "w")))
    {
      fputs (text, fp);
      fclose (fp);
    }
}

/* The whole file DIR/NAME as a string (malloc'd), or NULL; its size in
 * *size when size is not NULL. */
static char *
slurp_n (const char *dir, const char *name, size_t *size)
{
  char path[700], *buf = NULL;
  long n = 0;
  FILE *fp;
  snprintf (path, sizeof path, "%s/%s", dir, name);
  if (!(fp = fopen (path, "rb")))
    return NULL;
  if (fseek (fp, 0, SEEK_END) == 0 && (n = ftell (fp)) >= 0
      && fseek (fp, 0, SEEK_SET) == 0 && (buf = malloc ((size_t) n + 1)))
    buf[fread (buf, 1, (size_t) n, fp)] = '\0';
  fclose (fp);
  if (size)
    *size = (size_t) n;
  return buf;
}

static char *
slurp (const char *dir, const char *name)
{
  return slurp_n (dir, name, NULL);
}

/* The line of text that contains needle (its first one), or "". */
static const char *
line_with (const char *text, const char *needle, char *buf, size_t len)
{
  const char *p = text ? strstr (text, needle) : NULL, *a, *b;
  buf[0] = '\0';
  if (!p)
    return buf;
  for (a = p; a > text && a[-1] != '\n'; a--)
    ;
  b = strchr (p, '\n');
  snprintf (buf, len, "%.*s", (int) (b ? b - a : (long) strlen (a)), a);
  return buf;
}

static int
png_size (const char *path, int *w, int *h)
{
  unsigned char *img = t8_read_png (path, w, h);
  free (img);
  return img != NULL;
}

/* A result directory from a mesh: u radial, stresses of a thick sphere. */
static void
write_result (const char *dir, lac_mesh *m, lac_model model)
{
  int dim = m->dim, ns = lac_model_nstress (model);
  double *u = lac_malloc (m->nnodes * (size_t) dim * sizeof *u),
    *s = lac_malloc (m->nnodes * (size_t) ns * sizeof *s),
    *vm = lac_malloc (m->nnodes * sizeof *vm);
  char path[600];
  lac_output_fields f;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double r2 = 0;
      for (int i = 0; i < dim; i++)
        r2 += m->x[a * (size_t) dim + (size_t) i]
              * m->x[a * (size_t) dim + (size_t) i];
      for (int i = 0; i < dim; i++)
        u[a * (size_t) dim + (size_t) i] = 1e-3 * m->x[a * (size_t) dim
                                                      + (size_t) i];
      for (int k = 0; k < ns; k++)
        s[a * (size_t) ns + (size_t) k] = k < dim ? -1000 / (r2 + 1) : 0;
      vm[a] = sqrt (r2);
    }
  memset (&f, 0, sizeof f);
  f.mesh = m;
  f.model = model;
  f.u = u;
  f.sigma = s;
  f.vm = vm;
  mkdir (dir, 0777);
  snprintf (path, sizeof path, "%s/solution.vtu", dir);
  check_status (lac_output_vtu (path, &f), LAC_SUCCESS, "write %s", path);
  lac_free (u);
  lac_free (s);
  lac_free (vm);
}

/* Every bad option value or compare file: the exit status, and the
 * picture, data and script of the run before left as they were. */
static void
bad_curves (const char *dir)
{
  static const char *const files[3] = { "contact.png", "contact.gp",
                                        "contact.dat" };
  char *before[3], one[600], nan_[600], none[600];
  size_t nb[3], na;
  snprintf (one, sizeof one, "%s/one.txt", dir);
  snprintf (nan_, sizeof nan_, "%s/nan.txt", dir);
  snprintf (none, sizeof none, "%s/missing.txt", dir);
  write_file (dir, "one.txt", "# title\n0 1\n5\n");
  write_file (dir, "nan.txt", "0 nan\n");
  for (int i = 0; i < 3; i++)
    before[i] = slurp_n (dir, files[i], &nb[i]);
  check_int (cli (dir, "--contact", "--compare", none, NULL, NULL), 1,
             "compare: no such file");
  check_message ("missing.txt", "the message names the file");
  check_int (cli (dir, "--contact", "--compare", one, NULL, NULL), 1,
             "compare: a line with one number");
  check_message ("one.txt:3:", "the message names the file and the line");
  check_int (cli (dir, "--contact", "--compare", nan_, NULL, NULL), 1,
             "compare: nan");
  check_message ("nan.txt:1:", "the message names the file and the line");
  check_int (cli (dir, "--contact", "--srange", "3:1", NULL, NULL), 2,
             "srange: S0 > S1");
  check_int (cli (dir, "--contact", "--srange", "1:1", NULL, NULL), 2,
             "srange: S0 = S1");
  check_int (cli (dir, "--contact", "--srange", "nan:1", NULL, NULL), 2,
             "srange: nan");
  check_int (cli (dir, "--contact", "--srange=0:inf", NULL, NULL, NULL), 2,
             "srange: inf");
  check_int (cli (dir, "--contact", "--srange", "1", NULL, NULL), 2,
             "srange: one number");
  check_int (cli (dir, "--srange", "0:1", NULL, NULL, NULL), 2,
             "srange without --contact");
  check_int (cli (dir, "--compare", one, NULL, NULL, NULL), 2,
             "compare without --contact");
  for (int i = 0; i < 3; i++)
    {
      char *after = slurp_n (dir, files[i], &na);
      check_true (before[i] && after && na == nb[i] && na > 100
                  && !memcmp (before[i], after, na), "%s/%s left as it was",
                  dir, files[i]);
      free (after);
      free (before[i]);
    }
}

/* Without friction: two panels, the compare curve with lambda. */
static void
test_2d_compare (const char *dir)
{
  char cmp[600], line[2048], *gp = slurp (dir, "contact.gp");
  check_true (gp && strstr (gp, "layout 2,1") && !strstr (gp, "compare")
              && !strstr (gp, "lambda_t"), "frictionless contact.gp: two "
              "panels");
  free (gp);
  write_file (dir, "cmp.txt", "1 -10\n30 -15\n");
  snprintf (cmp, sizeof cmp, "%s/cmp.txt", dir);
  check_int (cli (dir, "--contact", "--compare", cmp, NULL, NULL), 0,
             "frictionless --compare");
  gp = slurp (dir, "contact.gp");
  check_true (gp && strstr (line_with (gp, "'{/Symbol l} per macro-element'",
                                       line, sizeof line),
                            "'contact-compare.dat' using 1:2")
              && strstr (line, "title 'cmp.txt'")
              && !strstr (gp, "layout 3,1"), "frictionless contact.gp: the "
              "compare curve with lambda, titled by the file's name");
  free (gp);
  bad_curves (dir);
}

/* A frictional run along the arc of test_2d: statuses and lambda_t per
 * macro-element k (k from the equator), mu = 0.25 in summary.txt; the
 * column s puts a non-admissible macro-element of the same length between
 * k = 2 and 3: a gap in s. */
static void
test_2d_friction (lac_mesh *m)
{
  static const char *const status[6] = { "slip", "stick", "stick", "slip",
                                         "inactive", "stick" };
  char dir[512], csv[2048], *p = csv, cmp[600], line[2048], *gp;
  int w, h, ok = 1;
  FILE *fp;
  snprintf (dir, sizeof dir, "%s", t8_path ("t805-2d-friction"));
  write_result (dir, m, LAC_AXISYMMETRIC);
  write_file (dir, "summary.txt", "title = t805 friction\n"
              "effects = axisymmetric, Coulomb friction (LAC; mu = 0.25), "
              "small strain\n");
  p += sprintf (p, "macro,x,y,z,measure,covered,criterion,admissible,"
                "multiplier,lambda,lambda_exact,mean_gap,active,s,lambda_t,"
                "status,slip,pair\n");
  for (int j = 0; j < 6; j++)
    {
      int k = (int[]) { 3, 0, 5, 1, 4, 2 }[j];
      double th = (k + 0.5) * PI / 12, len = 20 * PI / 12;
      p += sprintf (p, "%d,%.10e,%.10e,,%.10e,1,0.6,1,%d,%g,,0,1,%.10e,%g,%s,"
                    "0,i\n", j, 20 * cos (th), 20 * sin (th),
                    2 * PI * 20 * cos (th) * len, j, -10.0 - k,
                    (k + 0.5 + (k >= 3)) * len, 0.5 + k, status[k]);
    }
  write_file (dir, "contact.csv", csv);
  check_int (cli (dir, "--contact", NULL, NULL, NULL, NULL), 0,
             "2D contact curves with friction");
  snprintf (cmp, sizeof cmp, "%s/contact.png", dir);
  check_true (png_size (cmp, &w, &h) && w == 800 && h == 900,
              "%s: 800 x 900 (three panels)", cmp);
  snprintf (cmp, sizeof cmp, "%s/contact.dat", dir);
  fp = fopen (cmp, "r");
  check_true (fp && fgets (line, sizeof line, fp)
              && strstr (line, "lambda_t  stick"), "%s: columns", cmp);
  for (int r = 0; fp && r < 12; r++)          /* two rows per macro */
    {
      double v[5], ds = 20 * PI / 12;
      int stick = -1, k = r / 2;
      ok &= fscanf (fp, "%lf %lf %lf %lf %lf %d", &v[0], &v[1], &v[2], &v[3],
                    &v[4], &stick) == 6
            && fabs (v[0] - (k + r % 2 + (k >= 3)) * ds) < 1e-6
            && v[1] == -10.0 - k && v[4] == 0.5 + k
            && stick == !strcmp (status[k], "stick");
    }
  check_true (ok, "%s: lambda, lambda_t and stick of contact.csv, in "
              "order along the arc, a gap before k = 3", cmp);
  if (fp)
    fclose (fp);
  gp = slurp (dir, "contact.gp");
  check_true (gp && strstr (gp, "layout 3,1") && strstr (gp, "mu = 0.25\n")
              && strstr (line_with (gp, "using 1:5", line, sizeof line),
                         "'' using 1:(mu * abs($2))")
              && strstr (line, "stick shaded"), "contact.gp: the third "
              "panel, lambda_t, +mu |lambda| (lambda_t > 0)");
  check_true (gp && strstr (gp, "set object 1 rect") && strstr (gp,
              "set object 2 rect") && !strstr (gp, "set object 3"),
              "contact.gp: two runs of sticking macro-elements shaded");
  free (gp);
  write_file (dir, "cmp.txt", "# closed form q(s)\n0 1\n# more\n\n"
              "10\t2.5\n20.5 3\n");
  snprintf (cmp, sizeof cmp, "%s/cmp.txt", dir);
  check_int (cli (dir, "--contact", "--compare", cmp, "--srange", "1:3.5"),
             0, "--compare, --srange");
  gp = slurp (dir, "contact.gp");
  check_true (gp && strstr (line_with (gp, "using 1:5", line, sizeof line),
                            "'contact-compare.dat' using 1:2")
              && strstr (line, "'closed form q(s)'")
              && strstr (gp, "set xrange [1:3.5]\n"), "contact.gp: the "
              "compare curve in the lambda_t panel, the range of s");
  free (gp);
  gp = slurp (dir, "contact-compare.dat");
  check_true (gp && !strcmp (gp, "# closed form q(s)\n0.0000000000e+00 "
                             "1.0000000000e+00\n1.0000000000e+01 "
                             "2.5000000000e+00\n2.0500000000e+01 "
                             "3.0000000000e+00\n"), "contact-compare.dat");
  free (gp);
  bad_curves (dir);
}

static void
test_2d (void)
{
  size_t n[2] = { 2, 6 };
  double L[2] = { 1, 1 };
  lac_mesh *m = NULL;
  char dir[512], png[600], dat[600], csv[2048], *p = csv;
  int w, h;
  FILE *fp;
  snprintf (dir, sizeof dir, "%s", t8_path ("t805-2d"));
  check_status (lac_mesh_box (LAC_QUAD8, n, L, 0, &m), LAC_SUCCESS, "box");
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double r = 20 + 20 * m->x[2 * a], th = m->x[2 * a + 1] * PI / 2;
      m->x[2 * a] = r * cos (th);
      m->x[2 * a + 1] = r * sin (th);
    }
  write_result (dir, m, LAC_AXISYMMETRIC);
  write_file (dir, "summary.txt", "title = t805 quarter annulus\n"
              "model = axisymmetric\n");
  /* six macro-elements on r = 20, listed as 3 0 5 1 4 2 (k = angle index);
   * one more, not admissible (no centroid) */
  p += sprintf (p, "macro,x,y,z,measure,covered,criterion,admissible,"
                "multiplier,lambda,lambda_exact,mean_gap,active\n");
  for (int j = 0; j < 6; j++)
    {
      int k = (int[]) { 3, 0, 5, 1, 4, 2 }[j];
      double th = (k + 0.5) * PI / 12, len = 20 * PI / 12;
      p += sprintf (p, "%d,%.10e,%.10e,0,%.10e,1,0.6,1,%d,%g,-10,0,1\n", j,
                    20 * cos (th), 20 * sin (th),
                    2 * PI * 20 * cos (th) * len, j, -10.0 - k);
    }
  sprintf (p, "6,0,0,0,1,0,0,0,-1,0,0,0,0\n");
  write_file (dir, "contact.csv", csv);

  check_int (cli (dir, "--edges", "--field", "radial_stress", NULL, NULL), 0,
             "2D field");
  snprintf (png, sizeof png, "%s/radial_stress.png", dir);
  check_true (png_size (png, &w, &h) && w == 800 && h == 600, "%s", png);
  snprintf (png, sizeof png, "%s/small.png", dir);
  check_int (cli (dir, "--out", png, "--width=400", "--height=300",
                  "--scale=auto"), 0, "2D von Mises, small, auto scale");
  check_true (png_size (png, &w, &h) && w == 400 && h == 300, "%s", png);
  check_int (cli (dir, "--list", NULL, NULL, NULL, NULL), 0, "--list");
  if (have_gnuplot ())
    {
      double s0, lam0, s1, lam1, ds;
      check_int (cli (dir, "--contact", NULL, NULL, NULL, NULL), 0,
                 "2D contact curves");
      snprintf (png, sizeof png, "%s/contact.png", dir);
      check_true (png_size (png, &w, &h) && w == 800, "%s", png);
      snprintf (dat, sizeof dat, "%s/contact.dat", dir);
      fp = fopen (dat, "r");
      check_true (fp != NULL, "%s kept", dat);
      if (fp)
        {
          char line[256];
          int ok = fgets (line, sizeof line, fp) != NULL;     /* comment */
          ok &= fscanf (fp, "%lf %lf %*f %*f %lf %lf %*f %*f", &s0, &lam0, &s1,
                        &lam1)
                == 4;
          check_true (ok, "read %s", dat);
          ds = 20 * PI / 12;                       /* the length, not 2 pi r l */
          check_abs (s0, 0, 1e-9, "s starts at 0");
          check_abs (s1, ds, 1e-6, "first macro spans its length");
          check_abs (lam0, -10, 0, "first macro: the one at the equator");
          for (int k = 1; ok && k < 6; k++)
            {
              ok = fscanf (fp, "%lf %lf %*f %*f %*f %*f %*f %*f", &s0, &lam0)
                   == 2;
              check_abs (lam0, -10.0 - k, 0, "macro %d in order", k);
              check_abs (s0, k * ds, 1e-6, "macro %d starts at k ds", k);
            }
          fclose (fp);
        }
      test_2d_compare (dir);
      test_2d_friction (m);
    }

  /* bad command lines and results */
  check_int (cli (NULL, NULL, NULL, NULL, NULL, NULL), 2, "no directory");
  check_int (cli (dir, "--bogus", NULL, NULL, NULL, NULL), 2, "bad option");
  check_int (cli (dir, "--scale", "abc", NULL, NULL, NULL), 2, "bad scale");
  check_int (cli (dir, "--range", "3:1", NULL, NULL, NULL), 2, "bad range");
  check_int (cli (dir, "--width", "10", NULL, NULL, NULL), 2, "bad width");
  check_int (cli (dir, "--field", NULL, NULL, NULL, NULL), 2, "no field");
  check_int (cli (dir, dir, NULL, NULL, NULL, NULL), 2, "two directories");
  check_int (cli (dir, "--field", "nope", NULL, NULL, NULL), 1,
             "unknown field");
  check_message ("available:", "unknown field: list");
  check_int (cli ("/nonexistent", NULL, NULL, NULL, NULL, NULL), 1,
             "no result there");
  check_int (cli (dir, "--help", NULL, NULL, NULL, NULL), 0, "--help");
  lac_mesh_free (m);
}

/* Drawn fraction of the left 3/4 of DIR/u.png (the colour bar is right). */
static double
drawn_u (const char *dir, unsigned char **img)
{
  char png[600];
  int w = 0, h = 0;
  double f;
  snprintf (png, sizeof png, "%s/u.png", dir);
  *img = t8_read_png (png, &w, &h);
  if (!*img)
    return -1;
  f = t8_frac_drawn (*img, w, 0, 3 * w / 4, 40, h);
  return f;
}

/* --box: the box of the mesh itself changes nothing (byte for byte); a
 * box 3 times larger frames the mesh smaller (area ~1/9); malformed boxes
 * are usage errors. */
static void
test_box (const char *dir)
{
  unsigned char *a = NULL, *b = NULL, *c = NULL;
  double f0, f1, f2;
  check_int (cli (dir, "--field", "u", NULL, NULL, NULL), 0, "u");
  f0 = drawn_u (dir, &a);
  check_int (cli (dir, "--field", "u", "--box", "0:2:0:2:0:1", NULL), 0,
             "own box");
  f1 = drawn_u (dir, &b);
  check_int (cli (dir, "--field", "u", "--box", "-2:4:-2:4:-1:2", NULL), 0,
             "larger box");
  f2 = drawn_u (dir, &c);
  check_true (a && b && !memcmp (a, b, 800 * 600 * 4), "the mesh's own box "
              "changes no pixel");
  check_true (f0 > 0.1 && f2 > 0.005 && f2 < 0.2 * f0, "framed smaller: "
              "%.3f of the picture drawn, %.3f with a 3x box", f0, f2);
  check_true (fabs (f1 - f0) < 1e-12, "own box %.3f vs %.3f", f1, f0);
  check_int (cli (dir, "--box", "1:0:0:1", NULL, NULL, NULL), 2, "x0 > x1");
  check_int (cli (dir, "--box", "0:1:0", NULL, NULL, NULL), 2, "3 numbers");
  check_int (cli (dir, "--box", "0:1:0:1:0:1:5", NULL, NULL, NULL), 2,
             "7 numbers");
  check_int (cli (dir, "--box", "0:1:a:1", NULL, NULL, NULL), 2, "not a "
             "number");
  free (a);
  free (b);
  free (c);
}

static void
test_3d (void)
{
  size_t n[3] = { 2, 2, 2 };
  double L[3] = { 2, 2, 1 };
  lac_mesh *m = NULL;
  char dir[512], png[600];
  int w, h;
  snprintf (dir, sizeof dir, "%s", t8_path ("t805-3d"));
  check_status (lac_mesh_box (LAC_HEX8, n, L, 0, &m), LAC_SUCCESS, "box");
  write_result (dir, m, LAC_SOLID3D);
  write_file (dir, "contact.csv",
              "macro,x,y,z,measure,admissible,lambda,mean_gap\n"
              "0,0.5,0.5,1,1,1,-25,0\n1,1.5,0.5,1,1,1,-24,0\n"
              "2,0.5,1.5,1,1,1,-23,0\n3,1.5,1.5,1,1,1,-22,0\n");
  check_int (cli (dir, "--contact", "--scale", "10", NULL, NULL), 0,
             "3D contact discs");
  snprintf (png, sizeof png, "%s/contact.png", dir);
  check_true (png_size (png, &w, &h) && w == 800, "%s", png);
  check_int (cli (dir, "--az", "-60", "--el=40", "--field", "u"), 0,
             "3D |u|");
  snprintf (png, sizeof png, "%s/u.png", dir);
  check_true (png_size (png, &w, &h), "%s", png);
  check_int (cli (dir, "--contact", "--field", "lambda_t", NULL, NULL), 1,
             "3D --field lambda_t without friction");
  check_message ("no tangential multiplier", "lambda_t: message");
  check_int (cli (dir, "--contact", "--srange", "0:1", NULL, NULL), 1,
             "3D --srange");
  write_file (dir, "contact.csv",
              "macro,x,y,z,measure,admissible,lambda,mean_gap,lambda_t1,"
              "lambda_t2,status\n"
              "0,0.5,0.5,1,1,1,-25,0,3,4,slip\n1,1.5,0.5,1,1,1,-24,0,0,1,"
              "stick\n2,0.5,1.5,1,1,1,-23,0,0,0,inactive\n"
              "3,1.5,1.5,1,1,1,-22,0,1,0,stick\n");
  check_int (cli (dir, "--contact", "--field", "lambda_t", NULL, NULL), 0,
             "3D discs coloured by |lambda_t|");
  check_true (png_size (png, &w, &h) && w == 800, "%s", png);
  write_file (dir, "contact.csv",
              "macro,x,y,z,measure,admissible,lambda,mean_gap,status\n"
              "0,0.5,0.5,1,1,1,-25,0,stuck\n");
  check_int (cli (dir, "--contact", NULL, NULL, NULL, NULL), 1,
             "a status that is not stick, slip, inactive");
  check_message ("contact.csv:2:", "the message names the line");
  test_box (dir);
  write_file (dir, "contact.csv", "macro,x,y\n");
  check_int (cli (dir, "--contact", NULL, NULL, NULL, NULL), 1,
             "contact.csv without the columns");
  check_message ("no column", "message names the column");
  lac_mesh_free (m);
}

int
main (void)
{
  lac_init ();
  test_2d ();
  test_3d ();
  return check_summary ();
}
