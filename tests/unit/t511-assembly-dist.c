/* t511: the assembly of K_W on the MPI processes against the root's K
 *                                            [LAC (8), (17); chapter 13]
 *
 * fem/lac_assembly_dist.h on one process: the matrix assembled from the
 * cells, with the Dirichlet elimination at the insertion, equals K of
 * lac_assembly_stiffness_csc after lac_dirichlet_apply to 1e-14 of its
 * largest entry (quad4 plane strain, quad8 axisymmetric, hex8, tet4; in 2D an
 * interior cell with E = 0 left out by both); the same matrix from the root's K
 * (no mesh); K_W = K + C diag(dw) C^T and B = -C_A for a C of three
 * columns, one of them inactive (C given before the patterns are
 * made); then a change of dw added, where dw was 0.  The check of K
 * against the cells' element matrices (lac_dist_check_stiffness): to
 * rounding, and an entry changed by 1e-6 of the largest seen; refused
 * without the cells.  One process:
 * lac_petsc_agree gives back the status it is given.  Built without
 * PETSc: nothing to test (one check).  tests/cases-petsc.sh runs the
 * assembly on 2 and 4 processes (the same U and lambda) and injects a
 * failure on one of them.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "base/lac_status.h"
#include "fem/lac_assembly_dist.h"
#include "linalg/lac_petsc_env.h"

#ifdef LAC_HAVE_PETSC

#include <petscmat.h>

/* A PETSc matrix of the root's CSC A (n x m), all on this process. */
static Mat
from_csc (const lac_csc *A)
{
  Mat M;
  MatCreateSeqAIJ (PETSC_COMM_SELF, (PetscInt) A->nrow, (PetscInt) A->ncol,
                   0, NULL, &M);
  MatSetOption (M, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE);
  for (PetscInt j = 0; j < (PetscInt) A->ncol; j++)
    for (int p = A->p[j]; p < A->p[j + 1]; p++)
      MatSetValue (M, A->i[p], j, A->x[p], ADD_VALUES);
  MatAssemblyBegin (M, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (M, MAT_FINAL_ASSEMBLY);
  return M;
}

/* max |A - B| / max |B|. */
static double
mat_diff (Mat A, Mat B)
{
  Mat D;
  PetscReal d, b;
  MatDuplicate (A, MAT_COPY_VALUES, &D);
  MatAXPY (D, -1.0, B, DIFFERENT_NONZERO_PATTERN);
  MatNorm (D, NORM_MAX, &d);
  MatNorm (B, NORM_MAX, &b);
  MatDestroy (&D);
  return b > 0 ? d / b : d;
}

/* Empty K_W and B of d's rows, preallocated from its cells (K: the
 * root's, or NULL). */
static void
matrices (lac_dist *d, const lac_csc *K, size_t n, size_t k, int bs,
          Mat *Kw, Mat *B)
{
  Mat P[2];
  int r0, r1;
  lac_dist_rows (d, &r0, &r1);
  for (int l = 0; l < 2; l++)
    {
      MatCreate (PETSC_COMM_WORLD, &P[l]);
      MatSetType (P[l], MATPREALLOCATOR);
      MatSetSizes (P[l], r1 - r0, l ? (PetscInt) k : r1 - r0, (PetscInt) n,
                   l ? (PetscInt) k : (PetscInt) n);
      MatSetUp (P[l]);
    }
  check_status (lac_dist_pattern (d, K, P[0], P[1]), LAC_SUCCESS,
                "the patterns");
  for (int l = 0; l < 2; l++)
    {
      Mat *M = l ? B : Kw;
      MatCreate (PETSC_COMM_WORLD, M);
      MatSetSizes (*M, r1 - r0, l ? (PetscInt) k : r1 - r0, (PetscInt) n,
                   l ? (PetscInt) k : (PetscInt) n);
      MatSetType (*M, MATAIJ);
      MatSetBlockSize (*M, l ? 1 : bs);
      MatPreallocatorPreallocate (P[l], PETSC_TRUE, *M);
      MatDestroy (&P[l]);
    }
}

/* A C of three columns over the dofs 0 .. n-1 (rows of fixed dofs
 * zero, as the models make them). */
static lac_csc *
some_c (size_t n, const char *fixed)
{
  lac_csc *C = lac_csc_alloc (n, 3, 9);
  for (int i = 0; i < 3; i++)
    {
      C->p[i + 1] = 3 * (i + 1);
      for (int q = 0; q < 3; q++)
        {
          size_t j = ((size_t) (7 * i + 5 * q + 1)) % n;
          C->i[3 * i + q] = (int) (j + (size_t) q * n / 3) % (int) n;
          C->x[3 * i + q] = fixed[C->i[3 * i + q]] ? 0.0 : 0.5 + i - q;
        }
      /* rows in increasing order */
      for (int a = 3 * i; a < 3 * i + 3; a++)
        for (int b = a + 1; b < 3 * i + 3; b++)
          if (C->i[b] < C->i[a])
            {
              int t = C->i[a];
              double x = C->x[a];
              C->i[a] = C->i[b], C->x[a] = C->x[b];
              C->i[b] = t, C->x[b] = x;
            }
    }
  return C;
}

/* K + C diag(dw) C^T as a CSC (dense in between: small n). */
static lac_csc *
k_plus (const lac_csc *K, const lac_csc *C, const double *dw)
{
  size_t n = K->ncol;
  double *A = calloc (n * n, sizeof *A);
  lac_triplet *T = lac_triplet_alloc (n, n, n * n);
  for (size_t j = 0; j < n; j++)
    for (int p = K->p[j]; p < K->p[j + 1]; p++)
      A[(size_t) K->i[p] * n + j] += K->x[p];
  for (size_t i = 0; i < C->ncol; i++)
    for (int p = C->p[i]; p < C->p[i + 1]; p++)
      for (int q = C->p[i]; q < C->p[i + 1]; q++)
        A[(size_t) C->i[p] * n + (size_t) C->i[q]] += dw[i] * C->x[p]
                                                      * C->x[q];
  for (size_t a = 0; a < n; a++)
    for (size_t b = 0; b < n; b++)
      if (A[a * n + b] != 0)
        lac_triplet_add (T, a, b, A[a * n + b]);
  lac_csc *S = lac_csc_from_triplet (T);
  lac_triplet_free (T);
  free (A);
  return S;
}

/* B = -C_A as the CSC of the active columns. */
static lac_csc *
minus_ca (const lac_csc *C, const char *on)
{
  lac_csc *B = lac_csc_copy (C);
  for (size_t i = 0; i < C->ncol; i++)
    for (int p = C->p[i]; p < C->p[i + 1]; p++)
      B->x[p] = on[i] ? -C->x[p] : 0.0;
  return B;
}

static void
contact (lac_dist *d, Mat Kw, Mat B, const lac_csc *K, const lac_csc *C,
         const char *name)
{
  lac_csc *S, *Bc;
  double dw[3] = { 2.0, 0.0, 5.0 }, dw2[3] = { -2.0, 3.0, 0.0 };
  double sum[3] = { 0.0, 3.0, 5.0 };
  char on[3] = { 1, 0, 1 };
  Mat R;
  check_status (lac_dist_add_contact (d, Kw, dw), LAC_SUCCESS,
                "%s: C W C^T", name);
  MatAssemblyBegin (Kw, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (Kw, MAT_FINAL_ASSEMBLY);
  S = k_plus (K, C, dw);
  R = from_csc (S);
  check_abs (mat_diff (Kw, R), 0.0, 1e-14, "%s: K + C W C^T", name);
  MatDestroy (&R);
  lac_csc_free (S);
  check_status (lac_dist_add_contact (d, Kw, dw2), LAC_SUCCESS,
                "%s: a change of W", name);
  MatAssemblyBegin (Kw, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (Kw, MAT_FINAL_ASSEMBLY);
  S = k_plus (K, C, sum);
  R = from_csc (S);
  check_abs (mat_diff (Kw, R), 0.0, 1e-14, "%s: K + C W' C^T", name);
  MatDestroy (&R);
  lac_csc_free (S);
  check_status (lac_dist_set_b (d, B, on), LAC_SUCCESS, "%s: B", name);
  MatAssemblyBegin (B, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (B, MAT_FINAL_ASSEMBLY);
  Bc = minus_ca (C, on);
  R = from_csc (Bc);
  check_abs (mat_diff (B, R), 0.0, 0.0, "%s: B = -C_A", name);
  MatDestroy (&R);
  lac_csc_free (Bc);
}

/* K just assembled from the cells against their element matrices: to
 * rounding; one entry of PETSc's matrix changed by 1e-6 of its largest,
 * seen. */
static void
check_probe (lac_dist *d, Mat Kw, const char *name)
{
  double err = -1;
  Mat W;
  PetscReal big;
  check_status (lac_dist_check_stiffness (d, Kw, &err), LAC_SUCCESS,
                "%s: the check of K", name);
  check_abs (err, 0.0, 1e-14, "%s: K x against the cells' sum", name);
  MatDuplicate (Kw, MAT_COPY_VALUES, &W);
  MatNorm (W, NORM_MAX, &big);
  MatSetValue (W, 3, 3, 1e-6 * big, ADD_VALUES);
  MatAssemblyBegin (W, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (W, MAT_FINAL_ASSEMBLY);
  check_status (lac_dist_check_stiffness (d, W, &err), LAC_SUCCESS,
                "%s: the check of a changed K", name);
  check_true (err > 1e-9, "%s: one entry changed by 1e-6: %.2g", name, err);
  MatDestroy (&W);
}

/* One mesh: the cells' K_W and the root's K against K. */
static void
compare (lac_elem_type type, lac_model model, const size_t *nc,
         const char *name)
{
  const double L[3] = { 2.0, 1.0, 1.5 };
  lac_mesh *m = NULL;
  lac_csc *K = NULL, *C;
  lac_dist *d = NULL;
  Mat Kw, B, R;
  check_status (lac_mesh_box (type, nc, L, 0.2, &m), LAC_SUCCESS,
                "%s: mesh", name);
  size_t n = (size_t) m->dim * m->nnodes;
  double *E = malloc (m->ncells * sizeof *E);
  double *nu = malloc (m->ncells * sizeof *nu);
  double *F = calloc (n, sizeof *F);
  char *fixed = calloc (n, 1);
  lac_dirichlet *D = lac_dirichlet_alloc ();
  for (size_t c = 0; c < m->ncells; c++)
    E[c] = m->dim == 2 && c == 5 ? 0.0 : 1000.0 * (1 + (double) (c % 3)),
    nu[c] = 0.3;                  /* 2D: an interior cell without E */
  lac_elastic mat = { model, E, nu };
  lac_dirichlet_add_group (D, m, lac_mesh_group (m, "xmin"), 0, 0.1);
  lac_dirichlet_add_group (D, m, lac_mesh_group (m, "ymin"), 1, 0.0);
  for (size_t q = 0; q < D->n; q++)
    fixed[D->dof[q]] = 1;
  check_status (lac_assembly_stiffness_csc (m, &mat, &K), LAC_SUCCESS,
                "%s: K", name);
  check_status (lac_dirichlet_apply (D, K, F), LAC_SUCCESS,
                "%s: Dirichlet", name);
  lac_dist_source src = { m, &mat, fixed };
  check_status (lac_dist_alloc (&src, n, m->dim, &d), LAC_SUCCESS,
                "%s: the rows", name);
  check_true (d && lac_dist_row (d) && lac_dist_row (d)[n - 1]
              == (int) n - 1, "%s: one process, rows in order", name);
  C = some_c (n, fixed);
  check_status (lac_dist_set_c (d, C, 1), LAC_SUCCESS, "%s: C", name);
  matrices (d, NULL, n, 3, m->dim, &Kw, &B);
  check_status (lac_dist_add_stiffness (d, NULL, Kw, 1.0), LAC_SUCCESS,
                "%s: the cells", name);
  MatAssemblyBegin (Kw, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (Kw, MAT_FINAL_ASSEMBLY);
  R = from_csc (K);
  check_abs (mat_diff (Kw, R), 0.0, 1e-14, "%s: K from the cells", name);
  MatDestroy (&R);
  check_probe (d, Kw, name);
  contact (d, Kw, B, K, C, name);
  MatDestroy (&Kw);
  MatDestroy (&B);
  lac_dist_free (d);
  /* no mesh: the root's K */
  check_status (lac_dist_alloc (NULL, n, m->dim, &d), LAC_SUCCESS,
                "%s: rows without a mesh", name);
  check_status (lac_dist_set_c (d, C, 1), LAC_SUCCESS, "%s: C again", name);
  matrices (d, K, n, 3, m->dim, &Kw, &B);
  check_status (lac_dist_add_stiffness (d, K, Kw, 2.0), LAC_SUCCESS,
                "%s: the root's K", name);
  MatAssemblyBegin (Kw, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd (Kw, MAT_FINAL_ASSEMBLY);
  MatScale (Kw, 2.0);
  R = from_csc (K);
  check_abs (mat_diff (Kw, R), 0.0, 1e-15, "%s: K / kappa from the root's",
             name);
  double err;
  check_status (lac_dist_check_stiffness (d, Kw, &err), LAC_EINVAL,
                "%s: no check without the cells", name);
  MatDestroy (&R);
  MatDestroy (&Kw);
  MatDestroy (&B);
  lac_dist_free (d);
  lac_dirichlet_free (D);
  lac_csc_free (C);
  lac_csc_free (K);
  lac_mesh_free (m);
  free (E);
  free (nu);
  free (F);
  free (fixed);
}

int
main (void)
{
  const size_t n2[2] = { 4, 3 }, n3[3] = { 3, 2, 2 };
  lac_init ();
  check_status (lac_petsc_initialize (NULL), LAC_SUCCESS, "initialize");
  compare (LAC_QUAD4, LAC_PLANE_STRAIN, n2, "quad4");
  compare (LAC_QUAD8, LAC_AXISYMMETRIC, n2, "quad8 axisymmetric");
  compare (LAC_HEX8, LAC_SOLID3D, n3, "hex8");
  compare (LAC_TET4, LAC_SOLID3D, n3, "tet4");
  check_status (lac_petsc_agree (LAC_EINVAL), LAC_EINVAL,
                "one process: agree gives back the status");
  check_status (lac_petsc_agree (LAC_SUCCESS), LAC_SUCCESS,
                "one process: agree, no failure");
  lac_petsc_finalize ();
  lac_finalize ();
  return check_summary ();
}

#else

int
main (void)
{
  check_true (!lac_petsc_available (), "built without PETSc");
  return check_summary ();
}

#endif
