/* lac_petsc_mg_prolong.c -- the contact multigrid's finest level,
 *                           steps 4 and 5: the tentative prolongator of
 *                           K's near-null space on the aggregates (a QR
 *                           per aggregate), smoothed by one Jacobi step
 *                           (see lac_petsc_mg.h)            [chapter 13]
 */
#ifdef LAC_HAVE_PETSC

#include <math.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "linalg/lac_petsc_mg_internal.h"

#define EIG_STEPS 10         /* CG iterations of the estimate of lambda   */

/* ---- step 4: the tentative prolongator ---------------------------------- */

int
lac_petsc_mg_near_null_open (Mat K, near_null *z)
{
  MatNullSpace nsp;
  PetscBool has_const = PETSC_FALSE;
  PetscInt nv = 0;
  memset (z, 0, sizeof *z);
  TRY (MatGetBlockSize (K, &z->bs));
  TRY (MatGetNearNullSpace (K, &nsp));
  if (nsp)
    TRY (MatNullSpaceGetVecs (nsp, &has_const, &nv, &z->vec));
  z->given = nsp != NULL;
  z->has_const = has_const == PETSC_TRUE;
  z->m = z->given ? (int) nv + z->has_const : (int) z->bs;
  if (z->m < 1 || z->m > MAX_NULL)
    LAC_ERROR (LAC_EINVAL, "%d near-null vectors (1 to %d)", z->m, MAX_NULL);
  for (PetscInt k = 0; k < nv; k++)
    TRY (VecGetArrayRead (z->vec[k], &z->a[k]));
  return LAC_SUCCESS;
}

int
lac_petsc_mg_near_null_close (near_null *z)
{
  for (int k = 0; z->given && k < z->m - z->has_const; k++)
    TRY (VecRestoreArrayRead (z->vec[k], &z->a[k]));
  return LAC_SUCCESS;
}

/* Vector k at the local dof r. */
static double
near_null_at (const near_null *z, int k, PetscInt r)
{
  if (!z->given)
    return r % z->bs == k ? 1.0 : 0.0;
  if (z->has_const && k == 0)
    return 1.0;
  return PetscRealPart (z->a[k - z->has_const][r]);
}

static double
norm2 (const double *v, int n)
{
  double s = 0;
  for (int i = 0; i < n; i++)
    s += v[i] * v[i];
  return sqrt (s);
}

/* v -= Q_j (Q_j . v) for the k columns Q_j before it (twice: modified
 * Gram-Schmidt, repeated), r[j] += the coefficients (r NULL: not kept). */
static void
orthogonalize (double *v, const double *Q, int nr, int k, double *r)
{
  for (int pass = 0; pass < 2; pass++)
    for (int j = 0; j < k; j++)
      {
        double d = 0;
        for (int i = 0; i < nr; i++)
          d += Q[j * nr + i] * v[i];
        for (int i = 0; i < nr; i++)
          v[i] -= d * Q[j * nr + i];
        if (r)
          r[j] += d;
      }
}

/* B (nr x m, by columns) = Q R: Q in B, orthonormal columns; R (m x m,
 * by columns) upper triangular.  A column in the span of those before
 * it gets a unit vector e_p orthogonalized instead, and R_kk = 0 (an
 * aggregate of two nodes does not see the rotation about their line). */
static void
qr (double *B, int nr, int m, double *R)
{
  memset (R, 0, (size_t) m * (size_t) m * sizeof *R);
  for (int k = 0; k < m; k++)
    {
      double *v = B + (size_t) k * (size_t) nr, n0 = norm2 (v, nr), nk;
      orthogonalize (v, B, nr, k, R + (size_t) k * (size_t) m);
      nk = norm2 (v, nr);
      if (nk > 1e-10 * n0 && nk > 0)
        R[(size_t) k * (size_t) m + (size_t) k] = nk;
      else
        for (int p = 0; p < nr; p++)
          {
            memset (v, 0, (size_t) nr * sizeof *v);
            v[p] = 1;
            orthogonalize (v, B, nr, k, NULL);
            if ((nk = norm2 (v, nr)) > 0.5)
              break;
          }
      for (int i = 0; i < nr; i++)
        v[i] /= nk;
    }
}

/* P: K's rows, m columns an aggregate (nagg here, Nagg in all), m
 * entries in each row of a node in one. */
static int
create_tentative (Mat K, int m, const int *agg, int nagg, PetscInt Nagg,
                  Mat *P)
{
  PetscInt bs, nl, N, *dnz;
  TRY (MatGetBlockSize (K, &bs));
  TRY (MatGetLocalSize (K, &nl, NULL));
  TRY (MatGetSize (K, &N, NULL));
  TRY (PetscMalloc1 (nl + 1, &dnz));
  for (PetscInt r = 0; r < nl; r++)
    dnz[r] = agg[r / bs] >= 0 ? m : 0;
  TRY (MatCreate (PetscObjectComm ((PetscObject) K), P));
  TRY (MatSetSizes (*P, nl, m * nagg, N, m * Nagg));
  TRY (MatSetBlockSizes (*P, bs, m));
  TRY (MatSetType (*P, MATAIJ));
  TRY (MatSeqAIJSetPreallocation (*P, 0, dnz));
  TRY (MatMPIAIJSetPreallocation (*P, 0, dnz, 0, NULL));
  TRY (MatSetOption (*P, MAT_ROW_ORIENTED, PETSC_FALSE));
  TRY (MatSetOption (*P, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));
  TRY (PetscFree (dnz));
  return LAC_SUCCESS;
}

/* Aggregate a's block of P: the near-null vectors on its nodes (na of
 * them at node[]), Q of their QR into rows r0 + dofs, columns m (a0 +
 * a) ..; R (m x m, by columns) into R. B: room for bs na m. */
static int
tentative_block (Mat P, const near_null *z, PetscInt r0, const int *node,
                 int na, PetscInt col0, double *B, PetscInt *rows,
                 PetscInt *cols, double *R)
{
  int bs = (int) z->bs, nr = bs * na, m = z->m;
  for (int p = 0; p < na; p++)
    for (int c = 0; c < bs; c++)
      {
        PetscInt r = (PetscInt) bs * node[p] + c;
        rows[p * bs + c] = r0 + r;
        for (int k = 0; k < m; k++)
          B[(size_t) k * (size_t) nr + (size_t) (p * bs + c)]
            = near_null_at (z, k, r);
      }
  for (int k = 0; k < m; k++)
    cols[k] = col0 + k;
  qr (B, nr, m, R);
  TRY (MatSetValues (P, nr, rows, m, cols, B, INSERT_VALUES));
  return LAC_SUCCESS;
}

/* The coarse near-null vectors: vector k is R_a's column k on the m
 * coarse dofs of each aggregate a (R: nagg blocks m x m, by columns),
 * then orthonormalized (their span is what GAMG uses). */
static int
coarse_near_null (Mat P, int m, int nagg, const double *R, MatNullSpace *nsp)
{
  Vec v[MAX_NULL];
  PetscScalar *a;
  TRY (MatCreateVecs (P, &v[0], NULL));
  for (int k = 1; k < m; k++)
    TRY (VecDuplicate (v[0], &v[k]));
  for (int k = 0; k < m; k++)
    {
      TRY (VecGetArray (v[k], &a));
      for (int g = 0; g < nagg; g++)
        for (int j = 0; j < m; j++)
          a[g * m + j] = R[((size_t) g * (size_t) m + (size_t) k)
                           * (size_t) m + (size_t) j];
      TRY (VecRestoreArray (v[k], &a));
      for (int j = 0; j < k; j++)
        {
          PetscScalar d;
          TRY (VecDot (v[k], v[j], &d));
          TRY (VecAXPY (v[k], -d, v[j]));
        }
      TRY (VecNormalize (v[k], NULL));
    }
  TRY (MatNullSpaceCreate (PetscObjectComm ((PetscObject) P), PETSC_FALSE,
                           m, v, nsp));
  for (int k = 0; k < m; k++)
    TRY (VecDestroy (&v[k]));
  return LAC_SUCCESS;
}

/* The blocks of every aggregate into P (assembled), their R into R. */
static int
fill_tentative (Mat K, Mat P, const near_null *z, const int *agg, int nagg,
                PetscInt a0, double *R)
{
  PetscInt r0, nl;
  int status = LAC_SUCCESS, bs = (int) z->bs, m = z->m;
  TRY (MatGetOwnershipRange (K, &r0, NULL));
  TRY (MatGetLocalSize (K, &nl, NULL));
  int n = (int) nl / bs;
  int *first = lac_malloc (((size_t) nagg + 2) * sizeof *first);
  int *node = lac_malloc (((size_t) n + 1) * sizeof *node);
  int maxsize = first && node
                ? lac_petsc_mg_members (agg, n, nagg, first, node) : 0;
  size_t nr = (size_t) bs * (size_t) maxsize + 1;
  double *B = lac_malloc (nr * (size_t) m * sizeof *B);
  PetscInt *rows = lac_malloc (nr * sizeof *rows);
  PetscInt cols[MAX_NULL];
  if (!first || !node || !B || !rows)
    status = LAC_ERRMSG (LAC_ENOMEM, "the tentative prolongator");
  for (int a = 0; !status && a < nagg; a++)
    status = tentative_block (P, z, r0, node + first[a], first[a + 1]
                              - first[a], (PetscInt) m * (a0 + a), B, rows,
                              cols, R + (size_t) a * (size_t) m * (size_t) m);
  lac_free (first);
  lac_free (node);
  lac_free (B);
  lac_free (rows);
  if ((status = lac_petsc_agree (status)))       /* before the assembly */
    return status;
  TRY (MatAssemblyBegin (P, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (P, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* This process's first aggregate among all, and their number. */
static int
aggregate_offset (Mat K, int nagg, PetscInt *a0, PetscInt *Nagg)
{
  long long mine = nagg, before = 0, all = 0;
  MPI_Comm comm = PetscObjectComm ((PetscObject) K);
  if (MPI_Exscan (&mine, &before, 1, MPI_LONG_LONG, MPI_SUM, comm)
      || MPI_Allreduce (&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, comm))
    LAC_ERROR (LAC_EDEP, "MPI: the numbers of aggregates");
  int rank;
  MPI_Comm_rank (comm, &rank);
  *a0 = rank ? (PetscInt) before : 0;     /* MPI_Exscan: undefined on 0 */
  *Nagg = (PetscInt) all;
  if (all == 0)
    LAC_ERROR (LAC_EINVAL, "the contact multigrid found no aggregate (no "
               "coupling between the nodes of K)");
  return LAC_SUCCESS;
}

int
lac_petsc_mg_tentative (Mat K, const int *agg, int nagg, Mat *P,
                        MatNullSpace *nsp)
{
  near_null z;
  PetscInt a0 = 0, Nagg = 0;
  double *R = NULL;
  int status;
  *P = NULL;
  *nsp = NULL;
  if ((status = aggregate_offset (K, nagg, &a0, &Nagg))
      || (status = lac_petsc_mg_near_null_open (K, &z)))
    return status;
  if (!(R = lac_malloc (((size_t) nagg + 1) * (size_t) z.m * (size_t) z.m
                        * sizeof *R)))
    status = LAC_ERRMSG (LAC_ENOMEM, "the coarse near-null vectors");
  if (!status)
    status = create_tentative (K, z.m, agg, nagg, Nagg, P);
  if (!status)
    status = fill_tentative (K, *P, &z, agg, nagg, a0, R);
  int closed = lac_petsc_mg_near_null_close (&z);
  if (!status && !(status = closed))
    status = coarse_near_null (*P, z.m, nagg, R, nsp);
  lac_free (R);
  return status;
}

/* ---- step 5: one Jacobi step -------------------------------------------- */

/* *lambda: the largest eigenvalue of D^-1 K, from EIG_STEPS iterations of
 * CG with Jacobi on K x = b, b random (PETSc's generator, its default
 * seed: the same on every run of the same layout). */
int
lac_petsc_mg_largest_eigenvalue (Mat K, double *lambda)
{
  KSP ksp;
  PC pc;
  Vec b, x;
  PetscRandom rnd;
  PetscReal emax, emin;
  MPI_Comm comm = PetscObjectComm ((PetscObject) K);
  TRY (MatCreateVecs (K, &x, &b));
  TRY (PetscRandomCreate (comm, &rnd));
  TRY (VecSetRandom (b, rnd));
  TRY (PetscRandomDestroy (&rnd));
  TRY (KSPCreate (comm, &ksp));
  TRY (KSPSetType (ksp, KSPCG));
  TRY (KSPSetOperators (ksp, K, K));
  TRY (KSPGetPC (ksp, &pc));
  TRY (PCSetType (pc, PCJACOBI));
  TRY (KSPSetTolerances (ksp, 1e-30, 1e-50, 1e10, EIG_STEPS));
  TRY (KSPSetConvergenceTest (ksp, KSPConvergedSkip, NULL, NULL));
  TRY (KSPSetNormType (ksp, KSP_NORM_NONE));
  TRY (KSPSetComputeSingularValues (ksp, PETSC_TRUE));
  TRY (KSPSolve (ksp, b, x));
  TRY (KSPComputeExtremeSingularValues (ksp, &emax, &emin));
  TRY (KSPDestroy (&ksp));
  TRY (VecDestroy (&b));
  TRY (VecDestroy (&x));
  if (!(emax > 0))
    LAC_ERROR (LAC_ESING, "the contact multigrid: the largest eigenvalue of "
               "D^-1 K is %g, not positive", (double) emax);
  *lambda = emax;
  return LAC_SUCCESS;
}

/* *P = (I - w D^-1 K) *P, w = 4 / (3 lambda): the tentative prolongator
 * made smooth where K is stiff. */
int
lac_petsc_mg_smooth (Mat K, double lambda, Mat *P)
{
  Mat KP;
  Vec dinv;
  TRY (MatMatMult (K, *P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &KP));
  TRY (MatProductClear (KP));
  TRY (MatCreateVecs (K, NULL, &dinv));
  TRY (MatGetDiagonal (K, dinv));
  TRY (VecReciprocal (dinv));
  TRY (MatDiagonalScale (KP, dinv, NULL));                 /* D^-1 K P  */
  TRY (MatAYPX (KP, -4.0 / (3.0 * lambda), *P, SUBSET_NONZERO_PATTERN));
  TRY (VecDestroy (&dinv));
  TRY (MatDestroy (P));
  *P = KP;
  return LAC_SUCCESS;
}

#else

typedef int lac_petsc_mg_prolong_unused;        /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
