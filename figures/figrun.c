/* figrun.c -- run a scene through the library and draw its contact results
 *
 * A helper of figures/make-figures.sh and bench/accuracy-cost.sh (not part
 * of the library).  It does what `lac run` does -- read the scene with its
 * --set overrides, run every stage (lac_run.h), print the summary lines --
 * and then uses what only a live run has (the macro-elements' sub-facets,
 * lambda per multiplier) to draw the real contact surface:
 *
 *   figrun SCENE [--set KEY=VALUE]... [--solver NAME] [--strategy NAME]
 *          [--max-memory SIZE] [--out DIR] [--no-output] [--timings]
 *          [--quiet]
 *          [drawing options, then --draw KIND FILE.png]...
 *
 * KIND
 *   lambda   the slave sub-facets of every macro-element T^m coloured by
 *            its multiplier lambda_m (piecewise constant; grey if T^m is
 *            not admissible): lac_render_facets.  3D: the lit slave
 *            surface; 2D: thick coloured lines over the mesh in grey.
 *   gap      the same coloured by the mean gap d_m / |T^m cap Gamma_C|.
 *   u_R      the mesh coloured by the radial displacement from the
 *            origin, u . x / |x| (spheres: the paper's "radial
 *            displacement"; in the axisymmetric model x = (r, z)).
 *   u        the mesh coloured by |u|.
 * Drawing options apply to the --draw options after them:
 *   --scale S (0), --az A, --el E, --width W, --height H, --title TEXT,
 *   --label TEXT, --units TEXT, --range MIN:MAX, --edges, --no-edges.
 *
 * --timings prints the time_* lines of `lac run --timings` with
 * microseconds instead of milliseconds (the library rounds them to
 * 0.001 s, too coarse for the small meshes of an accuracy-cost study), and
 * adds time_total (the stages mesh .. post, the output stage excluded) and
 * solver_used (with contact, the strategy that solved the system: the one
 * auto chose, or saddle after a fallback; without contact, the solver).
 * --strategy is that of `lac run` (auto, dense, schur, augmented, split,
 * saddle, petsc: solve/lac_strategy.h); --max-memory too (bytes, or with
 * a suffix K, M, G: 64G).
 *
 * Exit status: 0 success, 1 the run or a drawing failed, 2 bad usage.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "render/lac_render.h"
#include "run/lac_run.h"
#include "io/lac_scene.h"
#include "solve/lac_strategy.h"
#include "base/lac_status.h"

#define MAX_SET 64
#define MAX_DRAW 16

typedef struct draw
{
  const char *kind, *file;
  lac_render_opts o;
} draw;

static int
usage (const char *msg)
{
  fprintf (stderr, "figrun: %s\nusage: figrun SCENE [--set K=V]... "
           "[--solver NAME] [--strategy NAME] [--max-memory SIZE] [--out DIR] "
           "[--no-output] "
           "[--timings] [--quiet] [--scale S] [--az A] [--el E] [--width W] "
           "[--height H] [--title T] [--label L] [--units U] "
           "[--range A:B] [--edges] [--draw lambda|gap|u_R|u FILE.png]...\n",
           msg);
  return 2;
}

/* The precise value of a time_* key, or -1 if the key is not a time. */
static double
precise_time (const lac_run *r, const char *key)
{
  if (strncmp (key, "time_", 5) != 0)
    return -1;
  for (int s = 0; s < LAC_NSTAGES; s++)
    if (strcmp (key + 5, lac_run_stage_name (s)) == 0)
      return r->time[s];
  if (strcmp (key, "time_refine") == 0)
    return r->setup.time_refine;
  if (strcmp (key, "time_pairing") == 0)
    return r->setup.time_pairing;
  lac_strategy_counts c;
  if (r->sol.newton)
    lac_strategy_get_counts (r->sol.newton->strategy, &c);
  if (strcmp (key, "time_factor_K") == 0 && r->sol.newton)
    return c.time_factor;
  if (strcmp (key, "time_active_set") == 0 && r->sol.newton)
    return c.time_solve;
  return -1;
}

/* The slave sub-facets of every contact pair (cell, face) and one value
 * per sub-facet: lambda or the mean gap of its macro-element (slot). */
typedef struct facets
{
  size_t n;
  size_t *cell;
  int *face;
  double *v;
} facets;

static int
facet_values (const lac_run *r, const char *kind, facets *f)
{
  const lac_run_setup *st = &r->setup;
  const lac_contact *c = r->sys.contact;
  size_t j = 0;
  f->n = 0;
  for (size_t p = 0; p < st->npairs; p++)
    f->n += st->macro[p]->ptr[st->macro[p]->n];
  f->cell = malloc ((f->n + 1) * sizeof *f->cell);
  f->face = malloc ((f->n + 1) * sizeof *f->face);
  f->v = malloc ((f->n + 1) * sizeof *f->v);
  if (!f->cell || !f->face || !f->v)
    return 1;
  for (size_t p = 0; p < st->npairs; p++)
    for (size_t m = 0; m < st->macro[p]->n; m++)
      {
        const lac_macro *M = st->macro[p];
        size_t slot = st->set.offset[p] + m;
        long i = c->mult[slot];
        double val = NAN;
        if (i >= 0 && strcmp (kind, "lambda") == 0)
          val = r->sol.newton->lambda[slot];
        else if (i >= 0 && c->area[i] > 0)
          val = r->sol.newton->d[slot] / c->area[i];
        for (size_t q = M->ptr[m]; q < M->ptr[m + 1]; q++, j++)
          {
            f->cell[j] = M->cell[q];
            f->face[j] = M->face[q];
            f->v[j] = val;
          }
      }
  return 0;
}

/* A nodal field of the mesh: u_R or |u|. */
static double *
nodal_values (const lac_run *r, const char *kind)
{
  const lac_mesh *m = r->mesh;
  int d = m->dim;
  double *v = malloc (m->nnodes * sizeof *v);
  if (!v)
    return NULL;
  for (size_t n = 0; n < m->nnodes; n++)
    {
      double xx = 0, xu = 0, uu = 0;
      for (int i = 0; i < d; i++)
        {
          double x = m->x[d * n + i], u = r->sol.u[d * n + i];
          xx += x * x;
          xu += x * u;
          uu += u * u;
        }
      v[n] = strcmp (kind, "u") == 0 ? sqrt (uu)
             : (xx > 0 ? xu / sqrt (xx) : 0.0);
    }
  return v;
}

static int
do_draw (const lac_run *r, const draw *dw)
{
  int status;
  const lac_mesh *m = r->mesh;
  const double *u = dw->o.scale != 0 ? r->sol.u : NULL;
  if (strcmp (dw->kind, "lambda") == 0 || strcmp (dw->kind, "gap") == 0)
    {
      if (!r->setup.npairs || !r->sys.contact || !r->sol.newton)
        {
          fprintf (stderr, "figrun: --draw %s: the scene has no contact\n",
                   dw->kind);
          return 1;
        }
      facets f = { 0, NULL, NULL, NULL };
      status = facet_values (r, dw->kind, &f)
               ? 1 : lac_render_facets (m, u, f.n, f.cell, f.face, f.v,
                                        &dw->o, dw->file);
      free (f.cell), free (f.face), free (f.v);
    }
  else if (strcmp (dw->kind, "u_R") == 0 || strcmp (dw->kind, "u") == 0)
    {
      double *v = nodal_values (r, dw->kind);
      if (!v)
        return 1;
      status = lac_render_mesh (m, u, v, &dw->o, dw->file);
      free (v);
    }
  else
    {
      fprintf (stderr, "figrun: --draw %s: unknown kind (lambda, gap, u_R, "
               "u)\n", dw->kind);
      return 1;
    }
  if (status)
    {
      fprintf (stderr, "figrun: %s: %s\n", dw->file, lac_error_message ());
      return 1;
    }
  printf ("# wrote %s\n", dw->file);
  return 0;
}

int
main (int argc, char **argv)
{
  const char *scene = NULL, *set[MAX_SET];
  char solver_set[64];
  size_t nset = 0, ndraw = 0;
  draw dr[MAX_DRAW];
  lac_run_opts opts = { NULL, 0, 0, 0, 0, NULL, 0, 0 };
  int quiet = 0;
  lac_render_opts o;
  lac_render_opts_init (&o);

  for (int a = 1; a < argc; a++)
    {
      const char *s = argv[a], *v = a + 1 < argc ? argv[a + 1] : NULL;
#define NEED(n) do { if (a + (n) >= argc) return usage ("missing value"); } while (0)
      if (strcmp (s, "--set") == 0)
        {
          NEED (1);
          if (nset == MAX_SET)
            return usage ("too many --set");
          set[nset++] = v;
          a++;
        }
      else if (strcmp (s, "--solver") == 0)
        {
          NEED (1);
          snprintf (solver_set, sizeof solver_set, "solver=%s", v);
          if (nset == MAX_SET)
            return usage ("too many --set");
          set[nset++] = solver_set;
          a++;
        }
      else if (strcmp (s, "--strategy") == 0)
        {
          NEED (1);
          if ((opts.strategy = lac_strategy_from_name (v)) < 0)
            return usage ("--strategy: auto, dense, schur, augmented, "
                          "split, saddle or petsc");
          a++;
        }
      else if (strcmp (s, "--max-memory") == 0)
        {
          NEED (1);
          char *end;
          double b = strtod (v, &end);
          b *= *end == 'K' ? 1e3 : *end == 'M' ? 1e6 : *end == 'G' ? 1e9 : 1;
          if (!(b > 0) || (*end && end[1]) || (*end && !strchr ("KMG", *end)))
            return usage ("--max-memory: bytes, or a number with K, M or G");
          opts.max_memory = b;
          a++;
        }
      else if (strcmp (s, "--out") == 0)
        {
          NEED (1);
          opts.out_dir = v;
          a++;
        }
      else if (strcmp (s, "--no-output") == 0)
        opts.no_output = 1;
      else if (strcmp (s, "--timings") == 0)
        opts.timings = 1;
      else if (strcmp (s, "--quiet") == 0)
        quiet = 1;
      else if (strcmp (s, "--edges") == 0)
        o.edges = 1;
      else if (strcmp (s, "--no-edges") == 0)
        o.edges = 0;
      else if (strcmp (s, "--scale") == 0)
        { NEED (1); o.scale = atof (v); a++; }
      else if (strcmp (s, "--az") == 0)
        { NEED (1); o.azimuth = atof (v); a++; }
      else if (strcmp (s, "--el") == 0)
        { NEED (1); o.elevation = atof (v); a++; }
      else if (strcmp (s, "--width") == 0)
        { NEED (1); o.width = atoi (v); a++; }
      else if (strcmp (s, "--height") == 0)
        { NEED (1); o.height = atoi (v); a++; }
      else if (strcmp (s, "--title") == 0)
        { NEED (1); o.title = v; a++; }
      else if (strcmp (s, "--label") == 0)
        { NEED (1); o.label = v; a++; }
      else if (strcmp (s, "--units") == 0)
        { NEED (1); o.units = v; a++; }
      else if (strcmp (s, "--range") == 0)
        {
          NEED (1);
          if (sscanf (v, "%lf:%lf", &o.vmin, &o.vmax) != 2 || !(o.vmin < o.vmax))
            return usage ("--range MIN:MAX with MIN < MAX");
          o.fixed_range = 1;
          a++;
        }
      else if (strcmp (s, "--auto-range") == 0)
        o.fixed_range = 0;
      else if (strcmp (s, "--draw") == 0)
        {
          NEED (2);
          if (ndraw == MAX_DRAW)
            return usage ("too many --draw");
          dr[ndraw].kind = argv[a + 1];
          dr[ndraw].file = argv[a + 2];
          dr[ndraw].o = o;
          ndraw++;
          a += 2;
        }
      else if (s[0] == '-')
        return usage (s);
      else if (!scene)
        scene = s;
      else
        return usage ("more than one scene");
#undef NEED
    }
  if (!scene)
    return usage ("no scene");
  if (!opts.out_dir)
    opts.no_output = 1;

  lac_scene *sc = NULL;
  if (lac_scene_read (scene, nset, set, &sc))
    {
      fprintf (stderr, "figrun: %s\n", lac_error_message ());
      return 1;
    }
  lac_run *r = lac_run_alloc (sc, &opts);
  if (!r)
    {
      fprintf (stderr, "figrun: %s\n", lac_error_message ());
      lac_scene_free (sc);
      return 1;
    }
  int status;
  do
    {
      int stage = r->stage;
      status = lac_run_iterate (r);
      if (!quiet && (status == LAC_CONTINUE || status == LAC_SUCCESS))
        fprintf (stderr, "figrun: %-9s %s (%.3f s)\n",
                 lac_run_stage_name (stage), r->progress, r->time[stage]);
    }
  while (status == LAC_CONTINUE);
  int rc = 0;
  if (status != LAC_SUCCESS)
    {
      fprintf (stderr, "figrun: %s\n", lac_error_message ());
      rc = 1;
    }
  else
    {
      for (size_t k = 0; k < r->res.summary.n; k++)
        {
          double t = opts.timings ? precise_time (r, r->res.summary.key[k])
                                  : -1;
          if (t >= 0)
            printf ("%s = %.6f\n", r->res.summary.key[k], t);
          else
            printf ("%s = %s\n", r->res.summary.key[k],
                    r->res.summary.val[k]);
        }
      if (opts.timings)
        {
          double tot = 0;
          for (int s = 0; s < LAC_NSTAGES; s++)
            if (s != LAC_STAGE_OUTPUT)
              tot += r->time[s];
          printf ("time_total = %.6f\n", tot);
          printf ("solver_used = %s\n", r->sol.newton
                  ? lac_strategy_name (lac_strategy_kind_of
                                       (r->sol.newton->strategy))
                  : lac_solver_kind_name ((lac_solver_kind)
                                          r->scene->scene.solver));
        }
      for (size_t k = 0; k < ndraw; k++)
        rc |= do_draw (r, &dr[k]);
    }
  lac_run_free (r);
  lac_scene_free (sc);
  return rc;
}
