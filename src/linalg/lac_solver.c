/* lac_solver.c -- one solver interface, three back ends (dense, UMFPACK,
 * CHOLMOD), chosen at run time
 *
 * factor  dense    copy A into an n x n array, LU with partial pivoting
 *         umfpack  copy A (64-bit indices), symbolic + numeric LU
 *         cholmod  copy the upper triangle (64-bit indices, stype = 1),
 *                  analyze (METIS/AMD) + factorize (supernodal LL' or
 *                  simplicial LDL', CHOLMOD's choice); the factor is kept
 * solve   forward/back substitution with the stored factors.
 *
 * The 64-bit (SuiteSparse_long) versions of UMFPACK and CHOLMOD are used so
 * that large factors (nnz(L) > 2^31 for 3D problems of ~1M unknowns) do not
 * overflow.  Singularity is decided the same way for all back ends, by a
 * relative pivot test (LAC_PIVOT_RTOL) and a condition estimate from two
 * extra solves (LAC_RCOND_MIN), both documented in lac_linalg.h: a floating
 * body must be reported, not solved into garbage.
 *
 * SuiteSparse allocates with its own malloc; its objects are freed with its
 * own free calls in this file.  CHOLMOD's printing is switched off
 * (Common->print = 0), UMFPACK prints only through its report functions,
 * which are not called.
 *
 * References: T. A. Davis, Algorithm 832: UMFPACK V4.3, ACM TOMS 30 (2004);
 * Y. Chen, T. A. Davis, W. W. Hager, S. Rajamanickam, Algorithm 887:
 * CHOLMOD, ACM TOMS 35 (2008); GSL manual, "Linear Algebra: LU".
 */
#include "linalg/lac_linalg.h"

#include "linalg/lac_blas.h"

#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <cholmod.h>
#include <umfpack.h>
#include "base/lac_mem.h"
#include "linalg/lac_solver_internal.h"
#include "base/lac_status.h"

struct lac_solver
{
  lac_solver_kind kind;
  int factored;            /* a usable factorization is stored           */
  int threads;             /* 1: the BLAS on one thread; 0: every core   */
  lac_solver_info info;    /* of the last successful factorization       */
  size_t n;
  /* dense */
  double *lu;              /* owned, n*n: L and U, row-major (GSL)       */
  size_t *perm;            /* owned, n: row permutation                  */
  /* umfpack */
  ss_long *Ap, *Ai;        /* owned, copy of A (solve refines with A)    */
  double *Ax;              /* owned                                      */
  void *numeric;           /* owned by UMFPACK                           */
  double control[UMFPACK_CONTROL], uinfo[UMFPACK_INFO];
  /* cholmod */
  int cc_started;
  cholmod_common cc;
  cholmod_factor *L;       /* owned by CHOLMOD                           */
  /* the analysis kept for lac_solver_refactor (umfpack, cholmod) */
  void *symbolic;          /* owned by UMFPACK: ordering, symbolic LU    */
  double sym_nnz, sym_fl;  /* cholmod: nnz(L) and flops of the analysis  */
  size_t sym_n, sym_nnz_A; /* order and entries of the analysed pattern  */
  unsigned long long sym_hash;  /* checksum of that pattern              */
};

/* ---- names ------------------------------------------------------------ */

static const char *const kind_names[] = { "dense", "umfpack", "cholmod" };

int
lac_solver_kind_from_name (const char *name)
{
  for (int k = 0; name && k < 3; k++)
    if (strcmp (name, kind_names[k]) == 0)
      return k;
  return -1;
}

const char *
lac_solver_kind_name (lac_solver_kind k)
{
  return (unsigned) k < 3 ? kind_names[k] : "unknown";
}

/* ---- alloc / free ------------------------------------------------------ */

void
lac_solver_set_threads (lac_solver *s, int threads)
{
  s->threads = threads;
}

/* Around a numeric factorization or a solve: every core, unless s runs
 * beside another task (then the BLAS stays on the one thread it is on).
 * A solve with one right-hand side is memory-bound matrix-vector
 * products on the supernodes: two cores read the factor 1.4x faster on
 * the fine ring (lac_blas.h). */
static void
blas_begin (const lac_solver *s)
{
  if (s->threads != 1)
    lac_blas_parallel ();
}

static void
blas_end (const lac_solver *s)
{
  if (s->threads != 1)
    lac_blas_serial ();
}

lac_solver *
lac_solver_alloc (lac_solver_kind kind)
{
  lac_solver *s;
  if ((unsigned) kind > LAC_SOLVER_CHOLMOD)
    LAC_ERROR_NULL (LAC_EINVAL, "unknown solver kind %d (dense, umfpack or "
                    "cholmod)", (int) kind);
  s = lac_calloc (1, sizeof *s);
  if (!s)
    LAC_ERROR_NULL (LAC_ENOMEM, "solver");
  s->kind = kind;
  if (kind == LAC_SOLVER_UMFPACK)
    {
      umfpack_dl_defaults (s->control);
      s->control[UMFPACK_PRL] = 0;                     /* never print */
      /* METIS instead of the default AMD: on the 3D saddle systems of
       * chapter 07 the LU takes 4x less time and 2x less memory */
      s->control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
    }
  if (kind == LAC_SOLVER_CHOLMOD)
    {
      if (!cholmod_l_start (&s->cc))
        {
          lac_free (s);
          LAC_ERROR_NULL (LAC_EDEP, "cholmod_l_start failed");
        }
      s->cc_started = 1;
      s->cc.print = 0;                   /* errors come back as statuses */
    }
  return s;
}

/* Drop the analysis kept for lac_solver_refactor. */
static void
forget_analysis (lac_solver *s)
{
  if (s->symbolic)
    umfpack_dl_free_symbolic (&s->symbolic);
  if (s->L)
    cholmod_l_free_factor (&s->L, &s->cc);
  s->sym_n = s->sym_nnz_A = 0;
  s->sym_hash = 0;
}

/* Drop the stored factorization (the solver can factor again); with
 * keep_analysis the ordering and symbolic analysis stay (for CHOLMOD, L
 * keeps its structure and gets new numbers). */
static void
release (lac_solver *s, int keep_analysis)
{
  lac_free (s->lu);
  lac_free (s->perm);
  lac_free (s->Ap);
  lac_free (s->Ai);
  lac_free (s->Ax);
  s->lu = NULL;
  s->perm = NULL;
  s->Ap = s->Ai = NULL;
  s->Ax = NULL;
  if (s->numeric)
    umfpack_dl_free_numeric (&s->numeric);
  if (!keep_analysis)
    forget_analysis (s);
  s->factored = 0;
  s->n = 0;
}

void
lac_solver_free (lac_solver *s)
{
  if (!s)
    return;
  release (s, 0);
  if (s->cc_started)
    cholmod_l_finish (&s->cc);
  lac_free (s);
}

/* ---- dense: LU with partial pivoting, solved by GSL ---------------------- */

/* P A = L U in place (row-major a, n x n; L unit lower, U upper, as GSL
 * stores them), row k of P A is row perm[k] of A (GSL's permutation, for
 * gsl_linalg_LU_solve).  Golub and Van Loan, Algorithm 3.4.1.  Written
 * out because gsl_linalg_LU_decomp (GSL 2.7) does not check an allocation
 * of its own and crashes when memory runs out; this allocates nothing. */
static void
lu_decomp (double *a, size_t n, size_t *perm)
{
  for (size_t i = 0; i < n; i++)
    perm[i] = i;
  for (size_t k = 0; k < n; k++)
    {
      size_t p = k;
      for (size_t i = k + 1; i < n; i++)            /* the pivot row */
        if (fabs (a[i * n + k]) > fabs (a[p * n + k]))
          p = i;
      if (p != k)
        {
          size_t t = perm[k];
          perm[k] = perm[p];
          perm[p] = t;
          for (size_t j = 0; j < n; j++)
            {
              double v = a[k * n + j];
              a[k * n + j] = a[p * n + j];
              a[p * n + j] = v;
            }
        }
      if (a[k * n + k] == 0)                        /* singular: U_kk = 0 */
        continue;
      for (size_t i = k + 1; i < n; i++)
        {
          double l = a[i * n + k] /= a[k * n + k];  /* L_ik */
          for (size_t j = k + 1; j < n; j++)
            a[i * n + j] -= l * a[k * n + j];
        }
    }
}

static int
dense_factor (lac_solver *s, const lac_csc *A)
{
  size_t n = A->ncol, kmin = 0;
  double amax = 0, umin = HUGE_VAL;

  if (n > LAC_DENSE_NMAX)
    LAC_ERROR (LAC_EINVAL, "dense solver refuses n = %zu > %d (the n x n "
               "copy would take %.1f GB); use umfpack or cholmod", n,
               LAC_DENSE_NMAX, 8e-9 * (double) n * (double) n);
  s->lu = lac_calloc (n * n, sizeof *s->lu);
  s->perm = lac_malloc (n * sizeof *s->perm);
  if (!s->lu || !s->perm)
    LAC_ERROR (LAC_ENOMEM, "dense copy of a %zu x %zu matrix (%.1f MB)", n, n,
               8e-6 * (double) n * (double) n);
  for (size_t j = 0; j < n; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      {
        s->lu[(size_t) A->i[q] * n + j] += A->x[q];    /* LU(i,j) = A(i,j) */
        if (fabs (A->x[q]) > amax)
          amax = fabs (A->x[q]);
      }
  if (amax == 0)
    LAC_ERROR (LAC_ESING, "the %zu x %zu matrix is zero", n, n);
  lu_decomp (s->lu, n, s->perm);                       /* P A = L U */
  for (size_t k = 0; k < n; k++)            /* min_k |U_kk| vs max |A_ij| */
    if (fabs (s->lu[k * n + k]) < umin)
      {
        umin = fabs (s->lu[k * n + k]);
        kmin = k;
      }
  s->info.pivot_ratio = umin / amax;
  if (!(umin > LAC_PIVOT_RTOL * amax))
    LAC_ERROR (LAC_ESING, "singular matrix: LU pivot %zu (column %zu) is "
               "|U_kk| = %.3g <= %g * max|A| = %.3g; is the body fixed "
               "against rigid motion?", kmin, kmin, umin, LAC_PIVOT_RTOL,
               LAC_PIVOT_RTOL * amax);
  s->info.nnz_factor = (double) n * (double) n;
  s->info.peak_bytes = 8.0 * (double) n * (double) n;
  s->info.flops = 2.0 / 3.0 * (double) n * (double) n * (double) n;
  s->info.method = "LU, partial pivoting";
  s->info.ordering = "";
  return LAC_SUCCESS;
}

static int
dense_solve (lac_solver *s, const double *b, double *x)
{
  gsl_matrix_view M = gsl_matrix_view_array (s->lu, s->n, s->n);
  gsl_permutation P = { s->n, s->perm };
  gsl_vector_const_view B = gsl_vector_const_view_array (b, s->n);
  gsl_vector_view X = gsl_vector_view_array (x, s->n);
  int gs = gsl_linalg_LU_solve (&M.matrix, &P, &B.vector, &X.vector);
  if (gs)
    LAC_ERROR (gs == GSL_EDOM ? LAC_ESING : LAC_EDEP,
               "gsl_linalg_LU_solve failed: %s", gsl_strerror (gs));
  return LAC_SUCCESS;
}

/* ---- umfpack: sparse LU ------------------------------------------------- */

/* Name the column of the smallest |U_kk| (original numbering). */
static int
umf_singular (lac_solver *s, const char *why)
{
  ss_long n = (ss_long) s->n, kmin = 0;
  ss_long *Q = lac_malloc ((size_t) n * sizeof *Q);
  double *D = lac_malloc ((size_t) n * sizeof *D);
  double umin = HUGE_VAL;
  int st;
  if (!Q || !D)
    {
      lac_free (Q);
      lac_free (D);
      LAC_ERROR (LAC_ESING, "singular matrix (%s)", why);
    }
  st = umfpack_dl_get_numeric (NULL, NULL, NULL, NULL, NULL, NULL, NULL, Q,
                                 D, NULL, NULL, s->numeric);
  for (ss_long k = 0; st == UMFPACK_OK && k < n; k++)
    if (fabs (D[k]) < umin)
      {
        umin = fabs (D[k]);
        kmin = Q[k];
      }
  lac_free (Q);
  lac_free (D);
  LAC_ERROR (LAC_ESING, "singular matrix (%s): smallest pivot |U_kk| = %.3g "
             "at column %ld, rcond = %.3g; is the body fixed against rigid "
             "motion?", why, umin, (long) kmin, s->uinfo[UMFPACK_RCOND]);
}

static int
umf_factor (lac_solver *s, const lac_csc *A)
{
  size_t n = A->ncol, nnz = (size_t) A->p[n];
  double *info = s->uinfo;
  int st;

  s->Ap = lac_malloc ((n + 1) * sizeof *s->Ap);
  s->Ai = lac_malloc (nnz * sizeof *s->Ai);
  s->Ax = lac_malloc (nnz * sizeof *s->Ax);
  if (!s->Ap || !s->Ai || !s->Ax)
    LAC_ERROR (LAC_ENOMEM, "copy of a matrix with %zu entries for UMFPACK",
               nnz);
  for (size_t j = 0; j <= n; j++)
    s->Ap[j] = A->p[j];
  for (size_t q = 0; q < nnz; q++)
    {
      s->Ai[q] = A->i[q];
      s->Ax[q] = A->x[q];
    }
  st = UMFPACK_OK;
  if (!s->symbolic)                   /* ordering + symbolic LU, or kept */
    st = umfpack_dl_symbolic ((ss_long) n, (ss_long) n, s->Ap, s->Ai, s->Ax,
                              &s->symbolic, s->control, info);
  blas_begin (s);
  if (st == UMFPACK_OK)
    st = umfpack_dl_numeric (s->Ap, s->Ai, s->Ax, s->symbolic, &s->numeric,
                             s->control, info);
  blas_end (s);
  if (st == UMFPACK_ERROR_out_of_memory)
    LAC_ERROR (LAC_ENOMEM, "UMFPACK ran out of memory factoring n = %zu, "
               "nnz = %zu", n, nnz);
  if (st == UMFPACK_ERROR_invalid_matrix)
    LAC_ERROR (LAC_EINVAL, "UMFPACK: invalid matrix (row indices must be "
               "sorted and unique in each column)");
  if (st == UMFPACK_WARNING_singular_matrix)
    return umf_singular (s, "UMFPACK found a zero pivot");
  if (st != UMFPACK_OK && st != UMFPACK_WARNING_determinant_underflow
      && st != UMFPACK_WARNING_determinant_overflow)
    LAC_ERROR (LAC_EDEP, "UMFPACK factorization failed with status %d", st);
  s->info.pivot_ratio = info[UMFPACK_RCOND];
  if (!(info[UMFPACK_RCOND] >= LAC_PIVOT_RTOL))   /* also catches NaN */
    return umf_singular (s, "rcond below LAC_PIVOT_RTOL");
  s->info.nnz_factor = info[UMFPACK_LNZ] + info[UMFPACK_UNZ] - (double) n;
  s->info.flops = info[UMFPACK_FLOPS];
  s->info.peak_bytes = info[UMFPACK_PEAK_MEMORY] * info[UMFPACK_SIZE_OF_UNIT];
  s->info.method = "LU (UMFPACK)";
  s->info.ordering = info[UMFPACK_ORDERING_USED] == UMFPACK_ORDERING_METIS
    ? "METIS" : info[UMFPACK_ORDERING_USED] == UMFPACK_ORDERING_AMD
    ? "AMD" : "COLAMD/other";
  return LAC_SUCCESS;
}

static int
umf_solve (lac_solver *s, const double *b, double *x)
{
  int st = umfpack_dl_solve (UMFPACK_A, s->Ap, s->Ai, s->Ax, x, b, s->numeric,
                             s->control, s->uinfo);
  if (st == UMFPACK_WARNING_singular_matrix)
    LAC_ERROR (LAC_ESING, "UMFPACK solve: singular matrix");
  if (st != UMFPACK_OK)
    LAC_ERROR (LAC_EDEP, "UMFPACK solve failed with status %d", st);
  return LAC_SUCCESS;
}

/* ---- cholmod: sparse Cholesky ------------------------------------------- */

/* A(i,j) for i < j must equal A(j,i): CHOLMOD reads only the upper part,
 * so a non-symmetric matrix would be solved silently wrong.  The rows of
 * a column are sorted, and the columns j are visited in order: the rows j
 * looked for in a column i come in increasing order, so a cursor per
 * column finds them all in one pass over A (O(nnz), not a search each). */
static int
check_symmetric (const lac_csc *A)
{
  double amax = 0, tol;
  int *next = lac_malloc ((A->ncol ? A->ncol : 1) * sizeof *next);
  if (!next)
    LAC_ERROR (LAC_ENOMEM, "symmetry check of %zu columns", A->ncol);
  for (int q = 0; q < A->p[A->ncol]; q++)
    amax = fmax (amax, fabs (A->x[q]));
  tol = 1e-10 * amax;
  memcpy (next, A->p, A->ncol * sizeof *next);
  for (size_t j = 0; j < A->ncol; j++)
    for (int q = A->p[j]; q < A->p[j + 1] && (size_t) A->i[q] < j; q++)
      {
        size_t i = (size_t) A->i[q];
        int *c = &next[i];                 /* row j in column i, if there */
        while (*c < A->p[i + 1] && A->i[*c] < (int) j)
          ++*c;
        double aji = *c < A->p[i + 1] && A->i[*c] == (int) j ? A->x[*c] : 0;
        if (fabs (A->x[q] - aji) > tol)
          {
            lac_free (next);
            LAC_ERROR (LAC_EINVAL, "cholmod needs a symmetric matrix: "
                       "A(%zu,%zu) = %.6g but A(%zu,%zu) = %.6g; use umfpack",
                       i, j, A->x[q], j, i, aji);
          }
      }
  lac_free (next);
  return LAC_SUCCESS;
}

/* Upper triangle of A as a CHOLMOD matrix with stype = 1. */
cholmod_sparse *
lac_solver_upper_copy (const lac_csc *A, int xtype, cholmod_common *cc)
{
  size_t n = A->ncol, nz = 0;
  cholmod_sparse *C;
  ss_long *Cp, *Ci;
  double *Cx;
  for (size_t j = 0; j < n; j++)
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      nz += (size_t) A->i[q] <= j;
  C = cholmod_l_allocate_sparse (n, n, nz, 1, 1, 1, xtype, cc);
  if (!C)
    LAC_ERROR_NULL (LAC_ENOMEM, "upper triangle for CHOLMOD (%zu entries)",
                    nz);
  Cp = C->p;
  Ci = C->i;
  Cx = C->x;
  nz = 0;
  for (size_t j = 0; j < n; j++)
    {
      Cp[j] = (ss_long) nz;
      for (int q = A->p[j]; q < A->p[j + 1] && (size_t) A->i[q] <= j; q++)
        {
          if (Cx)
            Cx[nz] = A->x[q];
          Ci[nz++] = A->i[q];
        }
    }
  Cp[n] = (ss_long) nz;
  return C;
}

/* Pivot d_k of column k of the factor: L_kk^2 (LL') or D_kk (LDL'). */
static double
chol_pivot (const cholmod_factor *L, size_t k, const ss_long *col_super)
{
  const double *Lx = L->x;
  if (L->is_super)
    {
      const ss_long *super = L->super, *pi = L->pi, *px = L->px;
      ss_long sn = col_super[k], nsrow = pi[sn + 1] - pi[sn];
      ss_long jj = (ss_long) k - super[sn];
      double d = Lx[px[sn] + jj * nsrow + jj];
      return d * d;
    }
  else
    {
      double d = Lx[((const ss_long *) L->p)[k]];      /* diagonal first */
      return L->is_ll ? d * d : d;
    }
}

/* Scan the pivots of L: not positive definite, or numerically singular. */
static int
chol_check_pivots (lac_solver *s)
{
  cholmod_factor *L = s->L;
  size_t n = L->n, kmin = 0;
  double dmin = HUGE_VAL, dmax = 0;
  const ss_long *perm = L->Perm;
  ss_long *col_super = NULL;
  if (L->is_super)
    {
      const ss_long *super = L->super;
      col_super = lac_malloc (n * sizeof *col_super);
      if (!col_super)
        LAC_ERROR (LAC_ENOMEM, "pivot scan of the CHOLMOD factor");
      for (size_t sn = 0; sn < L->nsuper; sn++)
        for (ss_long k = super[sn]; k < super[sn + 1]; k++)
          col_super[k] = (ss_long) sn;
    }
  for (size_t k = 0; k < n; k++)
    {
      double d = chol_pivot (L, k, col_super);
      if (d < dmin || d != d)                        /* NaN counts too */
        {
          dmin = d;
          kmin = k;
        }
      dmax = fmax (dmax, d);
    }
  lac_free (col_super);
  s->info.pivot_ratio = dmax > 0 ? dmin / dmax : 0;
  if (!(dmin > 0))
    LAC_ERROR (LAC_ESING, "CHOLMOD: %s, pivot %.3g at column %ld (factor "
               "column %zu); is the body fixed against rigid motion?",
               fabs (dmin) < LAC_PIVOT_RTOL * dmax ? "singular matrix"
               : "matrix not positive definite", dmin, (long) perm[kmin],
               kmin);
  if (!(s->info.pivot_ratio >= LAC_PIVOT_RTOL))
    LAC_ERROR (LAC_ESING, "CHOLMOD: singular matrix, smallest pivot %.3g = "
               "%.3g * largest at column %ld (factor column %zu); is the body"
               " fixed against rigid motion?", dmin, s->info.pivot_ratio,
               (long) perm[kmin], kmin);
  return LAC_SUCCESS;
}

const char *
lac_solver_chol_ordering (int ord)
{
  switch (ord)
    {
    case CHOLMOD_NATURAL: return "natural";
    case CHOLMOD_AMD: return "AMD";
    case CHOLMOD_METIS: return "METIS";
    case CHOLMOD_NESDIS: return "NESDIS";
    default: return "other";
    }
}

static int
chol_factor (lac_solver *s, const lac_csc *A)
{
  cholmod_common *cc = &s->cc;
  cholmod_sparse *C;
  int status = check_symmetric (A);
  if (status)
    return status;
  cc->memory_usage = 0;
  if (!(C = lac_solver_upper_copy (A, CHOLMOD_REAL, cc)))
    return LAC_ENOMEM;
  if (!s->L)                /* ordering + symbolic factorization, or kept */
    {
      s->L = cholmod_l_analyze (C, cc);
      s->sym_nnz = cc->lnz;
      s->sym_fl = cc->fl;
    }
  blas_begin (s);
  if (s->L)
    cholmod_l_factorize (C, s->L, cc);
  blas_end (s);
  cholmod_l_free_sparse (&C, cc);
  if (!s->L || cc->status < CHOLMOD_OK)
    LAC_ERROR (cc->status == CHOLMOD_OUT_OF_MEMORY ? LAC_ENOMEM : LAC_EDEP,
               "CHOLMOD %s failed with status %d%s", s->L ? "factorize"
               : "analyze", cc->status, cc->status == CHOLMOD_TOO_LARGE
               ? " (integer overflow: problem too large)" : "");
  if (cc->status == CHOLMOD_NOT_POSDEF || s->L->minor < s->L->n)
    LAC_ERROR (LAC_ESING, "CHOLMOD: matrix not positive definite at column "
               "%ld (factor column %zu, CHOLMOD_NOT_POSDEF); is the body "
               "fixed against rigid motion?",
               (long) ((ss_long *) s->L->Perm)[s->L->minor], s->L->minor);
  if ((status = chol_check_pivots (s)))
    return status;
  s->info.nnz_factor = s->sym_nnz;
  s->info.flops = s->sym_fl;
  s->info.peak_bytes = (double) cc->memory_usage;
  s->info.method = s->L->is_super ? "supernodal LL' (CHOLMOD)"
    : s->L->is_ll ? "simplicial LL' (CHOLMOD)" : "simplicial LDL' (CHOLMOD)";
  s->info.ordering = lac_solver_chol_ordering (s->L->ordering);
  return LAC_SUCCESS;
}

/* b (n x nrhs, column after column) wrapped for CHOLMOD without a copy. */
static cholmod_dense
wrap (const lac_solver *s, size_t nrhs, const double *b)
{
  cholmod_dense B;
  memset (&B, 0, sizeof B);
  B.nrow = s->n;
  B.ncol = nrhs;
  B.nzmax = s->n * nrhs;
  B.d = s->n;
  B.x = (void *) b;                          /* read only by cholmod_solve */
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  return B;
}

/* x = the solution of system sys1 and then sys2 (CHOLMOD_A and 0 for a
 * whole solve, CHOLMOD_P and CHOLMOD_L for its first half, ...), for
 * nrhs columns. */
static int
chol_solve2 (lac_solver *s, int sys1, int sys2, size_t nrhs, const double *b,
             double *x)
{
  cholmod_dense B = wrap (s, nrhs, b), *T, *X;
  blas_begin (s);
  X = T = cholmod_l_solve (sys1, s->L, &B, &s->cc);
  if (T && sys2)
    X = cholmod_l_solve (sys2, s->L, T, &s->cc);
  blas_end (s);
  if (X != T)
    cholmod_l_free_dense (&T, &s->cc);
  if (!X)
    LAC_ERROR (s->cc.status == CHOLMOD_OUT_OF_MEMORY ? LAC_ENOMEM : LAC_EDEP,
               "cholmod_l_solve failed with status %d", s->cc.status);
  memcpy (x, X->x, s->n * nrhs * sizeof *x);
  cholmod_l_free_dense (&X, &s->cc);
  return LAC_SUCCESS;
}

/* X = A^{-1} B for nrhs columns. */
static int
chol_solve (lac_solver *s, size_t nrhs, const double *b, double *x)
{
  return chol_solve2 (s, CHOLMOD_A, 0, nrhs, b, x);
}

/* ---- condition estimate (all back ends) -------------------------------- */

static int solve_columns (lac_solver *s, size_t nrhs, const double *B,
                          double *X);

static double
norm_inf (size_t n, const double *x, size_t *imax)
{
  double m = 0;
  for (size_t i = 0; i < n; i++)
    if (fabs (x[i]) > m || x[i] != x[i])
      {
        m = fabs (x[i]);
        *imax = i;
      }
  return m;
}

/* rcond = 1 / (||A||_inf * est ||A^-1||_inf), the norm of the inverse from
 * two steps of inverse iteration x1 = A^-1 r, x2 = A^-1 (x1 / ||x1||) with a
 * pseudo-random r (a fixed sequence: results are reproducible).  The first
 * step finds the near-null direction whatever symmetry r might share with
 * it, the second measures 1/|lambda_min| along it. */
static int
rcond_check (lac_solver *s, const lac_csc *A)
{
  size_t n = s->n, imax = 0;
  double *w = lac_calloc (3 * n, sizeof *w), *x1 = w + n, *x2 = w + 2 * n;
  double anorm, ainv, nx1, nx2;
  unsigned long long seed = 0x9E3779B97F4A7C15ull;
  int status;
  if (!w)
    LAC_ERROR (LAC_ENOMEM, "condition estimate, n = %zu", n);
  for (size_t j = 0; j < n; j++)                 /* w_i = sum_j |A_ij| */
    for (int q = A->p[j]; q < A->p[j + 1]; q++)
      w[A->i[q]] += fabs (A->x[q]);
  anorm = norm_inf (n, w, &imax);
  for (size_t i = 0; i < n; i++)                 /* r_i in +-[0.5, 1.5) */
    {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      w[i] = (0.5 + (double) (seed >> 11) / 9007199254740992.0)
             * ((seed >> 10) & 1 ? 1 : -1);
    }
  status = solve_columns (s, 1, w, x1);          /* x1 = A^-1 r */
  nx1 = status ? 0 : norm_inf (n, x1, &imax);
  ainv = HUGE_VAL;                     /* stays so if x1 is not finite */
  if (!status && isfinite (nx1))
    {
      for (size_t i = 0; i < n; i++)
        w[i] = x1[i] / nx1;
      status = solve_columns (s, 1, w, x2);      /* x2 = A^-1 x1/||x1|| */
      nx2 = status ? 0 : norm_inf (n, x2, &imax);
      if (isfinite (nx2))
        ainv = fmax (nx1 / 1.5, nx2);            /* ||r||_inf < 1.5 */
    }
  lac_free (w);
  if (status)
    return status;
  s->info.rcond = 1 / (anorm * ainv);
  if (!(s->info.rcond >= LAC_RCOND_MIN))
    LAC_ERROR (LAC_ESING, "numerically singular matrix (%s): condition "
               "estimate %.3g > 1/LAC_RCOND_MIN = %.3g; the near-null vector "
               "is largest at dof %zu; is the body fixed against rigid "
               "motion?", kind_names[s->kind], 1 / s->info.rcond,
               1 / LAC_RCOND_MIN, imax);
  return LAC_SUCCESS;
}

/* ---- the interface ------------------------------------------------------ */

static int
factor (lac_solver *s, const lac_csc *A, int reuse)
{
  int status;
  unsigned long long hash = 0;
  if (!s || !A)
    LAC_ERROR (LAC_EINVAL, "no solver or no matrix");
  if (A->nrow != A->ncol)
    LAC_ERROR (LAC_EBADLEN, "matrix is %zu x %zu, not square", A->nrow,
               A->ncol);
  if (A->ncol == 0)
    LAC_ERROR (LAC_EINVAL, "empty matrix (n = 0)");
  if (reuse && s->kind != LAC_SOLVER_DENSE)
    {
      hash = lac_csc_pattern_hash (A);
      reuse = s->sym_n == A->ncol && s->sym_nnz_A == (size_t) A->p[A->ncol]
              && s->sym_hash == hash;
    }
  release (s, reuse);
  memset (&s->info, 0, sizeof s->info);
  s->n = A->ncol;
  s->info.n = A->ncol;
  switch (s->kind)
    {
    case LAC_SOLVER_DENSE: status = dense_factor (s, A); break;
    case LAC_SOLVER_UMFPACK: status = umf_factor (s, A); break;
    default: status = chol_factor (s, A); break;
    }
  s->factored = status == LAC_SUCCESS;
  if (!status)
    status = rcond_check (s, A);
  if (status)
    release (s, 0);          /* keep nothing half-made; the message stays */
  else if (s->kind != LAC_SOLVER_DENSE)
    {
      s->sym_n = A->ncol;
      s->sym_nnz_A = (size_t) A->p[A->ncol];
      s->sym_hash = hash ? hash : lac_csc_pattern_hash (A);
      s->info.analysis_reused = reuse;
    }
  return status;
}

int
lac_solver_factor (lac_solver *s, const lac_csc *A)
{
  return factor (s, A, 0);
}

int
lac_solver_refactor (lac_solver *s, const lac_csc *A)
{
  return factor (s, A, 1);
}

static int
solve_columns (lac_solver *s, size_t nrhs, const double *B, double *X)
{
  int status = LAC_SUCCESS;
  if (s->kind == LAC_SOLVER_CHOLMOD)
    return chol_solve (s, nrhs, B, X);
  for (size_t r = 0; r < nrhs && !status; r++)
    status = s->kind == LAC_SOLVER_DENSE
      ? dense_solve (s, B + r * s->n, X + r * s->n)
      : umf_solve (s, B + r * s->n, X + r * s->n);
  return status;
}

int
lac_solver_solve_many (lac_solver *s, size_t nrhs, const double *B,
                       double *X)
{
  if (!s || !s->factored)
    LAC_ERROR (LAC_EINVAL, "no factorization to solve with (call "
               "lac_solver_factor first, and check its status)");
  return solve_columns (s, nrhs, B, X);
}

int
lac_solver_solve (lac_solver *s, const double *b, double *x)
{
  return lac_solver_solve_many (s, 1, b, x);
}

int
lac_solver_halves (const lac_solver *s)
{
  return s && s->factored && s->kind == LAC_SOLVER_CHOLMOD && s->L
         && s->L->is_ll;
}

int
lac_solver_forward_many (lac_solver *s, size_t nrhs, const double *B,
                         double *Y)
{
  if (!lac_solver_halves (s))
    LAC_ERROR (LAC_EINVAL, "no Cholesky factor L L^T to solve in halves "
               "with (lac_solver_halves)");
  return chol_solve2 (s, CHOLMOD_P, CHOLMOD_L, nrhs, B, Y);  /* L^-1 P B */
}

int
lac_solver_backward (lac_solver *s, const double *y, double *x)
{
  if (!lac_solver_halves (s))
    LAC_ERROR (LAC_EINVAL, "no Cholesky factor L L^T to solve in halves "
               "with (lac_solver_halves)");
  return chol_solve2 (s, CHOLMOD_Lt, CHOLMOD_Pt, 1, y, x);  /* P^T L^-T y */
}

int
lac_solver_get_info (const lac_solver *s, lac_solver_info *info)
{
  if (!s || !s->factored)
    LAC_ERROR (LAC_EINVAL, "no factorization");
  *info = s->info;
  return LAC_SUCCESS;
}
