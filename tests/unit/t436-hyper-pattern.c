/* t436: the kept pattern of K_T, its scatter map and its slabs
 *       (fem/lac_pattern.h, fem/lac_hyper.h)
 *
 * On box meshes of tri6, quad8 (2D), tet10, hex20 (3D), two bodies merged
 * (hex8 + hex27) and a bar of hex20, with pseudo-random displacements:
 *   1. lac_pattern_build gives the pattern of the triplet route (every
 *      entry of every cell block, compressed): the same p and i;
 *   2. a pattern without slabs assembles the cells in order: the K_T and
 *      F_int of the triplet route to the last bit;
 *   3. with slabs, lac_hyper_assemble_pattern gives the values of the
 *      triplet route, K_T and F_int, to 1e-14 of the largest entry, twice
 *      in a row (the values are overwritten, not accumulated);
 *   4. cells left out (E = 0 in half of them) are left out of both; a
 *      cell with E > 0 that is not in the pattern is refused;
 *   5. the runs of the slabs: every cell of the pattern once, no node in
 *      two runs of one phase, for several counts of slabs and on meshes
 *      too small for them (cells set apart); a bar of 2 cells per slab
 *      sets none apart; the same count twice makes them once;
 *   6. the slabbed assembly by one worker, by two from the start, by a
 *      second that joins after k runs (another thread), and handed over
 *      to another worker after k runs: the same K_T and F_int to the last
 *      bit; F_int alone (K_T not asked for): the same F_int, K untouched;
 *   7. a cell turned inside out, in a run that the second thread takes,
 *      or in the last run before a phase starts (the other thread waits
 *      there): the status and message of one worker alone, no hang.
 */
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "fem/lac_hyper.h"
#include "fem/lac_pattern.h"
#include "base/lac_status.h"
#include "linalg/lac_tasks.h"

static double
rnd (unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 32767.5 - 1.0;
}

/* ---- 5. the runs ---------------------------------------------------------- */

/* The runs of the pattern p of the cells flagged in `cells` (NULL: all),
 * made with nslab slabs; returns the number of cells set apart. */
static size_t
runs (const char *name, const lac_mesh *m, const lac_pattern *p,
      const char *cells, size_t nslab)
{
  size_t ncell = 0, *owner = calloc (m->nnodes, sizeof *owner);
  char *seen = calloc (m->ncells, 1);
  int ok = p->nrun == nslab + 1 && p->phase[0] == 0
           && p->phase[1] == (nslab + 1) / 2 && p->phase[2] == nslab
           && p->phase[3] == nslab + 1 && p->run[0] == 0;
  check_true (ok, "%s, %zu slabs: %zu runs in phases %zu %zu %zu %zu", name,
              nslab, p->nrun, p->phase[0], p->phase[1], p->phase[2],
              p->phase[3]);
  if (!ok)
    goto done;
  for (size_t c = 0; c < m->ncells; c++)
    ncell += !cells || cells[c];
  for (size_t r = 0; r < p->nrun; r++)
    ok = ok && p->run[r + 1] >= p->run[r];
  for (size_t q = 0; ok && q < p->run[p->nrun]; q++)
    {
      size_t c = p->order[q];
      ok = c < m->ncells && !seen[c] && (!cells || cells[c]);
      if (ok)
        seen[c] = 1;
    }
  check_true (ok && p->run[p->nrun] == ncell, "%s, %zu slabs: the runs "
              "hold the pattern's %zu cells once each (%zu)", name, nslab,
              ncell, p->run[p->nrun]);
  for (size_t k = 0; ok && k < 3; k++)     /* owner: 1 + the node's run */
    {
      memset (owner, 0, m->nnodes * sizeof *owner);
      for (size_t r = p->phase[k]; r < p->phase[k + 1]; r++)
        for (size_t q = p->run[r]; q < p->run[r + 1]; q++)
          for (size_t t = m->ptr[p->order[q]]; t < m->ptr[p->order[q] + 1];
               t++)
            {
              size_t *o = owner + m->conn[t];
              ok = ok && (!*o || *o == r + 1);
              *o = r + 1;
            }
      check_true (ok, "%s, %zu slabs: no node in two runs of phase %zu",
                  name, nslab, k);
    }
done:
  free (owner), free (seen);
  return ok ? p->run[p->nrun] - p->run[p->nrun - 1] : SIZE_MAX;
}

/* Several counts of slabs on the pattern of mesh m; returns the largest
 * number of cells set apart. */
static size_t
slab_counts (const char *name, const lac_mesh *m, const char *cells)
{
  size_t most = 0;
  lac_pattern *p = lac_pattern_build (m, cells);
  check_true (p != NULL, "%s: pattern: %s", name, lac_error_message ());
  for (size_t nslab = 1; p && nslab <= 16; nslab = nslab < 4 ? nslab + 1
                                                              : 2 * nslab)
    {
      check_status (lac_pattern_slabs (p, m, nslab), LAC_SUCCESS,
                    "%s: %zu slabs", name, nslab);
      size_t apart = runs (name, m, p, cells, nslab);
      most = apart > most ? apart : most;
    }
  lac_pattern_free (p);
  return most;
}

/* The cells set apart by nslab slabs of mesh m. */
static long
apart (const char *name, const lac_mesh *m, size_t nslab)
{
  lac_pattern *p = lac_pattern_build (m, NULL);
  size_t n = p && !lac_pattern_slabs (p, m, nslab)
             ? runs (name, m, p, NULL, nslab) : SIZE_MAX;
  lac_pattern_free (p);
  return n == SIZE_MAX ? -1 : (long) n;
}

/* ---- 6, 7. who takes which run -------------------------------------------- */

typedef struct late
{
  lac_hyper_job *j;
  size_t k;               /* runs the first worker takes alone */
  int then_all;           /* then it takes runs as the second does */
  atomic_int go;          /* the second may start */
} late;

static int
work_all (void *ctx)
{
  return lac_hyper_job_work (ctx, SIZE_MAX);
}

static int
first_worker (void *ctx)
{
  late *l = ctx;
  int status = lac_hyper_job_work (l->j, l->k);
  atomic_store (&l->go, 1);
  return l->then_all ? lac_hyper_job_work (l->j, SIZE_MAX) : status;
}

static int
second_worker (void *ctx)
{
  late *l = ctx;
  struct timespec tick = { 0, 100000 };
  while (!atomic_load (&l->go))
    nanosleep (&tick, NULL);
  return lac_hyper_job_work (l->j, SIZE_MAX);
}

/* The schedules of an assembly of the pattern p at u into f (and K). */
enum { ONE, TWO, JOIN, HAND_THREAD, HAND_HERE };
static const char *schedule_name[] = {
  "one worker", "two workers", "a second that joins after k runs",
  "handed to another thread after k runs",
  "handed to another worker after k runs" };

static int
assemble_by (int how, size_t k, const lac_mesh *m, const lac_hyper *h,
             const double *u, double *f, lac_pattern *p, int want_K)
{
  lac_hyper_job j;
  late l = { &j, k, how == JOIN, 0 };
  memset (f, 0, (size_t) m->dim * m->nnodes * sizeof *f);
  int status = lac_hyper_job_init (&j, m, h, u, f, p, want_K);
  if (status)
    return status;
  if (how == ONE)
    status = lac_hyper_job_work (&j, SIZE_MAX);
  else if (how == TWO)
    status = lac_tasks_pair (work_all, &j, work_all, &j);
  else if (how == HAND_HERE)
    {
      lac_hyper_job_work (&j, k);
      status = lac_hyper_job_work (&j, SIZE_MAX);
    }
  else
    status = lac_tasks_pair (first_worker, &l, second_worker, &l);
  lac_hyper_job_clear (&j);
  return status;
}

/* 6. every schedule gives the bits of one worker. */
static void
same_bits (const char *name, const lac_mesh *m, const lac_hyper *h,
           const double *u, lac_pattern *p)
{
  size_t n = (size_t) m->dim * m->nnodes, nnz = (size_t) p->K->p[n];
  double *K1 = malloc (nnz * sizeof *K1), *f1 = malloc (n * sizeof *f1);
  double *f = malloc (n * sizeof *f);
  check_status (assemble_by (ONE, 0, m, h, u, f1, p, 1), LAC_SUCCESS,
                "%s: one worker", name);
  memcpy (K1, p->K->x, nnz * sizeof *K1);
  size_t ks[] = { 1, p->nrun / 2, p->nrun - 1 };
  for (int how = TWO; how <= HAND_HERE; how++)
    for (size_t t = 0; t < (how == TWO ? 1 : 3); t++)
      {
        int status = assemble_by (how, ks[t], m, h, u, f, p, 1);
        check_true (!status && !memcmp (K1, p->K->x, nnz * sizeof *K1)
                    && !memcmp (f1, f, n * sizeof *f), "%s: %s (k = %zu): "
                    "the K_T and F_int of one worker to the last bit", name,
                    schedule_name[how], ks[t]);
      }
  p->K->x[0] = 12345;                       /* F_int alone: K untouched */
  check_status (assemble_by (TWO, 0, m, h, u, f, p, 0), LAC_SUCCESS,
                "%s: F_int alone", name);
  check_true (!memcmp (f1, f, n * sizeof *f) && p->K->x[0] == 12345,
              "%s: F_int alone: the same bits, K left as it was", name);
  free (K1), free (f1), free (f);
}

/* 7. the first cell c of run r turned inside out (its nodes mirrored in
 * the plane x = its centre's: det F < 0); its neighbours, in other runs,
 * may turn too. */
static void
inside_out (const char *name, const lac_mesh *m, const lac_hyper *h,
            const double *u, lac_pattern *p, size_t r)
{
  size_t n = (size_t) m->dim * m->nnodes, d = (size_t) m->dim;
  size_t c = p->order[p->run[r]];
  double *ub = malloc (n * sizeof *ub), *f = malloc (n * sizeof *f);
  double xc = 0;
  char want[1024];
  size_t nen = m->ptr[c + 1] - m->ptr[c];
  memcpy (ub, u, n * sizeof *ub);
  for (size_t q = m->ptr[c]; q < m->ptr[c + 1]; q++)
    xc += m->x[(size_t) m->conn[q] * d] / (double) nen;
  for (size_t q = m->ptr[c]; q < m->ptr[c + 1]; q++)       /* x -> 2 xc - x */
    ub[(size_t) m->conn[q] * d] = 2 * (xc - m->x[(size_t) m->conn[q] * d]);
  check_status (assemble_by (ONE, 0, m, h, ub, f, p, 1), LAC_ESING,
                "%s: cell %zu (run %zu) inside out, one worker", name, c, r);
  check_message ("inside out", "%s: the message", name);
  snprintf (want, sizeof want, "%s", lac_error_message ());
  for (int how = TWO; how <= HAND_HERE; how++)
    {
      lac_error_clear ();
      int status = assemble_by (how, r, m, h, ub, f, p, 1);
      check_true (status == LAC_ESING && !strcmp (want, lac_error_message ()),
                  "%s: cell %zu inside out, %s (k = %zu): status %d, \"%s\" "
                  "(one worker: \"%s\")", name, c, schedule_name[how], r,
                  status, lac_error_message (), want);
    }
  free (ub), free (f);
}

/* The last run of phase k that has cells. */
static size_t
last_run (const lac_pattern *p, size_t k)
{
  size_t r = p->phase[k + 1] - 1;
  while (r > p->phase[k] && p->run[r + 1] == p->run[r])
    r--;
  return r;
}

/* ---- 1-4 and the above on one mesh --------------------------------------- */

/* 2. a pattern without slabs (lac_pattern_build alone) adds its cells in
 * order, as the triplet route does: the same K_T (Kt) and F_int (ft) to
 * the last bit. */
static void
without_slabs (const char *name, const lac_mesh *m, const lac_hyper *h,
               const double *u, lac_pattern *p, const lac_csc *Kt,
               const double *ft)
{
  size_t n = (size_t) m->dim * m->nnodes, nnz = (size_t) p->K->p[n];
  double *f = calloc (n, sizeof *f);
  check_true (!p->order && !p->run && !p->nrun, "%s: lac_pattern_build "
              "makes no slabs", name);
  check_status (lac_hyper_assemble_pattern (m, h, u, f, p), LAC_SUCCESS,
                "%s: the assembly without slabs", name);
  size_t dk = 0, df = 0;
  for (size_t q = 0; q < nnz; q++)
    dk += Kt->x[q] != p->K->x[q];
  for (size_t j = 0; j < n; j++)
    df += ft[j] != f[j];
  check_true (!dk && !df, "%s: without slabs, the K_T and F_int of the "
              "triplet route to the last bit (%zu, %zu entries differ)", name,
              dk, df);
  free (f);
}

/* 3. the slabbed assembly against the triplet route, twice. */
static void
near_triplets (const char *name, const lac_mesh *m, const lac_hyper *h,
               const double *u, lac_pattern *p, const lac_csc *K,
               const double *f1)
{
  size_t n = (size_t) m->dim * m->nnodes;
  double *f2 = malloc (n * sizeof *f2);
  for (int pass = 0; pass < 2; pass++)
    {
      memset (f2, 0, n * sizeof *f2);
      check_status (lac_hyper_assemble_pattern (m, h, u, f2, p),
                    LAC_SUCCESS, "%s: pattern assembly", name);
      double emax = 0, dk = 0, df = 0, fmaxv = 0;
      for (int q = 0; q < K->p[K->ncol]; q++)
        {
          emax = fmax (emax, fabs (K->x[q]));
          dk = fmax (dk, fabs (K->x[q] - p->K->x[q]));
        }
      for (size_t j = 0; j < n; j++)
        {
          fmaxv = fmax (fmaxv, fabs (f1[j]));
          df = fmax (df, fabs (f1[j] - f2[j]));
        }
      check_true (dk <= 1e-14 * emax && df <= 1e-14 * fmaxv, "%s: pass %d: "
                  "K differs by %.2e of %.2e, F_int by %.2e", name, pass, dk,
                  emax, df);
    }
  free (f2);
}

static void
compare (const char *name, lac_mesh *m, int half, size_t nslab)
{
  size_t n = (size_t) m->dim * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E), *nu = malloc (m->ncells
                                                            * sizeof *nu);
  char *cells = malloc (m->ncells);
  for (size_t c = 0; c < m->ncells; c++)
    {
      E[c] = half && c % 2 ? 0.0 : 100.0 + (double) c;
      nu[c] = 0.3;
      cells[c] = E[c] > 0;
    }
  lac_hyper h = { m->dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D, E, nu, NULL,
                  0 };
  double *u = malloc (n * sizeof *u), *f1 = calloc (n, sizeof *f1);
  unsigned seed = 99;
  for (size_t j = 0; j < n; j++)
    u[j] = 0.02 * rnd (&seed);
  lac_triplet *T = lac_triplet_alloc (n, n, 0);
  check_status (lac_hyper_assemble (m, &h, u, f1, T), LAC_SUCCESS,
                "%s: triplets", name);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_pattern *p = lac_pattern_build (m, cells);
  check_true (K && p, "%s: pattern: %s", name, lac_error_message ());
  int same = K && p && K->ncol == p->K->ncol
             && !memcmp (K->p, p->K->p, (K->ncol + 1) * sizeof *K->p)
             && !memcmp (K->i, p->K->i, (size_t) K->p[K->ncol] * sizeof *K->i);
  check_true (same, "%s: the pattern differs from the triplet route's", name);
  if (same)
    {
      without_slabs (name, m, &h, u, p, K, f1);
      check_status (lac_pattern_slabs (p, m, nslab), LAC_SUCCESS,
                    "%s: %zu slabs", name, nslab);
      size_t *order = p->order;
      check_status (lac_pattern_slabs (p, m, nslab), LAC_SUCCESS,
                    "%s: %zu slabs again", name, nslab);
      check_true (order && p->order == order, "%s: the slabs made once",
                  name);
      runs (name, m, p, cells, nslab);
      near_triplets (name, m, &h, u, p, K, f1);
      same_bits (name, m, &h, u, p);
      inside_out (name, m, &h, u, p, last_run (p, 0));  /* a phase waits */
      inside_out (name, m, &h, u, p, last_run (p, 1));  /* the last slab */
    }
  if (same && half)
    {
      E[1] = 50;                       /* a cell outside the pattern */
      check_status (lac_hyper_assemble_pattern (m, &h, u, f1, p),
                    LAC_EINVAL, "%s: a cell outside the pattern", name);
      check_message ("not in the pattern", "%s: the message", name);
    }
  lac_pattern_free (p);
  lac_csc_free (K);
  lac_triplet_free (T);
  free (E), free (nu), free (cells), free (u), free (f1);
}

static lac_mesh *
box (lac_elem_type type, size_t nx, double distort)
{
  size_t n[3] = { nx, 2, 2 };
  double L[3] = { (double) nx / 3, 0.7, 0.5 };
  lac_mesh *m = NULL;
  lac_mesh_box (type, n, L, distort, &m);
  return m;
}

int
main (void)
{
  lac_init ();
  const lac_elem_type types[] = { LAC_TRI6, LAC_QUAD8, LAC_TET10, LAC_HEX20 };
  for (size_t k = 0; k < sizeof types / sizeof *types; k++)
    for (int half = 0; half < 2; half++)
      {
        lac_mesh *m = box (types[k], 3, 0.2);
        compare (lac_refelem_get (types[k])->name, m, half, 4);
        lac_mesh_free (m);
      }
  lac_mesh *a = box (LAC_HEX8, 3, 0.2), *b = box (LAC_HEX27, 3, 0.2);
  lac_mesh *m = NULL, *bar = box (LAC_HEX20, 8, 0);
  check_status (lac_mesh_merge (a, "a.", b, "b.", &m), LAC_SUCCESS, "merge");
  compare ("hex8 + hex27", m, 0, 4);
  compare ("8 x 2 x 2 hex20", bar, 0, 4);
  slab_counts ("hex8 + hex27", m, NULL);
  check_true (slab_counts ("3 x 2 x 2 hex8", a, NULL) > 0, "3 x 2 x 2 "
              "hex8, up to 16 slabs: too small, cells set apart");
  check_true (slab_counts ("8 x 2 x 2 hex20", bar, NULL) > 0, "8 x 2 x 2 "
              "hex20, 16 slabs: thinner than a cell, cells set apart");
  for (size_t nslab = 4; nslab <= 8; nslab *= 2)
    check_int (apart ("8 x 2 x 2 hex20", bar, nslab), 0, "8 x 2 x 2 "
               "hex20 in %zu slabs (a cell thick and more): none set apart",
               nslab);
  lac_mesh_free (a);
  lac_mesh_free (b);
  lac_mesh_free (m);
  lac_mesh_free (bar);
  lac_finalize ();
  return check_summary ();
}
