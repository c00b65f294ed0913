/* t436: the kept pattern of K_T and its scatter map (fem/lac_pattern.h)
 *
 * On box meshes of tri6, quad8 (2D), tet10, hex20 (3D) and two bodies
 * merged (hex8 + hex27), with pseudo-random displacements:
 *   1. lac_pattern_build gives the pattern of the triplet route (every
 *      entry of every cell block, compressed): the same p and i;
 *   2. lac_hyper_assemble_pattern gives the values of the triplet route,
 *      K_T and F_int, to 1e-14 of the largest entry, twice in a row (the
 *      values are overwritten, not accumulated);
 *   3. cells left out (E = 0 in half of them) are left out of both;
 *   4. a cell with E > 0 that is not in the pattern is refused;
 *   5. the pattern's three runs of cells (lac_pattern_halves): every cell
 *      of the pattern once, no node in a cell of the first run and in one
 *      of the second; on a box of 8 x 2 x 2 hex8 both halves have cells;
 *   6. the assembly by two threads (a half each) and by one (inside a
 *      task of lac_tasks_pair, linalg/lac_tasks.h) give the same K_T and
 *      F_int to the last bit;
 *   7. lac_pattern_build alone makes no halves; such a pattern assembles
 *      the cells in order: the K_T and F_int of the triplet route to the
 *      last bit (with halves the sums are made in another order: equal
 *      to 1e-14, check 2); a second lac_pattern_halves does nothing.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
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

/* 5. the runs of the pattern p of the cells flagged in `cells`. */
static void
runs (const char *name, const lac_mesh *m, const lac_pattern *p,
      const char *cells, int want_halves)
{
  size_t n = p->nrun[0] + p->nrun[1] + p->nrun[2], ncell = 0;
  char *seen = calloc (m->ncells, 1), *node = calloc (m->nnodes, 1);
  int ok = 1;
  for (size_t c = 0; c < m->ncells; c++)
    ncell += !cells || cells[c];
  for (size_t q = 0; q < n; q++)
    {
      size_t c = p->order[q];
      ok = ok && c < m->ncells && !seen[c] && (!cells || cells[c]);
      if (c < m->ncells)
        seen[c] = 1;
    }
  check_true (ok && n == ncell, "%s: the runs hold the pattern's %zu cells "
              "once each (%zu)", name, ncell, n);
  for (int run = 0; run < 2; run++)       /* nodes of run 0, then run 1 */
    for (size_t q = run ? p->nrun[0] : 0;
         q < (run ? p->nrun[0] + p->nrun[1] : p->nrun[0]); q++)
      for (size_t k = m->ptr[p->order[q]]; k < m->ptr[p->order[q] + 1]; k++)
        {
          ok = ok && !(run == 1 && node[m->conn[k]] == 1);
          node[m->conn[k]] = (char) (run + 1);
        }
  check_true (ok, "%s: no node in both halves", name);
  if (want_halves)
    check_true (p->nrun[0] > 0 && p->nrun[1] > 0, "%s: both halves have "
                "cells (%zu, %zu, %zu)", name, p->nrun[0], p->nrun[1],
                p->nrun[2]);
  free (seen), free (node);
}

/* 6. the assembly inside a task: one thread. */
typedef struct
{
  const lac_mesh *m;
  const lac_hyper *h;
  const double *u;
  double *f;
  lac_pattern *p;
} one_job;

static int
one_thread (void *ctx)
{
  one_job *j = ctx;
  memset (j->f, 0, (size_t) j->m->dim * j->m->nnodes * sizeof *j->f);
  return lac_hyper_assemble_pattern (j->m, j->h, j->u, j->f, j->p);
}

static int
nothing (void *ctx)
{
  (void) ctx;
  return LAC_SUCCESS;
}

static void
same_bits (const char *name, const lac_mesh *m, const lac_hyper *h,
           const double *u, lac_pattern *p, const double *f2)
{
  size_t n = (size_t) m->dim * m->nnodes, nnz = (size_t) p->K->p[n];
  double *K2 = malloc (nnz * sizeof *K2), *f1 = malloc (n * sizeof *f1);
  memcpy (K2, p->K->x, nnz * sizeof *K2);
  one_job j = { m, h, u, f1, p };
  check_status (lac_tasks_pair (one_thread, &j, nothing, NULL), LAC_SUCCESS,
                "%s: the assembly in one thread", name);
  check_true (!memcmp (K2, p->K->x, nnz * sizeof *K2)
              && !memcmp (f1, f2, n * sizeof *f1), "%s: one thread and two "
              "give the same K_T and F_int to the last bit", name);
  free (K2), free (f1);
}

/* 7. a pattern without halves (lac_pattern_build alone) has none, and
 * lac_hyper_assemble_pattern adds its cells in order, as the triplet
 * route does: the same K_T (Kt) and F_int (ft) to the last bit (values:
 * a zero may differ in sign).  The halves are made once. */
static void
without_halves (const char *name, const lac_mesh *m, const lac_hyper *h,
                const double *u, lac_pattern *p, const lac_csc *Kt,
                const double *ft)
{
  size_t n = (size_t) m->dim * m->nnodes, nnz = (size_t) p->K->p[n];
  double *f = calloc (n, sizeof *f);
  check_true (!p->order && !p->nrun[0] && !p->nrun[1] && !p->nrun[2],
              "%s: lac_pattern_build makes no halves", name);
  check_status (lac_hyper_assemble_pattern (m, h, u, f, p), LAC_SUCCESS,
                "%s: the assembly without halves", name);
  size_t dk = 0, df = 0;
  for (size_t q = 0; q < nnz; q++)
    dk += Kt->x[q] != p->K->x[q];
  for (size_t j = 0; j < n; j++)
    df += ft[j] != f[j];
  check_true (!dk && !df, "%s: without halves, the K_T and F_int of the "
              "triplet route to the last bit (%zu, %zu entries differ)", name,
              dk, df);
  check_status (lac_pattern_halves (p, m), LAC_SUCCESS, "%s: halves", name);
  size_t *order = p->order;
  check_status (lac_pattern_halves (p, m), LAC_SUCCESS, "%s: halves again",
                name);
  check_true (order && p->order == order, "%s: the halves made once", name);
  free (f);
}

static void
compare (const char *name, lac_mesh *m, int half)
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
  double *f2 = calloc (n, sizeof *f2);
  unsigned seed = 99;
  for (size_t j = 0; j < n; j++)
    u[j] = 0.02 * rnd (&seed);
  lac_triplet *T = lac_triplet_alloc (n, n, 0);
  check_status (lac_hyper_assemble (m, &h, u, f1, T), LAC_SUCCESS,
                "%s: triplets", name);
  lac_csc *K = lac_csc_from_triplet (T);
  lac_pattern *p = lac_pattern_build (m, cells);
  check_true (K && p, "%s: pattern: %s", name, lac_error_message ());
  if (!K || !p)
    goto done;

  int same = K->ncol == p->K->ncol
             && !memcmp (K->p, p->K->p, (K->ncol + 1) * sizeof *K->p)
             && !memcmp (K->i, p->K->i, (size_t) K->p[K->ncol] * sizeof *K->i);
  check_true (same, "%s: the pattern differs from the triplet route's", name);
  if (same)
    without_halves (name, m, &h, u, p, K, f1);
  for (int pass = 0; pass < 2 && same; pass++)
    {
      memset (f2, 0, n * sizeof *f2);
      check_status (lac_hyper_assemble_pattern (m, &h, u, f2, p),
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
  if (same)
    {
      runs (name, m, p, cells, 0);
      same_bits (name, m, &h, u, p, f2);
    }
  if (half)
    {
      E[1] = 50;                       /* a cell outside the pattern */
      check_status (lac_hyper_assemble_pattern (m, &h, u, f2, p),
                    LAC_EINVAL, "%s: a cell outside the pattern", name);
      check_message ("not in the pattern", "%s: the message", name);
    }
done:
  lac_pattern_free (p);
  lac_csc_free (K);
  lac_triplet_free (T);
  free (E), free (nu), free (cells), free (u), free (f1), free (f2);
}

static lac_mesh *
box (lac_elem_type type)
{
  size_t n[3] = { 3, 2, 2 };
  double L[3] = { 1, 0.7, 0.5 };
  lac_mesh *m = NULL;
  lac_mesh_box (type, n, L, 0.2, &m);
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
        lac_mesh *m = box (types[k]);
        compare (lac_refelem_get (types[k])->name, m, half);
        lac_mesh_free (m);
      }
  lac_mesh *a = box (LAC_HEX8), *b = box (LAC_HEX27), *m = NULL;
  check_status (lac_mesh_merge (a, "a.", b, "b.", &m), LAC_SUCCESS, "merge");
  compare ("hex8 + hex27", m, 0);
  lac_mesh_free (a);
  lac_mesh_free (b);
  lac_mesh_free (m);
  size_t nl[3] = { 8, 2, 2 };
  double L[3] = { 4, 1, 1 };
  lac_mesh *bar = NULL;
  lac_mesh_box (LAC_HEX8, nl, L, 0, &bar);
  lac_pattern *p = bar ? lac_pattern_build (bar, NULL) : NULL;
  check_true (p && !lac_pattern_halves (p, bar), "the pattern of 8 x 2 x 2 "
              "hex8 and its halves");
  if (p)
    runs ("8 x 2 x 2 hex8", bar, p, NULL, 1);
  lac_pattern_free (p);
  lac_mesh_free (bar);
  lac_finalize ();
  return check_summary ();
}
