/* lac_cli_render_curves.c -- `lac render --contact` in 2D: lambda and the
 * mean gap along Gamma_C against the curvilinear abscissa, piecewise
 * constant per macro-element, drawn by gnuplot (pngcairo).  A frictional
 * run (Coulomb's law, chapter 15) adds a third panel: the
 * tangential traction lambda_t per macro-element, Coulomb's bound
 * mu |lambda| (mu from summary.txt) and the sticking macro-elements
 * shaded, the picture of partial slip.  --compare adds a curve read from a
 * file (a closed form), --srange zooms on a part of Gamma_C.
 * Command-line glue like lac_cli_render.c: it writes files and runs
 * gnuplot.
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
#include "cli/lac_cli_render_compare.h"

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

/* Where each macro-element goes along the curve: order[j] is the row
 * drawn j-th, spanning s[2 j] to s[2 j + 1] (s[0] = 0), each after the
 * one before; with contact.csv's column s, non-admissible macro-elements
 * between two admissible ones leave their length as a gap (the distance of
 * the centroids less the half-lengths, when it exceeds rounding). */
static void
curve_layout (const macro_rows *r, int axi, size_t *order, double *s)
{
  double prev = 0;
  chain_order (r, order);
  s[0] = 0;
  for (size_t j = 0; j < r->n; j++)
    {
      size_t k = order[j];
      double len = axi ? r->meas[k] / (2 * 3.14159265358979323846 * r->x[3 * k])
                       : r->meas[k];
      if (j > 0)
        {
          size_t p = order[j - 1];
          double gap = fabs (r->sc[k] - r->sc[p]) - 0.5 * (prev + len);
          s[2 * j] = s[2 * j - 1];
          if (isfinite (gap) && gap > 1e-6 * (prev + len))
            s[2 * j] += gap;
        }
      s[2 * j + 1] = s[2 * j] + len;
      prev = len;
    }
}

/* A gap before the j-th macro-element (j > 0). */
static int
gap_before (const double *s, size_t j)
{
  return s[2 * j] != s[2 * j - 1];
}

/* Two rows per macro-element (its ends), a blank line at a gap; with
 * friction lambda_t and the stick flag too. */
static int
write_curves_dat (const char *path, const macro_rows *r, const size_t *order,
                  const double *s, int *exact)
{
  FILE *fp;
  int status;
  if ((status = lac_file_create (path, "w", &fp)))
    return status;
  fprintf (fp, "# s  lambda  lambda_exact  mean_gap  %s(two rows per "
           "macro-element: its ends%s)\n", r->friction ? "lambda_t  stick  "
           : "", r->friction ? "; stick: 1 if it sticks" : "");
  *exact = 0;
  for (size_t j = 0; j < r->n; j++)
    {
      size_t k = order[j];
      *exact |= isfinite (r->lex[k]) && r->lex[k] != 0;
      if (j > 0 && gap_before (s, j))        /* no line across the gap */
        fputc ('\n', fp);
      for (int e = 0; e < 2; e++)
        {
          fprintf (fp, "%.10e %.10e %.10e %.10e", s[2 * j + (size_t) e],
                   r->lam[k], r->lex[k], r->gap[k]);
          if (r->friction)
            fprintf (fp, " %.10e %d", r->lt[k],
                     r->status[k] == LAC_CLI_STICK);
          fputc ('\n', fp);
        }
    }
  return lac_file_close (fp, path);
}

/* A set of values for the y range: f * |v[k]|, or v[k] itself if f = 0;
 * only those with keep[k] (keep NULL: all). */
typedef struct yvalues
{
  const double *v;
  size_t n;
  double f;
  const char *keep;
} yvalues;

/* "set yrange" for the values: automatic, or, when they vary by less than
 * `floor` or by rounding only, mid +- max(5% of mid, floor) (gnuplot would
 * warn about an empty range, or blow rounding noise up to the full axis).
 * With --srange (fixed) always a range of its own, 8% wider than the values
 * on each side: gnuplot's autoscale fails when no end of a macro-element
 * falls in the range of s. */
static void
gp_yrange (FILE *fp, const yvalues *set, int nset, double floor_, int fixed)
{
  double lo = INFINITY, hi = -INFINITY, mid, d;
  for (int j = 0; j < nset; j++)
    for (size_t k = 0; set[j].v && k < set[j].n; k++)
      {
        double v = set[j].f != 0 ? set[j].f * fabs (set[j].v[k])
                                 : set[j].v[k];
        if (isfinite (v) && (!set[j].keep || set[j].keep[k]))
          lo = fmin (lo, v), hi = fmax (hi, v);
      }
  if (fixed && !(lo <= hi))                        /* nothing in range */
    lo = hi = 0;
  if (!(lo <= hi) || hi - lo > fmax (1e-9 * fmax (fabs (lo), fabs (hi)),
                                     floor_))
    {
      if (fixed)
        fprintf (fp, "set yrange [%.10e:%.10e]\n", lo - 0.08 * (hi - lo),
                 hi + 0.08 * (hi - lo));
      else
        fprintf (fp, "set autoscale y\n");
      return;
    }
  mid = 0.5 * (lo + hi);
  d = fmax (0.05 * fabs (mid), floor_);
  d = d > 0 ? d : 1;
  fprintf (fp, "set yrange [%.10e:%.10e]\n", mid - d, mid + d);
}

/* What the script is drawn from: the names are relative to its
 * directory. */
typedef struct curves_script
{
  const char *name, *png, *title;   /* NAME (of NAME.gp), the picture     */
  const lac_render_opts *o;
  const lac_cli_curves_opts *c;
  const macro_rows *r;
  const size_t *order;              /* curve_layout                       */
  const double *s;                  /* 2 per macro-element: its ends      */
  const render_compare *cmp;        /* --compare, or NULL                 */
  const char *keep, *keep_cmp;      /* --srange: the rows (macro-elements
                                       over it) and the compare points in
                                       it; NULL: all                      */
  int exact;                        /* the rows have lambda_exact         */
  double gap_floor;
} curves_script;

/* The terminal, the x range, the multiplot and the first y label. */
static void
gp_head (FILE *fp, const curves_script *g)
{
  const lac_render_opts *o = g->o;
  fprintf (fp, "# lac render --contact: lambda%s along Gamma_C\n"
           "# (run in this directory: gnuplot %s.gp)\n"
           "set terminal pngcairo size %d,%d font 'DejaVu Sans,10'\n"
           "if (!exists (\"out\")) out = ", g->r->friction
           ? ", mean gap and tangential traction" : " and mean gap", g->name,
           o->width, o->height);
  gp_quote (fp, g->png);
  fprintf (fp, "\nset output out");
  fprintf (fp, "\nset datafile missing 'NaN'\nset grid\nset key below\n");
  if (g->c->srange)                               /* --srange */
    fprintf (fp, "set xrange [%.10g:%.10g]\n", g->c->s0, g->c->s1);
  else if (g->cmp)              /* the curve of --compare may reach beyond */
    fprintf (fp, "set xrange [0:%.10e]\n", g->s[2 * g->r->n - 1]);
  else
    fprintf (fp, "set autoscale xfix\n");
  if (g->r->friction)               /* three panels, one x axis: aligned */
    fprintf (fp, "set lmargin 12\n");
  fprintf (fp, "set offsets 0, 0, graph 0.08, graph 0.08\n"
           "set multiplot layout %d,1 title ", g->r->friction ? 3 : 2);
  gp_quote (fp, g->title);
  fprintf (fp, " noenhanced\nset xlabel 's, curvilinear abscissa along "
           "{/Symbol G}_C'\nset ylabel '{/Symbol l}%s%s%s'\n",
           o->units ? " (" : "", o->units ? o->units : "",
           o->units ? ")" : "");
}

/* ", 'NAME-compare.dat' using 1:2 ... title 'TITLE' noenhanced" */
static void
gp_compare (FILE *fp, const curves_script *g)
{
  char dat[1100];
  snprintf (dat, sizeof dat, "%s-compare.dat", g->name);
  fprintf (fp, ", ");
  gp_quote (fp, dat);
  fprintf (fp, " using 1:2 with lines lw 2 dt 2 lc rgb 'black' title ");
  gp_quote (fp, g->cmp->title);
  fprintf (fp, " noenhanced");
}

/* The first panel, lambda; the --compare curve without friction. */
static void
gp_lambda (FILE *fp, const curves_script *g, const char *dat)
{
  const render_compare *cmp = g->r->friction ? NULL : g->cmp;
  yvalues y[3] = { { g->r->lam, g->r->n, 0, g->keep },
                   { g->exact ? g->r->lex : NULL, g->r->n, 0, g->keep },
                   { cmp ? cmp->v : NULL, cmp ? cmp->n : 0, 0, g->keep_cmp } };
  gp_yrange (fp, y, 3, 0, g->c->srange);
  fprintf (fp, "plot ");
  gp_quote (fp, dat);
  fprintf (fp, " using 1:2 with lines lw 2 lc rgb '#3b528b' title "
           "'{/Symbol l} per macro-element'");
  if (g->exact)
    fprintf (fp, ", '' using 1:3 with lines lw 2 dt 2 lc rgb '#5ec962' "
             "title 'exact (mean over the macro-element)'");
  if (cmp)
    gp_compare (fp, g);
}

/* The stick macro-elements shaded, one rectangle per run of them. */
static void
gp_stick_shading (FILE *fp, const curves_script *g)
{
  int tag = 0;
  for (size_t j = 0; j < g->r->n; j++)
    {
      size_t j1 = j;
      if (g->r->status[g->order[j]] != LAC_CLI_STICK)
        continue;
      while (j1 + 1 < g->r->n && !gap_before (g->s, j1 + 1)
             && g->r->status[g->order[j1 + 1]] == LAC_CLI_STICK)
        j1++;
      fprintf (fp, "set object %d rect from %.10e, graph 0 to %.10e, graph 1 "
               "behind fc rgb '#dbe9f6' fs solid noborder\n", ++tag,
               g->s[2 * j], g->s[2 * j1 + 1]);
      j = j1;
    }
}

/* The third panel (friction): lambda_t, Coulomb's bound mu |lambda| on
 * the side of the tangential force (both sides if it is zero), the stick
 * zone shaded, the --compare curve. */
static void
gp_tangential (FILE *fp, const curves_script *g, const char *dat)
{
  const macro_rows *r = g->r;
  const lac_render_opts *o = g->o;
  double mu = g->c->mu, force = 0;
  int side;
  for (size_t j = 0; j < r->n; j++)
    if (isfinite (r->lt[g->order[j]]))
      force += r->lt[g->order[j]] * (g->s[2 * j + 1] - g->s[2 * j]);
  side = force > 0 ? 1 : force < 0 ? -1 : 0;
  fprintf (fp, "set ylabel 'tangential traction {/Symbol l}_t%s%s%s'\n",
           o->units ? " (" : "", o->units ? o->units : "",
           o->units ? ")" : "");
  gp_stick_shading (fp, g);
  {
    yvalues y[4] = {
      { r->lt, r->n, 0, g->keep },
      { mu > 0 ? r->lam : NULL, r->n, (side ? side : 1) * mu, g->keep },
      { mu > 0 && !side ? r->lam : NULL, r->n, -mu, g->keep },
      { g->cmp ? g->cmp->v : NULL, g->cmp ? g->cmp->n : 0, 0, g->keep_cmp } };
    gp_yrange (fp, y, 4, 0, g->c->srange);
  }
  if (mu > 0)
    fprintf (fp, "mu = %.10g\n", mu);
  fprintf (fp, "plot ");
  gp_quote (fp, dat);
  fprintf (fp, " using 1:5 with lines lw 2 lc rgb '#b2182b' title "
           "'{/Symbol l}_t per macro-element'");
  if (mu > 0)
    fprintf (fp, ", '' using 1:(%smu * abs($2)) with lines lw 1.5 dt 2 "
             "lc rgb '#888888' title '%s{/Symbol m} |{/Symbol l}| (Coulomb)'",
             side < 0 ? "-" : "", side > 0 ? "" : side < 0 ? "-" : "\xc2\xb1");
  if (mu > 0 && !side)
    fprintf (fp, ", '' using 1:(-mu * abs($2)) with lines lw 1.5 dt 2 "
             "lc rgb '#888888' notitle");
  fprintf (fp, ", keyentry with boxes fc rgb '#dbe9f6' fs solid 1.0 border "
           "lc rgb '#9ecae1' title 'stick shaded'");
  if (g->cmp)
    gp_compare (fp, g);
  fprintf (fp, "\n");
}

/* The script: dat and png are names relative to the script's directory. */
static int
write_curves_gp (const char *gp, const curves_script *g)
{
  char dat[1100];
  FILE *fp;
  int status = lac_file_create (gp, "w", &fp);
  if (status)
    return status;
  snprintf (dat, sizeof dat, "%s.dat", g->name);
  gp_head (fp, g);
  gp_lambda (fp, g, dat);
  fprintf (fp, "\nset ylabel 'mean gap'\n");
  {
    yvalues y = { g->r->gap, g->r->n, 0, g->keep };
    gp_yrange (fp, &y, 1, g->gap_floor, g->c->srange);
  }
  fprintf (fp, "plot ");
  gp_quote (fp, dat);
  fprintf (fp, " using 1:4 with lines lw 2 lc rgb '#21918c' title "
           "'mean gap per macro-element'\n");
  if (g->r->friction)
    gp_tangential (fp, g, dat);
  fprintf (fp, "unset multiplot\n");
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

/* --srange: keep[k] = 1 for the rows over [s0, s1], keep_cmp[i] for the
 * compare points in it (g->keep, g->keep_cmp: NULL without --srange). */
static int
srange_keep (curves_script *g, char **keep, char **keep_cmp)
{
  const lac_cli_curves_opts *c = g->c;
  size_t ncmp = g->cmp ? g->cmp->n : 0;
  *keep = *keep_cmp = NULL;
  if (!c->srange)
    return LAC_SUCCESS;
  *keep = lac_calloc (g->r->n + 1, 1);
  *keep_cmp = lac_calloc (ncmp + 1, 1);
  if (!*keep || !*keep_cmp)
    return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
  for (size_t j = 0; j < g->r->n; j++)
    (*keep)[g->order[j]] = g->s[2 * j + 1] >= c->s0 && g->s[2 * j] <= c->s1;
  for (size_t i = 0; i < ncmp; i++)
    (*keep_cmp)[i] = g->cmp->s[i] >= c->s0 && g->cmp->s[i] <= c->s1;
  g->keep = *keep;
  g->keep_cmp = *keep_cmp;
  return LAC_SUCCESS;
}

/* out = DIR/NAME.png: DIR/NAME.dat, DIR/NAME-compare.dat and DIR/NAME.gp,
 * which refers to the data and the picture by their names (run it in
 * DIR); the --compare file is read before anything is written. */
int
lac_cli_render_curves (const macro_rows *rows, const lac_render_result *res,
                       const lac_render_opts *o, const lac_cli_curves_opts *c,
                       const char *out)
{
  char dir[4096], name[1024], dat[5200], gp[5200], title[1024];
  const char *slash = strrchr (out, '/'), *file = slash ? slash + 1 : out;
  size_t n = strlen (file);
  size_t *order = lac_malloc ((rows->n + 1) * sizeof *order);
  double *s = lac_malloc ((2 * rows->n + 1) * sizeof *s);
  char *keep = NULL, *keep_cmp = NULL;
  render_compare cmp;
  curves_script g;
  int status = LAC_SUCCESS;
  memset (&cmp, 0, sizeof cmp);
  if (!order || !s)
    status = LAC_ERRMSG (LAC_ENOMEM, "out of memory");
  else if (c->compare)
    status = lac_cli_render_compare_read (c->compare, &cmp);
  if (slash)
    snprintf (dir, sizeof dir, "%.*s", slash == out ? 1 : (int) (slash - out),
              out);
  else
    snprintf (dir, sizeof dir, ".");
  snprintf (name, sizeof name, "%.*s", (int) (n > 4 && !strcmp (file + n - 4,
                                              ".png") ? n - 4 : n), file);
  snprintf (title, sizeof title, "%s", o->title ? o->title : "");
  memset (&g, 0, sizeof g);
  g.name = name, g.png = file, g.title = title, g.o = o, g.c = c;
  g.r = rows, g.order = order, g.s = s, g.cmp = c->compare ? &cmp : NULL;
  g.gap_floor = 1e-9 * mesh_diameter (res->mesh);
  if (!status)
    {
      curve_layout (rows, res->axisymmetric, order, s);
      status = srange_keep (&g, &keep, &keep_cmp);
      snprintf (dat, sizeof dat, "%s/%s-compare.dat", dir, name);
      if (!status && g.cmp)
        status = lac_cli_render_compare_write (dat, &cmp);
      snprintf (dat, sizeof dat, "%s/%s.dat", dir, name);
      snprintf (gp, sizeof gp, "%s/%s.gp", dir, name);
      if (!status && !(status = write_curves_dat (dat, rows, order, s,
                                                  &g.exact))
          && !(status = write_curves_gp (gp, &g)))
        {
          snprintf (gp, sizeof gp, "%s.gp", name);
          status = draw (dir, gp, file, out);
        }
    }
  lac_cli_render_compare_free (&cmp);
  lac_free (keep);
  lac_free (keep_cmp);
  lac_free (order);
  lac_free (s);
  return status;
}
