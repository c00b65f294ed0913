/* lac_frames_basis.c -- the frame of the conditions at a node
 *                       (see lac_frames.h)               [LAC (4), (8)]
 */
#include "fem/lac_frames.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_status.h"
#include "base/lac_vec.h"

/* ---- the frame of the conditions at a node ------------------------------ */

/* Column k of R (row-major 3 x 3) into q, and back. */
static void
column_get (const double *R, int k, double *q)
{
  for (int i = 0; i < 3; i++)
    q[i] = R[3 * i + k];
}

static void
column_set (double *R, int k, const double *q)
{
  for (int i = 0; i < 3; i++)
    R[3 * i + k] = q[i];
}

/* w = d minus its components along the first r columns of R (twice, for
 * the orthogonality of nearly dependent directions); L[k] = d . q_k. */
static double
orthogonalize (const double *R, int r, const double *d, double *w, double *L)
{
  memcpy (w, d, 3 * sizeof *w);
  for (int k = 0; k < r; k++)
    L[k] = 0;
  for (int pass = 0; pass < 2; pass++)
    for (int k = 0; k < r; k++)
      {
        double q[3], s;
        column_get (R, k, q);
        s = lac_vec_dot (3, w, q);
        L[k] += s;
        for (int i = 0; i < 3; i++)
          w[i] -= s * q[i];
      }
  return lac_vec_norm (3, w);
}

/* The free axes: R's columns r .. dim-1 orthonormal to the first r. */
static void
complete (int dim, int r, double *R)
{
  for (int k = r; k < dim; k++)
    {
      double best[3] = { 0, 0, 0 }, nb = -1, L[3];
      for (int c = 0; c < dim; c++)     /* the axis least in the span */
        {
          double e[3] = { 0, 0, 0 }, w[3];
          e[c] = 1;
          double nw = orthogonalize (R, k, e, w, L);
          if (nw > nb + 1e-3)
            nb = nw, memcpy (best, w, sizeof w);
        }
      for (int i = 0; i < 3; i++)
        best[i] /= nb;
      column_set (R, k, best);
    }
  for (int k = dim; k < 3; k++)
    {
      double e[3] = { 0, 0, 0 };
      e[k] = 1;
      column_set (R, k, e);
    }
}

int
lac_frames_basis (int dim, size_t n, const double *d, const double *v,
                  double *R, double *w, char *indep, int *rank,
                  size_t *bad, size_t *with)
{
  int r = 0;
  memset (R, 0, 9 * sizeof *R);
  memset (w, 0, 3 * sizeof *w);
  *bad = *with = (size_t) -1;
  for (size_t j = 0; j < n; j++)
    {
      double res[3], L[3], s = 0, scale = fabs (v[j]);
      double nr = orthogonalize (R, r, d + 3 * j, res, L);
      if (r == dim)                   /* every axis fixed: nothing new */
        nr = 0;
      for (int k = 0; k < r; k++)
        s += L[k] * w[k], scale = fmax (scale, fabs (w[k]));
      indep[j] = nr > LAC_FRAMES_DEPENDENT;
      if (indep[j])                   /* a new axis: q_r . u = w_r */
        {
          for (int i = 0; i < 3; i++)
            res[i] /= nr;
          column_set (R, r, res);
          w[r++] = (v[j] - s) / nr;
        }
      else if (fabs (v[j] - s) > 1e-9 * scale)     /* d_j . u = v_j ? */
        {
          *bad = j;
          for (size_t i = 0; i < j && *with == (size_t) -1; i++)
            if (fabs (lac_vec_dot (3, d + 3 * i, d + 3 * j)) > LAC_FRAMES_DEPENDENT)
              *with = i;
          return LAC_EINVAL;
        }
    }
  complete (dim, r, R);
  *rank = r;
  return LAC_SUCCESS;
}
