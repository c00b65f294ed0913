/* lac_cli_render_curves.c -- `lac render --contact` in 2D: lambda and the
 * mean gap along Gamma_C against the curvilinear abscissa, piecewise
 * constant per macro-element, drawn by gnuplot (pngcairo).  Command-line
 * glue like lac_cli_render.c: it writes files and runs gnuplot.
 */
#include "cli/lac_cli_render_curves.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "base/lac_file.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* ---- 2D curves through gnuplot -------------------------------------------- */

/* Make s start at the end with the lower y (then the lower x): from the
 * equator up on a sphere, from left to right on a flat contact. */
static void
reverse_if_needed (const macro_rows *r, size_t *order)
{
  const double *a = r->x + 3 * order[0], *b = r->x + 3 * order[r->n - 1];
  double tol = 1e-9 * (fabs (a[0]) + fabs (a[1]) + fabs (b[0]) + fabs (b[1]));
  if (b[1] < a[1] - tol || (fabs (b[1] - a[1]) <= tol && b[0] < a[0]))
    for (size_t i = 0, j = r->n - 1; i < j; i++, j--)
      {
        size_t t = order[i];
        order[i] = order[j];
        order[j] = t;
      }
}

/* order[0..n-1]: from the centroid farthest from the mean, each time to
 * the nearest centroid not yet visited; then oriented. */
static void
chain_order (const macro_rows *r, size_t *order)
{
  double c[3] = { 0, 0, 0 }, far = -1;
  char *seen = lac_calloc (r->n + 1, 1);
  for (size_t k = 0; k < r->n; k++)
    for (int i = 0; i < 3; i++)
      c[i] += r->x[3 * k + (size_t) i] / (double) r->n;
  order[0] = 0;
  for (size_t k = 0; k < r->n; k++)
    {
      double d = 0;
      for (int i = 0; i < 3; i++)
        d += pow (r->x[3 * k + (size_t) i] - c[i], 2);
      if (d > far)
        far = d, order[0] = k;
    }
  for (size_t j = 0; j < r->n; j++)
    {
      size_t cur = order[j], next = cur;
      double best = INFINITY;
      if (seen)
        seen[cur] = 1;
      for (size_t k = 0; seen && j + 1 < r->n && k < r->n; k++)
        {
          double d = 0;
          for (int i = 0; i < 3; i++)
            d += pow (r->x[3 * k + (size_t) i] - r->x[3 * cur + (size_t) i], 2);
          if (!seen[k] && d < best)
            best = d, next = k;
        }
      if (j + 1 < r->n)
        order[j + 1] = seen ? next : j + 1;
    }
  lac_free (seen);
  reverse_if_needed (r, order);
}

/* A gnuplot single-quoted string: ' doubled. */
static void
gp_quote (FILE *fp, const char *s)
{
  fputc ('\'', fp);
  for (; *s; s++)
    {
      if (*s == '\'')
        fputc ('\'', fp);
      fputc (*s, fp);
    }
  fputc ('\'', fp);
}

static int
write_curves_dat (const char *path, const macro_rows *r, int axi, int *exact)
{
  size_t *order = lac_malloc ((r->n + 1) * sizeof *order);
  double s = 0;
  FILE *fp;
  int status;
  if (!order)
    return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
  if ((status = lac_file_create (path, "w", &fp)))
    {
      lac_free (order);
      return status;
    }
  chain_order (r, order);
  fprintf (fp, "# s  lambda  lambda_exact  mean_gap  (two rows per "
           "macro-element: its ends)\n");
  *exact = 0;
  for (size_t j = 0; j < r->n; j++)
    {
      size_t k = order[j];
      double len = axi ? r->meas[k] / (2 * 3.14159265358979323846 * r->x[3 * k])
                       : r->meas[k];
      *exact |= isfinite (r->lex[k]) && r->lex[k] != 0;
      for (int e = 0; e < 2; e++)
        fprintf (fp, "%.10e %.10e %.10e %.10e\n", s + e * len, r->lam[k],
                 r->lex[k], r->gap[k]);
      s += len;
    }
  lac_free (order);
  return lac_file_close (fp, path);
}

/* "set yrange" for the values: automatic, or, when they vary by less than
 * `floor` or by rounding only, mid +- max(5% of mid, floor) (gnuplot would
 * warn about an empty range, or blow rounding noise up to the full axis). */
static void
gp_yrange (FILE *fp, const double *v1, const double *v2, size_t n,
           double floor_)
{
  double lo = INFINITY, hi = -INFINITY, mid, d;
  for (size_t k = 0; k < n; k++)
    for (int j = 0; j < 2; j++)
      {
        const double *v = j ? v2 : v1;
        if (v && isfinite (v[k]))
          lo = fmin (lo, v[k]), hi = fmax (hi, v[k]);
      }
  if (!(lo <= hi) || hi - lo > fmax (1e-9 * fmax (fabs (lo), fabs (hi)),
                                     floor_))
    {
      fprintf (fp, "set autoscale y\n");
      return;
    }
  mid = 0.5 * (lo + hi);
  d = fmax (0.05 * fabs (mid), floor_);
  d = d > 0 ? d : 1;
  fprintf (fp, "set yrange [%.10e:%.10e]\n", mid - d, mid + d);
}

/* The script: dat and png are names relative to the script's directory. */
static int
write_curves_gp (const char *gp, const char *name, const char *png,
                 const char *title, const lac_render_opts *o,
                 const macro_rows *r, int exact, double gap_floor)
{
  char dat[1100];
  FILE *fp;
  int status = lac_file_create (gp, "w", &fp);
  if (status)
    return status;
  snprintf (dat, sizeof dat, "%s.dat", name);
  fprintf (fp, "# lac render --contact: lambda and mean gap along Gamma_C\n"
           "# (run in this directory: gnuplot %s.gp)\n"
           "set terminal pngcairo size %d,%d font 'DejaVu Sans,10'\n"
           "if (!exists (\"out\")) out = ", name, o->width, o->height);
  gp_quote (fp, png);
  fprintf (fp, "\nset output out");
  fprintf (fp, "\nset datafile missing 'NaN'\nset grid\n"
           "set key below\nset autoscale xfix\n"
           "set offsets 0, 0, graph 0.08, graph 0.08\n"
           "set multiplot layout 2,1 title ");
  gp_quote (fp, title);
  fprintf (fp, " noenhanced\nset xlabel 's, curvilinear abscissa along "
           "{/Symbol G}_C'\nset ylabel '{/Symbol l}%s%s%s'\n",
           o->units ? " (" : "", o->units ? o->units : "", o->units ? ")" : "");
  gp_yrange (fp, r->lam, exact ? r->lex : NULL, r->n, 0);
  fprintf (fp, "plot ");
  gp_quote (fp, dat);
  fprintf (fp, " using 1:2 with lines lw 2 lc rgb '#3b528b' title "
           "'{/Symbol l} per macro-element'");
  if (exact)
    fprintf (fp, ", '' using 1:3 with lines lw 2 dt 2 lc rgb '#5ec962' "
             "title 'exact (mean over the macro-element)'");
  fprintf (fp, "\nset ylabel 'mean gap'\n");
  gp_yrange (fp, r->gap, NULL, r->n, gap_floor);
  fprintf (fp, "plot ");
  gp_quote (fp, dat);
  fprintf (fp, " using 1:4 with lines lw 2 lc rgb '#21918c' title "
           "'mean gap per macro-element'\nunset multiplot\n");
  return lac_file_close (fp, gp);
}

/* Run `gnuplot -e "out = 'TMP'" GP` in the directory DIR (fork, chdir,
 * execvp): the picture goes to TMP (the script's own name for it when run
 * by hand). */
static int
run_gnuplot (const char *dir, const char *gp, const char *tmp)
{
  char set[1200];
  char *argv[5] = { (char *) "gnuplot", (char *) "-e", set, (char *) gp,
                    NULL };
  int st;
  pid_t pid;
  size_t n = (size_t) snprintf (set, sizeof set, "out = '");
  for (const char *c = tmp; *c && n + 4 < sizeof set; c++)  /* ' doubled */
    n += (size_t) snprintf (set + n, sizeof set - n, *c == '\'' ? "''"
                            : "%c", *c);
  snprintf (set + n, sizeof set - n, "'");
  fflush (stdout);
  fflush (stderr);
  if ((pid = fork ()) < 0)
    LAC_ERROR (LAC_EDEP, "cannot start gnuplot (%s)", strerror (errno));
  if (pid == 0)
    {
      if (chdir (dir) == 0)
        execvp ("gnuplot", argv);
      _exit (127);
    }
  if (waitpid (pid, &st, 0) < 0 || !WIFEXITED (st) || WEXITSTATUS (st))
    LAC_ERROR (LAC_EDEP, "gnuplot failed on %s/%s (exit status %d)%s", dir,
               gp, WIFEXITED (st) ? WEXITSTATUS (st) : -1,
               WIFEXITED (st) && WEXITSTATUS (st) == 127
               ? ": is gnuplot installed (Debian: gnuplot-nox)?" : "");
  return LAC_SUCCESS;
}

/* gnuplot draws DIR/.FILE.lac-tmp-PID, renamed to out when it succeeded:
 * a failure leaves an earlier picture of that name as it was. */
static int
draw (const char *dir, const char *gp, const char *file, const char *out)
{
  char tmp[1100], path[5300];
  int status;
  snprintf (tmp, sizeof tmp, ".%s.lac-tmp-%ld", file, (long) getpid ());
  snprintf (path, sizeof path, "%s/%s", dir, tmp);
  if (!(status = run_gnuplot (dir, gp, tmp)) && rename (path, out) != 0)
    status = LAC_ERRMSG (LAC_EIO, "cannot write '%s' (%s)", out,
                         strerror (errno));
  unlink (path);
  return status;
}

static double
mesh_diameter (const lac_mesh *m)
{
  double d = 0;
  for (int i = 0; i < m->dim; i++)
    {
      double lo = INFINITY, hi = -INFINITY;
      for (size_t a = 0; a < m->nnodes; a++)
        {
          lo = fmin (lo, m->x[a * (size_t) m->dim + (size_t) i]);
          hi = fmax (hi, m->x[a * (size_t) m->dim + (size_t) i]);
        }
      d += (hi - lo) * (hi - lo);
    }
  return sqrt (d);
}

/* out = DIR/NAME.png: DIR/NAME.dat and DIR/NAME.gp, which refers to the
 * data and the picture by their names (run it in DIR). */
int
lac_cli_render_curves (const macro_rows *rows, const lac_render_result *res,
                       const lac_render_opts *o, const char *out)
{
  char dir[4096], name[1024], dat[5200], gp[5200], title[1024];
  const char *slash = strrchr (out, '/'), *file = slash ? slash + 1 : out;
  size_t n = strlen (file);
  int exact = 0, status;
  if (slash)
    snprintf (dir, sizeof dir, "%.*s", slash == out ? 1 : (int) (slash - out),
              out);
  else
    snprintf (dir, sizeof dir, ".");
  snprintf (name, sizeof name, "%.*s", (int) (n > 4 && !strcmp (file + n - 4,
                                              ".png") ? n - 4 : n), file);
  snprintf (dat, sizeof dat, "%s/%s.dat", dir, name);
  snprintf (gp, sizeof gp, "%s/%s.gp", dir, name);
  snprintf (title, sizeof title, "%s", o->title ? o->title : "");
  if ((status = write_curves_dat (dat, rows, res->axisymmetric, &exact))
      || (status = write_curves_gp (gp, name, file, title, o, rows, exact,
                                    1e-9 * mesh_diameter (res->mesh))))
    return status;
  snprintf (gp, sizeof gp, "%s.gp", name);
  return draw (dir, gp, file, out);
}

