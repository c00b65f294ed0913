/* lac_solver_estimate.c -- what a factorization would cost, without it
 *
 * lac_solver_estimate (lac_linalg.h) runs the symbolic analysis only --
 * the fill-reducing ordering and the counts of the factor -- so that a
 * caller (bench/bench_elasticity.c) can decide whether the numerical
 * factorization fits in memory before it starts: CHOLMOD's counts are
 * exact (cholmod_analyze), UMFPACK's are upper bounds (umfpack_symbolic),
 * dense is n^2.  The factorizations themselves are in lac_solver.c.
 */
#include "linalg/lac_linalg.h"

#include <string.h>
#include <cholmod.h>
#include <umfpack.h>
#include "base/lac_mem.h"
#include "linalg/lac_solver_internal.h"
#include "base/lac_status.h"

/* UMFPACK: umfpack_symbolic's upper-bound estimates. */
static int
umf_estimate (const lac_csc *A, lac_solver_info *e)
{
  size_t n = A->ncol, nnz = (size_t) A->p[n];
  ss_long *Ap = lac_malloc ((n + 1) * sizeof *Ap);
  ss_long *Ai = lac_malloc (nnz * sizeof *Ai);
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  void *symbolic = NULL;
  int st = UMFPACK_ERROR_out_of_memory;
  if (Ap && Ai)
    {
      for (size_t j = 0; j <= n; j++)
        Ap[j] = A->p[j];
      for (size_t q = 0; q < nnz; q++)
        Ai[q] = A->i[q];
      umfpack_dl_defaults (control);
      st = umfpack_dl_symbolic ((ss_long) n, (ss_long) n, Ap, Ai, NULL,
                                &symbolic, control, info);
      umfpack_dl_free_symbolic (&symbolic);
    }
  lac_free (Ap);
  lac_free (Ai);
  if (st != UMFPACK_OK)
    LAC_ERROR (st == UMFPACK_ERROR_out_of_memory ? LAC_ENOMEM : LAC_EDEP,
               "UMFPACK symbolic analysis failed with status %d", st);
  e->nnz_factor = info[UMFPACK_LNZ_ESTIMATE] + info[UMFPACK_UNZ_ESTIMATE]
                  - (double) n;
  e->flops = info[UMFPACK_FLOPS_ESTIMATE];
  e->peak_bytes = info[UMFPACK_PEAK_MEMORY_ESTIMATE]
                  * info[UMFPACK_SIZE_OF_UNIT];
  e->method = "LU (UMFPACK), estimate";
  e->ordering = "";
  return LAC_SUCCESS;
}

static int
chol_estimate (const lac_csc *A, lac_solver_info *e)
{
  cholmod_common cc;
  cholmod_sparse *C;
  cholmod_factor *L = NULL;
  int status = LAC_SUCCESS;
  if (!cholmod_l_start (&cc))
    LAC_ERROR (LAC_EDEP, "cholmod_l_start failed");
  cc.print = 0;
  C = lac_solver_upper_copy (A, CHOLMOD_PATTERN, &cc);
  if (C)
    L = cholmod_l_analyze (C, &cc);
  if (!C)
    status = LAC_ENOMEM;
  else if (!L)
    status = LAC_ERRMSG (cc.status == CHOLMOD_OUT_OF_MEMORY ? LAC_ENOMEM
                         : LAC_EDEP, "CHOLMOD analyze failed with status %d",
                         cc.status);
  else
    {
      double xs = L->is_super ? (double) L->xsize : cc.lnz;
      e->nnz_factor = cc.lnz;
      e->flops = cc.fl;
      e->peak_bytes = 8.0 * (xs + (double) (L->is_super ? L->ssize : 0));
      e->method = L->is_super ? "supernodal LL' (CHOLMOD), estimate"
                              : "simplicial (CHOLMOD), estimate";
      e->ordering = lac_solver_chol_ordering (L->ordering);
    }
  cholmod_l_free_factor (&L, &cc);
  cholmod_l_free_sparse (&C, &cc);
  cholmod_l_finish (&cc);
  return status;
}

int
lac_solver_estimate (lac_solver_kind kind, const lac_csc *A,
                     lac_solver_info *info)
{
  double n;
  if (!A || !info)
    LAC_ERROR (LAC_EINVAL, "no matrix or no info");
  if (A->nrow != A->ncol || A->ncol == 0)
    LAC_ERROR (LAC_EBADLEN, "matrix is %zu x %zu, not square and non-empty",
               A->nrow, A->ncol);
  memset (info, 0, sizeof *info);
  info->n = A->ncol;
  n = (double) A->ncol;
  switch (kind)
    {
    case LAC_SOLVER_DENSE:
      info->nnz_factor = n * n;
      info->peak_bytes = 8 * n * n;
      info->flops = 2.0 / 3.0 * n * n * n;
      info->method = "LU, partial pivoting, estimate";
      info->ordering = "";
      return LAC_SUCCESS;
    case LAC_SOLVER_UMFPACK:
      return umf_estimate (A, info);
    case LAC_SOLVER_CHOLMOD:
      return chol_estimate (A, info);
    default:
      LAC_ERROR (LAC_EINVAL, "unknown solver kind %d", (int) kind);
    }
}
