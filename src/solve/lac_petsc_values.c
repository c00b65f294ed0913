/* lac_petsc_values.c -- the petsc strategy's values for the statuses:
 *                       K_W = K / kappa, W_i = omega / s_i, the contact
 *                       terms C (W - W_old) C^T, B = -C_A and D
 *                       (see lac_petsc.h)                [chapter 13]
 *
 * The update command of lac_petsc.c: the root sends the statuses, every
 * process makes its own rows and columns of the matrices, new numbers
 * from its own cells (K checked against them first), and hands them to
 * the solvers (linalg/lac_petsc_saddle.h).
 */
#ifdef LAC_HAVE_PETSC

#include <math.h>
#include <string.h>
#include "base/lac_status.h"
#include "solve/lac_petsc_internal.h"

#define ASSEMBLY_TOL 1e-10    /* K x against its cells', of |K| |x|    */

/* ---- collective: the values for the statuses ---------------------------- */

static int
assemble (Mat M)
{
  TRY (MatAssemblyBegin (M, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (M, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* sum |v_j| in the order of the rows (the same sum on every run: not
 * the BLAS's, whose threads may cut it differently). */
static int
sum_abs (Vec v, double *sum)
{
  const PetscScalar *a;
  PetscInt m;
  double mine = 0;
  TRY (VecGetLocalSize (v, &m));
  TRY (VecGetArrayRead (v, &a));
  for (PetscInt j = 0; j < m; j++)
    mine += fabs (a[j]);
  TRY (VecRestoreArrayRead (v, &a));
  if (MPI_Allreduce (&mine, sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Allreduce of the diagonal's sum failed");
  return LAC_SUCCESS;
}

/* s_i = c_i^T diag(K)^-1 c_i (lac_system_column_scales' sums) from d =
 * diag(K), PETSc's: each process the entries of C in its own rows, then
 * the sum over the processes, so that every process has W. */
static int
column_scales (lac_petsc *s, Vec d)
{
  const lac_csc *C = lac_dist_c (s->dist);
  const int *row = lac_dist_row (s->dist);
  const PetscScalar *a;
  TRY (VecGetArrayRead (d, &a));
  for (size_t i = 0; i < s->k; i++)
    {
      s->s[i] = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        {
          PetscInt r = row ? row[C->i[p]] : C->i[p];
          double kjj = r >= s->r0 && r < s->r1 ? a[r - s->r0] : 0.0;
          if (kjj != 0)
            s->s[i] += C->x[p] * C->x[p] * (1 / fabs (kjj));
        }
    }
  TRY (VecRestoreArrayRead (d, &a));
  if (s->size > 1 && MPI_Allreduce (MPI_IN_PLACE, s->s, (int) s->k,
                                    MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Allreduce of the column scales failed");
  return LAC_SUCCESS;
}

/* K_W, K just assembled from the cells, against the cells' element
 * matrices (lac_dist_check_stiffness): the residuals of the root take K x
 * from K_W (petsc_kmul), so that they are the cells' K's. */
static int
check_assembly (lac_petsc *s)
{
  double err;
  int status = lac_dist_check_stiffness (s->dist, s->Kw, &err);
  if (status)
    return status;
  TRY (PetscInfo (s->Kw, "K against its cells: %.3g of |K| |x|\n", err));
  if (!(err <= ASSEMBLY_TOL))
    LAC_ERROR (LAC_ESANITY, "the stiffness PETSc assembled on %d "
               "process%s is not its cells' (|K x - sum_e K_e x| = %.2g of "
               "|K| |x| for a probe x): a fault of the distributed "
               "assembly; a direct strategy on one process does without it",
               s->size, s->size > 1 ? "es" : "", err);
  return LAC_SUCCESS;
}

/* New numbers: K_W = K (from the cells or the root's K) divided by kappa,
 * the mean of |K_jj|: the stiffness K_W and the forces f_W are handed to
 * PETSc divided by it (not with fieldsplit, whose GMRES weighs forces
 * against gaps: tuned as it is), so that PETSc sees the same numbers
 * whatever the units (its GAMG with the rigid motions is not
 * scale-invariant: with lengths and moduli scaled by powers of two, the
 * results changed in their last bits, which the projected CG amplifies to
 * 1e-9; chapter 13).  No contact term in it yet (wold = 0).  From K,
 * before the division, ||K||_inf for the root's residuals and the
 * column scales s of W. */
static int
new_stiffness (lac_petsc *s, const lac_contact_system *sys)
{
  double sum;
  int status;
  if (s->k && (status = lac_dist_set_c (s->dist, sys ? sys->C : NULL, 0)))
    return status;
  TRY (MatZeroEntries (s->Kw));
  if ((status = lac_dist_add_stiffness (s->dist, sys && !s->cells
                                        ? sys->K : NULL, s->Kw, 1.0))
      || (status = assemble (s->Kw))
      || (s->cells && (status = check_assembly (s))))
    return status;
  TRY (MatNorm (s->Kw, NORM_INFINITY, &s->knorm));
  TRY (MatGetDiagonal (s->Kw, s->ru));
  if ((status = sum_abs (s->ru, &sum))
      || (s->k && (status = column_scales (s, s->ru))))
    return status;
  s->kappa = s->mode == FIELDSPLIT || !(sum > 0) ? 1.0
             : sum / (double) s->n;
  TRY (MatScale (s->Kw, 1 / s->kappa));
  memset (s->wold, 0, (s->k ? s->k : 1) * sizeof *s->wold);
  return LAC_SUCCESS;
}

/* K_W += C (W - W_old) C^T / kappa: the columns whose weight changed. */
static int
contact_terms (lac_petsc *s)
{
  int status;
  for (size_t i = 0; i < s->k; i++)
    s->dw[i] = (s->w[i] - s->wold[i]) / s->kappa;
  status = lac_dist_add_contact (s->dist, s->Kw, s->dw);
  memcpy (s->wold, s->w, (s->k ? s->k : 1) * sizeof *s->wold);
  return status ? status : assemble (s->Kw);
}

/* B = -C_A (the inactive columns are zeros); D = 1 on the inactive, 0
 * on the active; with fieldsplit, its Schur preconditioner Sp = 1 on the
 * inactive, -1/w on the active (-S_W^-1 is about -W_A: the Schur
 * complement of (*W) is -S_W).  Each process its own columns and
 * multipliers. */
static int
multipliers (lac_petsc *s)
{
  int status;
  if ((status = lac_dist_set_b (s->dist, s->B, s->stat))
      || (status = assemble (s->B)))
    return status;
  for (PetscInt i = s->l0; i < s->l1; i++)
    {
      int on = s->stat[i] && s->w[i] > 0;
      TRY (VecSetValue (s->dk, i, on ? 0.0 : 1.0, INSERT_VALUES));
      if (s->mode == FIELDSPLIT)
        TRY (VecSetValue (s->pk, i, on ? -s->kappa / s->w[i] : 1.0,
                          INSERT_VALUES));
    }
  TRY (VecAssemblyBegin (s->dk));
  TRY (VecAssemblyEnd (s->dk));
  TRY (VecAssemblyBegin (s->pk));
  TRY (VecAssemblyEnd (s->pk));
  return LAC_SUCCESS;
}

/* W_i = omega / s_i on the active columns, 0 on the others. */
static void
weights (lac_petsc *s)
{
  for (size_t i = 0; i < s->k; i++)
    s->w[i] = s->stat[i] && s->s[i] > 0 ? s->omega / s->s[i] : 0.0;
}

/* The values (all processes; sys: the root's): the statuses from the
 * root, K_W (new numbers: from the cells) and W, B and the solvers. */
int
lac_petsc_update_values (lac_petsc *s, const lac_petsc_command *c,
               const lac_contact_system *sys)
{
  int status;
  if ((s->k && (status = lac_petsc_bcast (s->stat, s->k)))
      || (c->all && (status = new_stiffness (s, sys))))
    return status;
  weights (s);
  if ((status = contact_terms (s))
      || (s->k && (status = multipliers (s)))
      || (status = lac_petsc_saddle_update (s->sv, s->k ? s->dk : NULL,
                                            s->k ? s->pk : NULL)))
    return status;
  s->counts.factorizations++;
  return LAC_SUCCESS;
}

/* The root: the matrices for the statuses, when they or the numbers
 * changed. */
int
lac_petsc_update (lac_petsc *s, const char *active)
{
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_UPDATE,
                          .all = s->new_numbers };
  int status;
  if (!s->new_numbers && s->have_stat
      && (s->k == 0 || memcmp (active, s->stat, s->k) == 0))
    return LAC_SUCCESS;
  if (s->k)
    memcpy (s->stat, active, s->k);
  s->have_stat = 0;
  if ((status = lac_petsc_command_send (&c))
      || (status = lac_petsc_agree (lac_petsc_update_values (s, &c, s->sys))))
    return status;
  s->have_stat = 1;
  s->new_numbers = 0;
  return LAC_SUCCESS;
}

#else

typedef int lac_petsc_values_unused;    /* nothing without PETSc */

#endif /* LAC_HAVE_PETSC */
