/* t011: Matrix Market dump of a CSC matrix, read back with a tiny parser:
 * same sizes, same entries bit for bit (%.17g), 1-based indices. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "linalg/lac_linalg.h"
#include "base/lac_status.h"

/* Read "coordinate real general" back into triplets (NULL on a bad file). */
static lac_triplet *
read_mm (const char *path)
{
  char line[256];
  size_t nr, nc, nz;
  lac_triplet *T = NULL;
  FILE *f = fopen (path, "r");
  if (!f)
    return NULL;
  if (!fgets (line, sizeof line, f)
      || strcmp (line, "%%MatrixMarket matrix coordinate real general\n"))
    goto done;
  do                                                  /* skip comments */
    if (!fgets (line, sizeof line, f))
      goto done;
  while (line[0] == '%');
  if (sscanf (line, "%zu %zu %zu", &nr, &nc, &nz) != 3)
    goto done;
  T = lac_triplet_alloc (nr, nc, nz);
  for (size_t k = 0; T && k < nz; k++)
    {
      size_t i, j;
      double x;
      if (fscanf (f, "%zu %zu %lf", &i, &j, &x) != 3 || i < 1 || j < 1
          || lac_triplet_add (T, i - 1, j - 1, x))
        {
          lac_triplet_free (T);
          T = NULL;
        }
    }
done:
  fclose (f);
  return T;
}

int
main (void)
{
  char path[64];
  lac_triplet *T, *R;
  lac_csc *A, *B = NULL;
  int fd;
  lac_init ();
  snprintf (path, sizeof path, "/tmp/lac-t011-XXXXXX");
  fd = mkstemp (path);
  check_true (fd >= 0, "temporary file");
  if (fd < 0)
    return check_summary ();
  close (fd);

  /* 4 x 6 with awkward values: tiny, huge, negative, 1/3, an empty column */
  T = lac_triplet_alloc (4, 6, 0);
  lac_triplet_add (T, 0, 0, 1.0 / 3.0);
  lac_triplet_add (T, 3, 0, -2.5e-300);
  lac_triplet_add (T, 2, 1, 6.02214076e23);
  lac_triplet_add (T, 1, 3, -0.1);
  lac_triplet_add (T, 1, 3, 0.7);                     /* summed: 0.6 */
  lac_triplet_add (T, 0, 5, 3.141592653589793);
  lac_triplet_add (T, 3, 5, 1e-17);
  A = lac_csc_from_triplet (T);
  check_status (lac_csc_write_mm (A, path), LAC_SUCCESS, "write");
  R = read_mm (path);
  check_true (R != NULL, "read back");
  if (R)
    {
      check_int ((long) R->nrow, 4, "nrow");
      check_int ((long) R->ncol, 6, "ncol");
      check_int ((long) R->nz, A->p[6], "nnz");
      B = lac_csc_from_triplet (R);
    }
  if (B)
    {
      for (size_t j = 0; j <= 6; j++)
        check_int (B->p[j], A->p[j], "p[%zu]", j);
      for (int q = 0; q < A->p[6]; q++)
        {
          check_int (B->i[q], A->i[q], "i[%d]", q);
          check_true (B->x[q] == A->x[q], "x[%d] = %.17g exactly", q,
                      A->x[q]);
        }
    }
  remove (path);
  check_status (lac_csc_write_mm (A, "/nonexistent-dir/a.mtx"), LAC_EIO,
                "unwritable path");
  check_message ("/nonexistent-dir/a.mtx", "message names the file");
  lac_csc_free (B);
  lac_triplet_free (R);
  lac_csc_free (A);
  lac_triplet_free (T);
  return check_summary ();
}
