/* lac_frames.c -- nodal frames for rollers (see lac_frames.h)
 *                                                        [LAC (4), (8)]
 */
#include "fem/lac_frames.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* ---- construct / destroy ------------------------------------------------ */

lac_frames *
lac_frames_alloc (int dim, size_t nnodes)
{
  lac_frames *f = lac_calloc (1, sizeof *f);
  if (!f || !(f->of = lac_malloc ((nnodes ? nnodes : 1) * sizeof *f->of)))
    {
      lac_free (f);
      LAC_ERROR_NULL (LAC_ENOMEM, "frames of %zu nodes", nnodes);
    }
  f->dim = dim;
  f->nnodes = nnodes;
  for (size_t a = 0; a < nnodes; a++)
    f->of[a] = -1;
  return f;
}

void
lac_frames_free (lac_frames *f)
{
  if (!f)
    return;
  lac_free (f->of);
  lac_free (f->R);
  lac_free (f->tilt);
  lac_free (f->counted);
  lac_free (f);
}

int
lac_frames_set (lac_frames *f, size_t a, const double *R)
{
  int d = f->dim;
  if (a >= f->nnodes)
    LAC_ERROR (LAC_EINVAL, "node %zu out of range (%zu nodes)", a,
               f->nnodes);
  for (int i = 0; i < d; i++)                   /* R^T R = I, dim columns */
    for (int j = 0; j < d; j++)
      {
        double s = 0;
        for (int k = 0; k < 3; k++)
          s += R[3 * k + i] * R[3 * k + j];
        if (fabs (s - (i == j)) > 1e-12)
          LAC_ERROR (LAC_EINVAL, "the frame of node %zu is not orthonormal",
                     a);
      }
  if (f->of[a] < 0)
    {
      if (lac_grow (&f->R, 9 * (f->n + 1), &f->cap, sizeof *f->R, 9 * 16))
        LAC_ERROR (LAC_ENOMEM, "frames of %zu nodes", f->n + 1);
      f->of[a] = (long) f->n++;
    }
  memcpy (f->R + 9 * (size_t) f->of[a], R, 9 * sizeof *R);
  return LAC_SUCCESS;
}

int
lac_frames_set_check (lac_frames *f, size_t a, double tilt, int counted)
{
  if (a >= f->nnodes)
    LAC_ERROR (LAC_EINVAL, "node %zu out of range (%zu nodes)", a,
               f->nnodes);
  if (!f->tilt)
    {
      f->tilt = lac_calloc (f->nnodes + 1, sizeof *f->tilt);
      f->counted = lac_malloc ((f->nnodes + 1) * sizeof *f->counted);
      if (!f->tilt || !f->counted)
        {
          lac_free (f->tilt), lac_free (f->counted);
          f->tilt = NULL, f->counted = NULL;
          LAC_ERROR (LAC_ENOMEM, "tilts of %zu nodes", f->nnodes);
        }
      for (size_t b = 0; b < f->nnodes; b++)
        f->counted[b] = 3;
    }
  f->tilt[a] = tilt;
  f->counted[a] = counted;
  return LAC_SUCCESS;
}

/* ---- query -------------------------------------------------------------- */

const double *
lac_frames_of (const lac_frames *f, size_t a)
{
  return f && a < f->nnodes && f->of[a] >= 0 ? f->R + 9 * (size_t) f->of[a]
                                             : NULL;
}

double
lac_frames_tilt (const lac_frames *f, size_t a)
{
  return f && f->tilt && a < f->nnodes ? f->tilt[a] : 0;
}

int
lac_frames_counted (const lac_frames *f, size_t a)
{
  return f && f->counted && a < f->nnodes ? f->counted[a] : 3;
}

void
lac_frames_axis (const lac_frames *f, int dim, size_t q, double *e)
{
  size_t d = (size_t) dim;
  const double *R = lac_frames_of (f, q / d);
  for (int i = 0; i < 3; i++)
    e[i] = R ? R[3 * i + (int) (q % d)] : (double) ((size_t) i == q % d);
}

/* ---- rotate ------------------------------------------------------------- */

/* v_a <- R^T v_a (local) or R v_a (global) at every node with a frame. */
static void
rotate_nodes (const lac_frames *f, double *v, int to_local)
{
  int d = f ? f->dim : 0;
  for (size_t a = 0; f && a < f->nnodes; a++)
    {
      const double *R = lac_frames_of (f, a);
      double *va = v + (size_t) d * a, t[3] = { 0, 0, 0 };
      if (!R)
        continue;
      for (int i = 0; i < d; i++)
        for (int j = 0; j < d; j++)
          t[i] += (to_local ? R[3 * j + i] : R[3 * i + j]) * va[j];
      memcpy (va, t, (size_t) d * sizeof *t);
    }
}

void
lac_frames_to_local (const lac_frames *f, double *v)
{
  rotate_nodes (f, v, 1);
}

void
lac_frames_to_global (const lac_frames *f, double *v)
{
  rotate_nodes (f, v, 0);
}

/* K <- T^T K: in every column, the dim consecutive rows of a node with a
 * frame (all present) become R^T times them. */
static int
rotate_row_blocks (const lac_frames *f, lac_csc *K)
{
  int d = f->dim;
  for (size_t j = 0; j < K->ncol; j++)
    for (int q = K->p[j]; q < K->p[j + 1]; q++)
      {
        size_t r = (size_t) K->i[q], a = r / (size_t) d;
        const double *R = lac_frames_of (f, a);
        double t[3] = { 0, 0, 0 };
        if (!R)
          continue;
        if (r % (size_t) d != 0 || q + d > K->p[j + 1]
            || (size_t) K->i[q + d - 1] != r + (size_t) d - 1)
          LAC_ERROR (LAC_ESANITY, "the stiffness pattern lacks part of the "
                     "block of node %zu (column %zu)", a, j);
        for (int i = 0; i < d; i++)
          for (int k = 0; k < d; k++)
            t[i] += R[3 * k + i] * K->x[q + k];        /* R^T K_a */
        memcpy (K->x + q, t, (size_t) d * sizeof *t);
        q += d - 1;
      }
  return LAC_SUCCESS;
}

/* K <- K T: the dim columns of a node with a frame (one pattern) become
 * their combinations by R. */
static int
rotate_column_blocks (const lac_frames *f, lac_csc *K)
{
  size_t d = (size_t) f->dim;
  for (size_t a = 0; a < f->nnodes; a++)
    {
      const double *R = lac_frames_of (f, a);
      size_t c = d * a;
      if (!R)
        continue;
      int len = K->p[c + 1] - K->p[c];
      for (size_t k = 1; k < d; k++)
        if (K->p[c + k + 1] - K->p[c + k] != len
            || memcmp (K->i + K->p[c], K->i + K->p[c + k],
                       (size_t) len * sizeof *K->i))
          LAC_ERROR (LAC_ESANITY, "the columns of node %zu have different "
                     "patterns", a);
      for (int q = 0; q < len; q++)
        {
          double t[3] = { 0, 0, 0 };
          for (size_t j = 0; j < d; j++)
            for (size_t k = 0; k < d; k++)
              t[j] += K->x[K->p[c + k] + q] * R[3 * k + j];   /* K_a R */
          for (size_t j = 0; j < d; j++)
            K->x[K->p[c + j] + q] = t[j];
        }
    }
  return LAC_SUCCESS;
}

int
lac_frames_rotate_matrix (const lac_frames *f, lac_csc *K)
{
  int status;
  if (!f || f->n == 0)
    return LAC_SUCCESS;
  if (K->nrow != K->ncol || K->nrow != (size_t) f->dim * f->nnodes)
    LAC_ERROR (LAC_EBADLEN, "a %zu x %zu matrix for %zu nodes", K->nrow,
               K->ncol, f->nnodes);
  if ((status = rotate_row_blocks (f, K)))
    return status;
  return rotate_column_blocks (f, K);
}

int
lac_frames_rotate_rows (const lac_frames *f, lac_csc **A)
{
  if (!f || f->n == 0)
    return LAC_SUCCESS;
  const lac_csc *B = *A;
  size_t d = (size_t) f->dim, nnz = (size_t) B->p[B->ncol];
  lac_triplet *T = lac_triplet_alloc (B->nrow, B->ncol, d * nnz + 1);
  int status = T ? LAC_SUCCESS : LAC_ENOMEM;
  for (size_t j = 0; !status && j < B->ncol; j++)
    for (int q = B->p[j]; !status && q < B->p[j + 1]; q++)
      {
        size_t r = (size_t) B->i[q], a = r / d;
        const double *R = lac_frames_of (f, a);
        for (size_t i = 0; R && !status && i < d; i++)  /* (R^T B)_(a,i) */
          status = lac_triplet_add (T, d * a + i, j,
                                    R[3 * (r % d) + i] * B->x[q]);
        if (!R)
          status = lac_triplet_add (T, r, j, B->x[q]);
      }
  lac_csc *C = status ? NULL : lac_csc_from_triplet (T);
  lac_triplet_free (T);
  if (!C)
    LAC_ERROR (LAC_ENOMEM, "rows of a %zu x %zu matrix in the nodal frames",
               B->nrow, B->ncol);
  lac_csc_free (*A);
  *A = C;
  return LAC_SUCCESS;
}
