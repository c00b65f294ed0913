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
 *   4. a cell with E > 0 that is not in the pattern is refused.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "fem/lac_hyper.h"
#include "fem/lac_pattern.h"
#include "base/lac_status.h"

static double
rnd (unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 32767.5 - 1.0;
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
  lac_finalize ();
  return check_summary ();
}
