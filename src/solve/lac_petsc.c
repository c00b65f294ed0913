/* lac_petsc.c -- the LAC system by Krylov methods and algebraic multigrid
 *                (see lac_petsc.h)                [LAC (17), Alg. 1 l. 21]
 *
 * The root (process 0) runs Algorithm 1; every step that involves PETSc
 * is a collective one, which the root starts by a command
 * (linalg/lac_petsc_env.h) and the other processes follow in
 * lac_petsc_serve, with the same functions and none of the root's data:
 *
 *   build   the rows and the assembly of fem/lac_assembly_dist.h (the
 *           cells partitioned by PETSc, C on every process), K_W and
 *           B = -C_A (n x k) preallocated from the own cells and columns,
 *           the near-null space, the solvers (projected: the multigrid
 *           of K_W, CG on P K_W; fieldsplit: the nest [K_W B; B^T D],
 *           GMRES);
 *   update  the statuses and W from the root; new numbers: K_W = K /
 *           kappa from the own cells; then K_W += C (W - W_old) C^T /
 *           kappa by the owners of the columns that changed; B; then
 *           B^T B + D (projected) or D and the Schur preconditioner Sp
 *           (fieldsplit), D = 1 on the inactive;
 *   solve   the right-hand side and the start from the root, one Krylov
 *           solve, its true residual, the solution back to the root.
 *
 * A failure on one process is agreed on by all before the next
 * collective call (lac_petsc_agree): the root returns it with the message
 * of the process that failed.  PETSc's errors become LAC_EDEP with
 * PETSc's message.
 */
#include "solve/lac_petsc.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

#ifndef LAC_HAVE_PETSC

/* ---- built without PETSc: the interface, failing with the install line */

#define NO_PETSC(func) lac_error_set (LAC_EDEP, func, "lac was built " \
  "without PETSc (the petsc strategy, MPI); install it with: %s", \
  LAC_PETSC_INSTALL)

int
lac_petsc_serve (void)
{
  return NO_PETSC (__func__);
}

/* The only operation: the others are never reached. */
static void *
petsc_alloc (void)
{
  NO_PETSC (__func__);
  return NULL;
}

const lac_strategy_ops lac_petsc_ops = { .alloc = petsc_alloc };

#else /* LAC_HAVE_PETSC */

#include <petscksp.h>
#include "fem/lac_assembly_dist.h"

_Static_assert (sizeof (PetscInt) == sizeof (int), "lac_csc's int indices "
                "are handed to PETSc: a PETSc with 32-bit indices");
_Static_assert (sizeof (PetscScalar) == sizeof (double), "real PETSc");

#define KSP_MAXIT 2000        /* Krylov iterations at most per solve     */
#define CORRECTION_RTOL 1e-6  /* fieldsplit: of its correction step      */

enum { PROJECTED, FIELDSPLIT };   /* the contact solvers (-lac_contact)  */

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

typedef struct lac_petsc
{
  double omega;                    /* W_i = omega / s_i                   */
  int rank, size, root;            /* root: rank 0                        */
  size_t n, k;
  int mode, coords_given, built, cells;   /* cells: K from the cells     */
  PetscInt bs, r0, r1, l0, l1;     /* block size; own rows of U, lambda   */
  lac_dist *dist;                  /* owned: the rows, the cells, C       */
  /* the root's: the whole system */
  const lac_contact_system *sys;   /* borrowed                            */
  const lac_dist_source *src;      /* borrowed: the cells of K, or NULL   */
  int dim;                         /* components per node (coordinates)   */
  const double *coords;            /* borrowed, n, or NULL                */
  unsigned long long hK, hC;       /* patterns the matrices were made for */
  double *s;                       /* owned, k: c_i^T diag(K)^-1 c_i      */
  int have_stat, new_numbers;
  double *xv;                      /* owned, n: scratch                   */
  size_t na, *idx;                 /* owned, k: the active multipliers    */
  double *rhs, *lst;               /* owned, k                            */
  /* every process */
  double *w, *wold, *dw;           /* owned, k: W, the W in K_W, change   */
  char *stat;                      /* owned, k: statuses of the matrices  */
  double kappa;                    /* the mean of diag(K): PETSc's K_W and
                                      f_W are divided by it              */
  Mat Kw, B;                       /* K_W; B = -C_A (n x k)               */
  Mat G, Ah;                       /* projected: B^T B + D; P K_W (shell) */
  Mat Bt, D, Sp, A;                /* fieldsplit: A = [K_W B; B^T D]      */
  KSP ku, kp, kg, ks;              /* K_W alone; projected CG, G; (*W)    */
  PC pg;                           /* projected: the multigrid of K_W     */
  Vec bu, xu, ru, tu, u0, fw;      /* U's layout                          */
  Vec tk, sk, dk, gk;              /* the multipliers' layout             */
  Vec b, x, r, dx;                 /* fieldsplit: (*W)                    */
  Vec useq, lseq;                  /* U, lambda whole on the root (empty
                                      elsewhere)                          */
  VecScatter gu, gl;               /* root -> distributed (forward)       */
  Mat Bl, Gl;                      /* projected, N > 1: the own rows of
                                      B (k columns), a copy of G          */
  KSP kl;                          /*   its LU (prefix gram_local_)       */
  Vec vl, ul, tl, tg, sl;          /*   their vectors (own rows; k)       */
  lac_solve_counts counts;
  char method[200];
} lac_petsc;

/* ---- the object --------------------------------------------------------- */

static void *
petsc_alloc (void)
{
  lac_petsc *s;
  PetscBool set = PETSC_FALSE;
  char mode[32] = "";
  if (lac_petsc_initialize (NULL))
    return NULL;
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR_NULL (LAC_ENOMEM, "petsc strategy");
  s->omega = LAC_PETSC_OMEGA;
  PetscOptionsGetReal (NULL, NULL, "-lac_omega", &s->omega, NULL);
  PetscOptionsGetString (NULL, NULL, "-lac_contact", mode, sizeof mode,
                         &set);
  s->mode = set && strcmp (mode, "fieldsplit") == 0 ? FIELDSPLIT : PROJECTED;
  if ((set && s->mode == PROJECTED && strcmp (mode, "projected") != 0)
      || !(s->omega > 0))
    {
      lac_error_set (LAC_EINVAL, __func__, "-lac_contact %s, -lac_omega %g: "
                     "expected projected or fieldsplit, and omega > 0",
                     mode, s->omega);
      lac_free (s);
      return NULL;
    }
  lac_petsc_rank (&s->rank, &s->size);
  s->root = s->rank == 0;
  return s;
}

#define COUNT(a) (sizeof (a) / sizeof *(a))

static void
free_petsc (lac_petsc *s)
{
  KSP *ksp[] = { &s->ku, &s->kp, &s->kg, &s->ks, &s->kl };
  Mat *mat[] = { &s->G, &s->Ah, &s->A, &s->Bt, &s->B, &s->D, &s->Sp, &s->Kw,
                 &s->Bl, &s->Gl };
  Vec *vec[] = { &s->bu, &s->xu, &s->ru, &s->tu, &s->u0, &s->fw, &s->tk,
                 &s->sk, &s->dk, &s->gk, &s->b, &s->x, &s->r, &s->dx,
                 &s->useq, &s->lseq, &s->vl, &s->ul, &s->tl, &s->tg,
                 &s->sl };
  for (size_t i = 0; i < COUNT (ksp); i++)
    KSPDestroy (ksp[i]);
  PCDestroy (&s->pg);
  for (size_t i = 0; i < COUNT (mat); i++)
    MatDestroy (mat[i]);
  for (size_t i = 0; i < COUNT (vec); i++)
    VecDestroy (vec[i]);
  VecScatterDestroy (&s->gu);
  VecScatterDestroy (&s->gl);
  lac_dist_free (s->dist);
  s->dist = NULL;
  s->built = 0;
}

static void
free_arrays (lac_petsc *s)
{
  double **d[] = { &s->s, &s->xv, &s->rhs, &s->lst, &s->w, &s->wold,
                   &s->dw };
  for (size_t i = 0; i < COUNT (d); i++)
    {
      lac_free (*d[i]);
      *d[i] = NULL;
    }
  lac_free (s->idx);
  lac_free (s->stat);
  s->idx = NULL;
  s->stat = NULL;
  s->have_stat = 0;
}

static void
petsc_free (void *w)
{
  lac_petsc *s = w;
  if (!s)
    return;
  if (s->root && s->built && s->size > 1)
    {
      lac_petsc_command c = { .cmd = LAC_PETSC_CMD_FREE };
      lac_petsc_command_send (&c);
    }
  free_petsc (s);
  free_arrays (s);
  lac_free (s);
}

static void
petsc_set_coordinates (void *w, int dim, const double *x)
{
  lac_petsc *s = w;
  s->dim = dim;
  s->coords = x;
}

static void
petsc_get_counts (const void *w, lac_solve_counts *c)
{
  const lac_petsc *s = w;
  *c = s->counts;
  c->processes = s->size;
}

static const char *
petsc_method (const void *w)
{
  const lac_petsc *s = w;
  return s->method[0] ? s->method : "petsc (not set)";
}

/* ---- layout ------------------------------------------------------------- */

/* Multipliers [a, b) on process p: PETSc's split of k in N ranges. */
static void
l_range (const lac_petsc *s, int p, PetscInt *a, PetscInt *b)
{
  PetscInt k = (PetscInt) s->k, q = k / s->size, r = k % s->size;
  *a = p * q + (p < r ? p : r);
  *b = *a + q + (p < r);
}

/* The root's arrays for a new pattern. */
static int
alloc_arrays (lac_petsc *s, size_t n, size_t k)
{
  size_t k1 = k ? k : 1;
  free_arrays (s);
  s->s = lac_calloc (k1, sizeof *s->s);
  s->idx = lac_malloc (k1 * sizeof *s->idx);
  s->rhs = lac_malloc (k1 * sizeof *s->rhs);
  s->lst = lac_malloc (k1 * sizeof *s->lst);
  s->xv = lac_malloc (n * sizeof *s->xv);
  if (!s->s || !s->idx || !s->rhs || !s->lst || !s->xv)
    LAC_ERROR (LAC_ENOMEM, "petsc strategy, n = %zu, k = %zu", n, k);
  return LAC_SUCCESS;
}

/* Every process: the statuses, W and the W of K_W now (k each). */
static int
alloc_weights (lac_petsc *s)
{
  size_t k1 = s->k ? s->k : 1;
  lac_free (s->w);
  lac_free (s->wold);
  lac_free (s->dw);
  lac_free (s->stat);
  s->w = lac_calloc (k1, sizeof *s->w);
  s->wold = lac_calloc (k1, sizeof *s->wold);
  s->dw = lac_calloc (k1, sizeof *s->dw);
  s->stat = lac_calloc (k1, 1);
  if (!s->w || !s->wold || !s->dw || !s->stat)
    return LAC_ERRMSG (LAC_ENOMEM, "the weights of %zu multipliers", s->k);
  return LAC_SUCCESS;
}

/* A preallocator of the own rows of U, columns of U (lam = 0) or of the
 * multipliers (lam = 1). */
static int
preallocator (lac_petsc *s, int lam, Mat *P)
{
  PetscInt nl = s->r1 - s->r0;
  TRY (MatCreate (PETSC_COMM_WORLD, P));
  TRY (MatSetType (*P, MATPREALLOCATOR));
  TRY (MatSetSizes (*P, nl, lam ? s->l1 - s->l0 : nl, (PetscInt) s->n,
                    lam ? (PetscInt) s->k : (PetscInt) s->n));
  TRY (MatSetBlockSize (*P, lam ? 1 : s->bs));
  TRY (MatSetUp (*P));
  return LAC_SUCCESS;
}

/* M of the sizes of P with P's pattern. */
static int
create_from (lac_petsc *s, Mat P, int lam, Mat *M)
{
  PetscInt m, n, M0, N0;
  TRY (MatGetLocalSize (P, &m, &n));
  TRY (MatGetSize (P, &M0, &N0));
  TRY (MatCreate (PETSC_COMM_WORLD, M));
  TRY (MatSetSizes (*M, m, n, M0, N0));
  TRY (MatSetType (*M, MATAIJ));
  TRY (MatSetBlockSize (*M, lam ? 1 : s->bs));
  TRY (MatPreallocatorPreallocate (P, PETSC_TRUE, *M));
  return LAC_SUCCESS;
}

/* K_W and B (k > 0), preallocated from the own cells and columns
 * (fem/lac_assembly_dist.h); K: the root's when it gives K whole. */
static int
create_matrices (lac_petsc *s, const lac_csc *K)
{
  Mat P[2] = { NULL, NULL };
  int status;
  if ((status = preallocator (s, 0, &P[0]))
      || (s->k && (status = preallocator (s, 1, &P[1])))
      || (status = lac_dist_pattern (s->dist, K, P[0], P[1]))
      || (status = create_from (s, P[0], 0, &s->Kw))
      || (s->k && (status = create_from (s, P[1], 1, &s->B))))
    {
      MatDestroy (&P[0]);
      MatDestroy (&P[1]);
      return status;
    }
  TRY (MatDestroy (&P[0]));
  TRY (MatDestroy (&P[1]));
  return LAC_SUCCESS;
}

/* The scatter sc between the root's whole vector *seq (empty elsewhere)
 * and v: forward to v, entry j to row[j] (row NULL: j). */
static int
root_scatter (const lac_petsc *s, Vec v, const PetscInt *row, VecScatter *sc,
              Vec *seq)
{
  PetscInt n;
  IS ix, iy;
  TRY (VecGetSize (v, &n));
  n = s->root ? n : 0;
  TRY (VecCreateSeq (PETSC_COMM_SELF, n, seq));
  TRY (ISCreateStride (PETSC_COMM_SELF, n, 0, 1, &ix));
  if (row)
    TRY (ISCreateGeneral (PETSC_COMM_SELF, n, row, PETSC_COPY_VALUES, &iy));
  else
    TRY (ISCreateStride (PETSC_COMM_SELF, n, 0, 1, &iy));
  TRY (VecScatterCreate (*seq, ix, v, iy, sc));
  TRY (ISDestroy (&ix));
  TRY (ISDestroy (&iy));
  return LAC_SUCCESS;
}


/* v (distributed) = the root's x (ignored elsewhere), through the seq
 * vector of the root and the scatter sc (reversed). */
static int
to_dist (const lac_petsc *s, VecScatter sc, Vec seq, const double *x,
         Vec v)
{
  if (s->root)
    {
      PetscScalar *a;
      PetscInt len;
      TRY (VecGetLocalSize (seq, &len));
      TRY (VecGetArray (seq, &a));
      memcpy (a, x, (size_t) len * sizeof *a);
      TRY (VecRestoreArray (seq, &a));
    }
  TRY (VecScatterBegin (sc, seq, v, INSERT_VALUES, SCATTER_FORWARD));
  TRY (VecScatterEnd (sc, seq, v, INSERT_VALUES, SCATTER_FORWARD));
  return LAC_SUCCESS;
}

/* The root's y = the distributed v (nothing copied elsewhere). */
static int
to_root (const lac_petsc *s, VecScatter sc, Vec v, Vec seq, double *y)
{
  TRY (VecScatterBegin (sc, v, seq, INSERT_VALUES, SCATTER_REVERSE));
  TRY (VecScatterEnd (sc, v, seq, INSERT_VALUES, SCATTER_REVERSE));
  if (s->root)
    {
      const PetscScalar *a;
      PetscInt len;
      TRY (VecGetLocalSize (seq, &len));
      TRY (VecGetArrayRead (seq, &a));
      memcpy (y, a, (size_t) len * sizeof *y);
      TRY (VecRestoreArrayRead (seq, &a));
    }
  return LAC_SUCCESS;
}

/* The root: its nodal coordinates centred on their mean and divided by
 * their largest distance from it, into xv (n): the rigid motions made of
 * them do not depend on where the origin lies nor on the unit of length. */
static const double *
unit_coordinates (lac_petsc *s)
{
  size_t dim = (size_t) s->bs, nn = s->n / dim;
  double c[3] = { 0, 0, 0 }, r = 0;
  for (size_t j = 0; j < s->n; j++)
    c[j % dim] += s->coords[j] / (double) nn;
  for (size_t j = 0; j < s->n; j++)
    r = fmax (r, fabs (s->coords[j] - c[j % dim]));
  for (size_t j = 0; j < s->n; j++)
    s->xv[j] = (s->coords[j] - c[j % dim]) / (r > 0 ? r : 1.0);
  return s->xv;
}

/* The rigid motions of the nodal coordinates as K_W's near-null space. */
static int
near_null_space (lac_petsc *s)
{
  Vec xc;
  MatNullSpace nsp;
  int status;
  if (!s->coords_given)
    return LAC_SUCCESS;
  TRY (VecDuplicate (s->xu, &xc));
  if ((status = to_dist (s, s->gu, s->useq, s->root ? unit_coordinates (s)
                         : NULL, xc)))
    return status;
  TRY (MatNullSpaceCreateRigidBody (xc, &nsp));
  TRY (MatSetNearNullSpace (s->Kw, nsp));
  TRY (MatNullSpaceDestroy (&nsp));
  TRY (VecDestroy (&xc));
  return LAC_SUCCESS;
}

/* ---- collective: build, the solvers --------------------------------------- */

/* k x k diagonal matrix of the multipliers' layout (zeros). */
static int
create_diagonal (lac_petsc *s, Mat *M)
{
  PetscInt kl = s->l1 - s->l0, k = (PetscInt) s->k;
  TRY (MatCreateAIJ (PETSC_COMM_WORLD, kl, kl, k, k, 1, NULL, 0, NULL, M));
  for (PetscInt i = s->l0; i < s->l1; i++)
    TRY (MatSetValue (*M, i, i, 0.0, INSERT_VALUES));
  TRY (MatAssemblyBegin (*M, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (*M, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* An option's default value, unless the user set it. */
static int
default_option (const char *name, const char *value)
{
  PetscBool set = PETSC_FALSE;
  TRY (PetscOptionsHasName (NULL, NULL, name, &set));
  if (!set)
    TRY (PetscOptionsSetValue (NULL, name, value));
  return LAC_SUCCESS;
}

/* Conjugate gradients and GAMG on K_W alone (k = 0; prefix elast_). */
static int
create_ku (lac_petsc *s)
{
  PC pc;
  TRY (KSPCreate (PETSC_COMM_WORLD, &s->ku));
  TRY (KSPSetOptionsPrefix (s->ku, "elast_"));
  TRY (KSPSetOperators (s->ku, s->Kw, s->Kw));
  TRY (KSPSetType (s->ku, KSPCG));
  TRY (KSPSetNormType (s->ku, KSP_NORM_UNPRECONDITIONED));
  TRY (KSPGetPC (s->ku, &pc));
  TRY (PCSetType (pc, PCGAMG));
  TRY (PCGAMGSetReuseInterpolation (pc, PETSC_TRUE));
  TRY (KSPSetFromOptions (s->ku));
  return LAC_SUCCESS;
}

/* v = P v = v - B (B^T B + D)^-1 B^T v: v without its part in the range
 * of C_A (l2-orthogonal projection on the null space of C_A^T). */
static PetscErrorCode
project_local (lac_petsc *s, Vec v);

static PetscErrorCode
project (lac_petsc *s, Vec v)
{
  if (s->kl)
    return project_local (s, v);
  PetscCall (MatMultTranspose (s->B, v, s->tk));
  PetscCall (KSPSolve (s->kg, s->tk, s->sk));
  PetscCall (MatMult (s->B, s->sk, s->tu));
  PetscCall (VecAXPY (v, -1.0, s->tu));
  return 0;
}

/* The same on N > 1 processes with one reduction: each process makes
 * B_own^T v_own from its rows, one MPI_Allreduce sums them, each solves
 * with its own copy of G and subtracts B_own s from its rows (instead of
 * the scatters of B^T v, of PCREDUNDANT and of B s: fewer waits for the
 * other processes, twice per CG iteration). */
static PetscErrorCode
project_local (lac_petsc *s, Vec v)
{
  PetscScalar *a, *g;
  const PetscScalar *t;
  PetscCall (VecGetArray (v, &a));
  PetscCall (VecPlaceArray (s->vl, a));
  PetscCall (MatMultTranspose (s->Bl, s->vl, s->tl));
  PetscCall (VecGetArrayRead (s->tl, &t));
  PetscCall (VecGetArray (s->tg, &g));
  PetscCallMPI (MPI_Allreduce (t, g, (int) s->k, MPIU_SCALAR, MPIU_SUM,
                               PETSC_COMM_WORLD));
  PetscCall (VecRestoreArray (s->tg, &g));
  PetscCall (VecRestoreArrayRead (s->tl, &t));
  PetscCall (KSPSolve (s->kl, s->tg, s->sl));
  PetscCall (MatMult (s->Bl, s->sl, s->ul));
  PetscCall (VecAXPY (s->vl, -1.0, s->ul));
  PetscCall (VecResetArray (s->vl));
  PetscCall (VecRestoreArray (v, &a));
  return 0;
}

/* N > 1: the own rows of B and a copy of G on every process, G's LU
 * there (after each new G). */
static int
update_local (lac_petsc *s)
{
  PC pc;
  PetscInt nl = s->r1 - s->r0;
  TRY (MatMPIAIJGetLocalMat (s->B, s->Bl ? MAT_REUSE_MATRIX
                             : MAT_INITIAL_MATRIX, &s->Bl));
  TRY (MatCreateRedundantMatrix (s->G, s->size, MPI_COMM_NULL, s->Gl
                                 ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX,
                                 &s->Gl));
  if (!s->kl)
    {
      TRY (KSPCreate (PetscObjectComm ((PetscObject) s->Gl), &s->kl));
      TRY (KSPSetOptionsPrefix (s->kl, "gram_local_"));
      TRY (KSPSetType (s->kl, KSPPREONLY));
      TRY (KSPGetPC (s->kl, &pc));
      TRY (PCSetType (pc, PCLU));
      TRY (KSPSetFromOptions (s->kl));
      TRY (MatCreateVecs (s->Gl, &s->sl, &s->tg));
      TRY (VecCreateSeqWithArray (PETSC_COMM_SELF, 1, nl, NULL, &s->vl));
      TRY (VecCreateSeq (PETSC_COMM_SELF, nl, &s->ul));
      TRY (VecCreateSeq (PETSC_COMM_SELF, (PetscInt) s->k, &s->tl));
    }
  TRY (KSPSetOperators (s->kl, s->Gl, s->Gl));
  return LAC_SUCCESS;
}

/* The operator of the projected CG: y = P K_W x. */
static PetscErrorCode
projected_op (Mat A, Vec x, Vec y)
{
  lac_petsc *s;
  PetscCall (MatShellGetContext (A, &s));
  PetscCall (MatMult (s->Kw, x, y));
  return project (s, y);
}

/* Its preconditioner: z = P M r, M one V-cycle of multigrid on K_W. */
static PetscErrorCode
projected_pc (PC pc, Vec r, Vec z)
{
  lac_petsc *s;
  PetscCall (PCShellGetContext (pc, &s));
  PetscCall (PCApply (s->pg, r, z));
  return project (s, z);
}

/* projected: the multigrid of K_W (prefix elast_), the solver of B^T B + D
 * (prefix gram_: redundant LU), CG on P K_W (no prefix). */
static int
create_projected (lac_petsc *s)
{
  PetscInt nl = s->r1 - s->r0;
  PC pc;
  TRY (PCCreate (PETSC_COMM_WORLD, &s->pg));
  TRY (PCSetOptionsPrefix (s->pg, "elast_"));
  TRY (PCSetOperators (s->pg, s->Kw, s->Kw));
  TRY (PCSetType (s->pg, PCGAMG));
  TRY (PCGAMGSetReuseInterpolation (s->pg, PETSC_TRUE));
  TRY (PCSetFromOptions (s->pg));
  TRY (KSPCreate (PETSC_COMM_WORLD, &s->kg));
  TRY (KSPSetOptionsPrefix (s->kg, "gram_"));
  TRY (KSPSetType (s->kg, KSPPREONLY));
  TRY (KSPGetPC (s->kg, &pc));
  TRY (PCSetType (pc, PCREDUNDANT));
  TRY (KSPSetFromOptions (s->kg));
  TRY (MatCreateShell (PETSC_COMM_WORLD, nl, nl, (PetscInt) s->n,
                       (PetscInt) s->n, s, &s->Ah));
  TRY (MatShellSetOperation (s->Ah, MATOP_MULT, (void (*) (void))
                             projected_op));
  TRY (KSPCreate (PETSC_COMM_WORLD, &s->kp));
  TRY (KSPSetOperators (s->kp, s->Ah, s->Ah));
  TRY (KSPSetType (s->kp, KSPCG));
  TRY (KSPSetNormType (s->kp, KSP_NORM_UNPRECONDITIONED));
  TRY (KSPSetFromOptions (s->kp));
  TRY (KSPGetPC (s->kp, &pc));
  TRY (PCSetType (pc, PCSHELL));
  TRY (PCShellSetContext (pc, s));
  TRY (PCShellSetApply (pc, projected_pc));
  TRY (MatCreateVecs (s->B, &s->sk, NULL));
  TRY (VecDuplicate (s->sk, &s->tk));
  TRY (VecDuplicate (s->sk, &s->dk));
  TRY (VecDuplicate (s->sk, &s->gk));
  TRY (VecDuplicate (s->xu, &s->tu));
  TRY (VecDuplicate (s->xu, &s->u0));
  TRY (VecDuplicate (s->xu, &s->fw));
  return root_scatter (s, s->sk, NULL, &s->gl, &s->lseq);
}

/* fieldsplit: the nest A = [K_W B; B^T D], its vectors, the Schur
 * preconditioner Sp, and GMRES with the Schur factorization of
 * PCFIELDSPLIT (no prefix; blocks fieldsplit_u_, fieldsplit_lambda_). */
static int
create_fieldsplit (lac_petsc *s)
{
  Mat blocks[4];
  Vec xl;
  PC pc;
  IS is[2];
  int status;
  if ((status = create_diagonal (s, &s->D))
      || (status = create_diagonal (s, &s->Sp))
      || (status = default_option ("-fieldsplit_u_ksp_type", "preonly"))
      || (status = default_option ("-fieldsplit_u_pc_type", "gamg"))
      || (status = default_option ("-fieldsplit_u_pc_gamg_reuse_interpolation",
                                   "true"))
      || (status = default_option ("-fieldsplit_lambda_ksp_type", "preonly"))
      || (status = default_option ("-fieldsplit_lambda_pc_type", "jacobi")))
    return status;
  TRY (MatCreateTranspose (s->B, &s->Bt));
  blocks[0] = s->Kw, blocks[1] = s->B, blocks[2] = s->Bt, blocks[3] = s->D;
  TRY (MatCreateNest (PETSC_COMM_WORLD, 2, NULL, 2, NULL, blocks, &s->A));
  TRY (MatCreateVecs (s->A, &s->x, &s->b));
  TRY (VecDuplicate (s->b, &s->r));
  TRY (VecDuplicate (s->b, &s->dx));
  TRY (MatCreateVecs (s->D, &xl, NULL));
  if ((status = root_scatter (s, xl, NULL, &s->gl, &s->lseq)))
    return status;
  TRY (VecDestroy (&xl));
  TRY (KSPCreate (PETSC_COMM_WORLD, &s->ks));
  TRY (KSPSetOperators (s->ks, s->A, s->A));
  TRY (KSPSetType (s->ks, KSPGMRES));
  TRY (KSPGMRESSetRestart (s->ks, 100));
  TRY (KSPSetPCSide (s->ks, PC_RIGHT));
  TRY (KSPSetNormType (s->ks, KSP_NORM_UNPRECONDITIONED));
  TRY (KSPGetPC (s->ks, &pc));
  TRY (PCSetType (pc, PCFIELDSPLIT));
  TRY (MatNestGetISs (s->A, is, NULL));
  TRY (PCFieldSplitSetIS (pc, "u", is[0]));
  TRY (PCFieldSplitSetIS (pc, "lambda", is[1]));
  TRY (PCFieldSplitSetType (pc, PC_COMPOSITE_SCHUR));
  TRY (PCFieldSplitSetSchurFactType (pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER));
  TRY (PCFieldSplitSetSchurPre (pc, PC_FIELDSPLIT_SCHUR_PRE_USER, s->Sp));
  TRY (KSPSetFromOptions (s->ks));
  return LAC_SUCCESS;
}

/* "cg + gamg on K, 2 processes" from the solvers. */
static int
describe (lac_petsc *s)
{
  KSPType kt;
  PCType pt;
  PC pc;
  char inner[32] = "gamg";
  PetscBool set;
  const char *es = s->size > 1 ? "es" : "";
  if (s->ks)
    {
      TRY (KSPGetType (s->ks, &kt));
      TRY (PetscOptionsGetString (NULL, NULL, "-fieldsplit_u_pc_type", inner,
                                  sizeof inner, &set));
      snprintf (s->method, sizeof s->method, "%s + fieldsplit(%s, W) on "
                "(*W), %d process%s", kt, inner, s->size, es);
      return LAC_SUCCESS;
    }
  TRY (KSPGetType (s->kp ? s->kp : s->ku, &kt));
  if (s->pg)
    pc = s->pg;
  else
    TRY (KSPGetPC (s->ku, &pc));
  TRY (PCGetType (pc, &pt));
  snprintf (s->method, sizeof s->method, s->kp ? "projected %s + %s on "
            "K_W, %d process%s" : "%s + %s on K, %d process%s", kt, pt,
            s->size, es);
  return LAC_SUCCESS;
}

/* The layout and C: the rows of the cells (the root gives its mesh when
 * c->cells) or of K, C on every process (fem/lac_assembly_dist.h). */
static int
build_layout (lac_petsc *s, const lac_petsc_command *c, const lac_csc *C)
{
  int status;
  lac_dist_free (s->dist);
  s->dist = NULL;
  if ((status = lac_dist_alloc (s->root && c->cells ? s->src : NULL, s->n,
                                (int) s->bs, &s->dist))
      || (s->k && (status = lac_dist_set_c (s->dist, C, 1))))
    return status;
  lac_dist_rows (s->dist, &s->r0, &s->r1);
  l_range (s, s->rank, &s->l0, &s->l1);
  return lac_petsc_agree (alloc_weights (s));
}

/* Everything that depends on the sizes and patterns (all processes; sys:
 * the root's, NULL elsewhere). */
static int
build (lac_petsc *s, const lac_petsc_command *c, const lac_contact_system *sys)
{
  int status;
  free_petsc (s);
  s->n = (size_t) c->n;
  s->k = (size_t) c->k;
  s->bs = c->bs;
  s->mode = c->mode;
  s->coords_given = c->coords;
  s->cells = c->cells;
  if ((status = build_layout (s, c, sys ? sys->C : NULL))
      || (status = create_matrices (s, sys && !c->cells ? sys->K : NULL)))
    return status;
  TRY (MatSetOption (s->Kw, MAT_SYMMETRIC, PETSC_TRUE));
  TRY (MatSetOption (s->Kw, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  TRY (MatCreateVecs (s->Kw, &s->xu, &s->bu));
  TRY (VecDuplicate (s->bu, &s->ru));
  if ((status = root_scatter (s, s->xu, lac_dist_row (s->dist), &s->gu,
                              &s->useq))
      || (status = near_null_space (s)))
    return status;
  if (s->k == 0)
    status = create_ku (s);
  else
    status = s->mode == FIELDSPLIT ? create_fieldsplit (s)
             : create_projected (s);
  if (status)
    return status;
  s->built = 1;
  s->counts.analyses++;
  return describe (s);
}

/* The root: the command of a new pattern; K from the cells when a mesh of
 * these dofs was given (set_mesh). */
static int
root_build (lac_petsc *s, const lac_contact_system *sys)
{
  size_t n = sys->K->ncol, k = sys->C ? sys->C->ncol : 0;
  size_t bs = s->dim > 0 && n % (size_t) s->dim == 0 ? (size_t) s->dim : 1;
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_BUILD, .mode = s->mode,
    .bs = (int) bs, .coords = s->coords && s->dim >= 2 && (int) bs == s->dim,
    .n = (long long) n, .k = (long long) k,
    .cells = s->src && s->src->mesh && (size_t) s->src->mesh->dim
             * s->src->mesh->nnodes == n && (int) bs == s->src->mesh->dim };
  int status;
  if ((status = alloc_arrays (s, n, k))
      || (status = lac_petsc_command_send (&c)))
    return status;
  return build (s, &c, sys);
}

static int
petsc_set (void *w, const lac_contact_system *sys)
{
  lac_petsc *s = w;
  unsigned long long hK = lac_csc_pattern_hash (sys->K);
  unsigned long long hC = sys->C ? lac_csc_pattern_hash (sys->C) : 0;
  size_t k = sys->C ? sys->C->ncol : 0;
  int status;
  if (!s->root)
    LAC_ERROR (LAC_ESANITY, "process %d: only the root sets a system",
               s->rank);
  if (sys->K->ncol != sys->K->nrow || (sys->C && sys->C->nrow != sys->K->ncol))
    LAC_ERROR (LAC_EBADLEN, "K is %zu x %zu, C %zu x %zu", sys->K->nrow,
               sys->K->ncol, sys->C ? sys->C->nrow : sys->K->nrow, k);
  s->sys = sys;
  if (!s->built || sys->K->ncol != s->n || k != s->k || hK != s->hK
      || hC != s->hC)
    {
      s->built = 0;
      if ((status = root_build (s, sys)))
        return status;
      s->hK = hK;
      s->hC = hC;
    }
  if (k)
    lac_system_column_scales (s->sys, s->xv, s->s);
  s->new_numbers = 1;
  return LAC_SUCCESS;
}

static void
petsc_set_mesh (void *w, const lac_dist_source *src)
{
  lac_petsc *s = w;
  s->src = src;
}

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

/* New numbers: K_W = K (from the cells or the root's K) divided by kappa,
 * the mean of |K_jj|: the stiffness K_W and the forces f_W are handed to
 * PETSc divided by it (not with fieldsplit, whose GMRES weighs forces
 * against gaps: tuned as it is), so that PETSc sees the same numbers
 * whatever the units (its GAMG with the rigid motions is not
 * scale-invariant: with lengths and moduli scaled by powers of two, the
 * results changed in their last bits, which the projected CG amplifies to
 * 1e-9; chapter 13).  No contact term in it yet (wold = 0). */
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
      || (status = assemble (s->Kw)))
    return status;
  TRY (MatGetDiagonal (s->Kw, s->ru));
  if ((status = sum_abs (s->ru, &sum)))
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

/* B = -C_A (the inactive columns are zeros); fieldsplit: D = 1 and Sp =
 * 1 on the inactive, Sp = -1/w on the active (-S_W^-1 is about -W_A: the
 * Schur complement of (*W) is -S_W); projected: dk = 1 on the inactive
 * (D of B^T B + D).  Each process its own columns and multipliers. */
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
      if (s->D)
        {
          TRY (MatSetValue (s->D, i, i, on ? 0.0 : 1.0, INSERT_VALUES));
          TRY (MatSetValue (s->Sp, i, i, on ? -s->kappa / s->w[i] : 1.0,
                            INSERT_VALUES));
        }
      else
        TRY (VecSetValue (s->dk, i, s->stat[i] ? 0.0 : 1.0, INSERT_VALUES));
    }
  if (!s->D)
    {
      TRY (VecAssemblyBegin (s->dk));
      TRY (VecAssemblyEnd (s->dk));
    }
  return LAC_SUCCESS;
}

/* projected: G = B^T B + D, its solver, and the multigrid of the new
 * K_W. */
static int
update_projected (lac_petsc *s)
{
  int status;
  if (s->G)
    TRY (MatTransposeMatMult (s->B, s->B, MAT_REUSE_MATRIX, PETSC_DEFAULT,
                              &s->G));
  else
    TRY (MatTransposeMatMult (s->B, s->B, MAT_INITIAL_MATRIX, PETSC_DEFAULT,
                              &s->G));
  TRY (MatDiagonalSet (s->G, s->dk, ADD_VALUES));
  TRY (KSPSetOperators (s->kg, s->G, s->G));
  if (s->size > 1 && (status = update_local (s)))
    return status;
  TRY (PCSetOperators (s->pg, s->Kw, s->Kw));
  return LAC_SUCCESS;
}

/* The values (all processes; sys: the root's): the statuses and W from
 * the root, K_W (new numbers: from the cells), B and the solvers. */
static int
update_values (lac_petsc *s, const lac_petsc_command *c,
               const lac_contact_system *sys)
{
  int status;
  if ((s->k && ((status = lac_petsc_bcast (s->w, s->k * sizeof *s->w))
                || (status = lac_petsc_bcast (s->stat, s->k))))
      || (c->all && (status = new_stiffness (s, sys)))
      || (status = contact_terms (s))
      || (s->B && (status = multipliers (s))))
    return status;
  if (s->ks)
    {
      if ((status = assemble (s->D)) || (status = assemble (s->Sp))
          || (status = assemble (s->A)))
        return status;
      TRY (KSPSetOperators (s->ks, s->A, s->A));
    }
  if (s->kp && (status = update_projected (s)))
    return status;
  if (s->ku)
    TRY (KSPSetOperators (s->ku, s->Kw, s->Kw));
  s->counts.factorizations++;
  return LAC_SUCCESS;
}

/* The root: the matrices for the statuses, when they or the numbers
 * changed. */
static int
update (lac_petsc *s, const char *active)
{
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_UPDATE,
                          .all = s->new_numbers };
  int status;
  if (!s->new_numbers && s->have_stat
      && (s->k == 0 || memcmp (active, s->stat, s->k) == 0))
    return LAC_SUCCESS;
  for (size_t i = 0; i < s->k; i++)
    s->w[i] = active[i] && s->s[i] > 0 ? s->omega / s->s[i] : 0.0;
  if (s->k)
    memcpy (s->stat, active, s->k);
  s->have_stat = 0;
  if ((status = lac_petsc_command_send (&c))
      || (status = update_values (s, &c, s->sys)))
    return status;
  s->have_stat = 1;
  s->new_numbers = 0;
  return LAC_SUCCESS;
}

/* ---- collective: the solves --------------------------------------------- */

/* After KSPSolve: iterations and reason; the relative true residual
 * res / ||b|| of the whole system is the caller's. */
static int
check_ksp (lac_petsc *s, KSP ksp, double res, const char *what)
{
  KSPConvergedReason why;
  PetscInt its;
  TRY (KSPGetIterationNumber (ksp, &its));
  TRY (KSPGetConvergedReason (ksp, &why));
  s->counts.iterations += (int) its;
  s->counts.last_iterations = (int) its;
  s->counts.last_residual = res;
  s->counts.solves++;
  if (why < 0)
    LAC_ERROR (why == KSP_DIVERGED_INDEFINITE_PC
               || why == KSP_DIVERGED_INDEFINITE_MAT ? LAC_ESING
               : LAC_EMAXITER, "%s: %s after %d iterations, relative "
               "residual %.3g", what, KSPConvergedReasons[why], (int) its,
               res);
  return LAC_SUCCESS;
}

/* ||b - A x|| / ||b|| (r: scratch). */
static int
true_residual (Mat A, Vec b, Vec x, Vec r, double *res)
{
  PetscReal nb, nr;
  TRY (MatMult (A, x, r));
  TRY (VecAYPX (r, -1.0, b));
  TRY (VecNorm (r, NORM_2, &nr));
  TRY (VecNorm (b, NORM_2, &nb));
  *res = nb > 0 ? nr / nb : nr;
  return LAC_SUCCESS;
}

/* k = 0: K y = x to c->rtol (x, y: the root's, n; y is the start and the
 * solution). */
static int
step_solve_kw (lac_petsc *s, const lac_petsc_command *c, const double *x,
               double *y)
{
  double res;
  int status;
  if ((status = to_dist (s, s->gu, s->useq, x, s->bu))
      || (status = to_dist (s, s->gu, s->useq, y, s->xu)))
    return status;
  TRY (KSPSetInitialGuessNonzero (s->ku, PETSC_TRUE));
  TRY (KSPSetTolerances (s->ku, c->rtol, 0.0, PETSC_DEFAULT, KSP_MAXIT));
  TRY (KSPSolve (s->ku, s->bu, s->xu));
  if ((status = true_residual (s->Kw, s->bu, s->xu, s->ru, &res))
      || (status = check_ksp (s, s->ku, res, "K")))
    return status;
  return to_root (s, s->gu, s->xu, s->useq, y);
}

/* projected, before CG: u0 = B (B^T B + D)^-1 gl with B^T u0 = gl on the
 * active multipliers (C_A^T u0 = g_A), the right-hand side P (f_W - K_W
 * u0) in bu, the start P (U - u0) in xu. */
static PetscErrorCode
projected_start (lac_petsc *s, Vec gl)
{
  PetscCall (KSPSolve (s->kg, gl, s->sk));
  PetscCall (MatMult (s->B, s->sk, s->u0));
  PetscCall (MatMult (s->Kw, s->u0, s->bu));
  PetscCall (VecAYPX (s->bu, -1.0, s->fw));
  PetscCall (project (s, s->bu));
  PetscCall (VecAXPY (s->xu, -1.0, s->u0));
  return project (s, s->xu);
}

/* projected, after CG: U = u0 + x (in xu), lambda = (B^T B + D)^-1 B^T
 * (f_W - K_W U) (in sk), and the relative true residual of (*W), each
 * block in its own unit (the larger of the two): the forces f_W - K_W U
 * - B lambda against f_W (2-norms, as the CG's), the gaps gl - B^T U
 * against |gl| + |B^T| |U| (max-norms). */
static PetscErrorCode
projected_finish (lac_petsc *s, Vec gl, double *res)
{
  PetscReal r1, r2, b1, b2, nB, nU;
  PetscCall (VecAXPY (s->xu, 1.0, s->u0));
  PetscCall (MatMult (s->Kw, s->xu, s->ru));
  PetscCall (VecAYPX (s->ru, -1.0, s->fw));
  PetscCall (MatMultTranspose (s->B, s->ru, s->tk));
  PetscCall (KSPSolve (s->kg, s->tk, s->sk));
  PetscCall (MatMult (s->B, s->sk, s->tu));
  PetscCall (VecAXPY (s->ru, -1.0, s->tu));
  PetscCall (VecNorm (s->ru, NORM_2, &r1));
  PetscCall (MatMultTranspose (s->B, s->xu, s->tk));
  PetscCall (VecAYPX (s->tk, -1.0, gl));
  PetscCall (VecNorm (s->tk, NORM_INFINITY, &r2));
  PetscCall (VecNorm (s->fw, NORM_2, &b1));
  PetscCall (VecNorm (gl, NORM_INFINITY, &b2));
  PetscCall (MatNorm (s->B, NORM_1, &nB));              /* |B^T|_inf */
  PetscCall (VecNorm (s->xu, NORM_INFINITY, &nU));
  *res = fmax (r1 / fmax (b1, 1e-300), r2 / fmax (b2 + nB * nU, 1e-300));
  return 0;
}

/* projected: (*W) by CG on the null space of C_A^T.  The root's f_W (n),
 * gl = -g_A (k, 0 on the inactive), U (start and solution) and lambda. */
static int
step_projected (lac_petsc *s, const lac_petsc_command *c, const double *fw,
                const double *g, double *U, double *lambda)
{
  PetscReal b1;
  double res = 0;
  int status;
  if ((status = to_dist (s, s->gu, s->useq, fw, s->fw))
      || (status = to_dist (s, s->gl, s->lseq, g, s->gk))
      || (status = to_dist (s, s->gu, s->useq, U, s->xu)))
    return status;
  TRY (projected_start (s, s->gk));
  TRY (VecNorm (s->fw, NORM_2, &b1));     /* the CG's residual: forces */
  TRY (KSPSetInitialGuessNonzero (s->kp, PETSC_TRUE));
  TRY (KSPSetTolerances (s->kp, 0.0, c->rtol * b1, PETSC_DEFAULT,
                         KSP_MAXIT));
  TRY (KSPSolve (s->kp, s->bu, s->xu));
  TRY (projected_finish (s, s->gk, &res));
  if ((status = check_ksp (s, s->kp, res, "projected CG on (*W)")))
    return status;
  if ((status = to_root (s, s->gu, s->xu, s->useq, U)))
    return status;
  return to_root (s, s->gl, s->sk, s->lseq, lambda);
}

/* fieldsplit: own entries of a vector of (*W), U's rows from the root's
 * u, lambda's from its l. */
static int
fill_saddle (lac_petsc *s, Vec v, const double *u, const double *l)
{
  IS is[2];
  Vec vu, vl;
  int status;
  TRY (MatNestGetISs (s->A, is, NULL));
  TRY (VecGetSubVector (v, is[0], &vu));
  status = to_dist (s, s->gu, s->useq, u, vu);
  TRY (VecRestoreSubVector (v, is[0], &vu));
  TRY (VecGetSubVector (v, is[1], &vl));
  status = status ? status : to_dist (s, s->gl, s->lseq, l, vl);
  TRY (VecRestoreSubVector (v, is[1], &vl));
  return status;
}

/* fieldsplit: the root's U, lambda = the solution x of (*W). */
static int
gather_saddle (lac_petsc *s, double *U, double *lambda)
{
  IS is[2];
  Vec v;
  int status;
  TRY (MatNestGetISs (s->A, is, NULL));
  TRY (VecGetSubVector (s->x, is[0], &v));
  status = to_root (s, s->gu, v, s->useq, U);
  TRY (VecRestoreSubVector (s->x, is[0], &v));
  TRY (VecGetSubVector (s->x, is[1], &v));
  status = status ? status : to_root (s, s->gl, v, s->lseq, lambda);
  TRY (VecRestoreSubVector (s->x, is[1], &v));
  return status;
}

/* fieldsplit: (*W) as a whole by GMRES; the root's right-hand side (fw,
 * gl), start and solution (U, lambda). */
static int
step_fieldsplit (lac_petsc *s, const lac_petsc_command *c, const double *fw,
                 const double *gl, double *U, double *lambda)
{
  double res;
  int status, first;
  if ((status = fill_saddle (s, s->b, fw, gl))
      || (status = fill_saddle (s, s->x, U, lambda)))
    return status;
  TRY (KSPSetInitialGuessNonzero (s->ks, PETSC_TRUE));
  TRY (KSPSetTolerances (s->ks, c->rtol, 0.0, PETSC_DEFAULT, KSP_MAXIT));
  TRY (KSPSolve (s->ks, s->b, s->x));
  if ((status = true_residual (s->A, s->b, s->x, s->r, &res))
      || (status = check_ksp (s, s->ks, res, "(*W)")))
    return status;
  first = s->counts.last_iterations;
  /* GMRES satisfies C_A^T U = g_A only to its tolerance relative to the
   * forces (the projected CG exactly): one correction x += A^-1 r. */
  TRY (KSPSetInitialGuessNonzero (s->ks, PETSC_FALSE));
  TRY (KSPSetTolerances (s->ks, CORRECTION_RTOL, 0.0, PETSC_DEFAULT,
                         KSP_MAXIT));
  TRY (KSPSolve (s->ks, s->r, s->dx));
  TRY (VecAXPY (s->x, 1.0, s->dx));
  if ((status = true_residual (s->A, s->b, s->x, s->r, &res))
      || (status = check_ksp (s, s->ks, res, "(*W), correction")))
    return status;
  s->counts.last_iterations += first;
  return gather_saddle (s, U, lambda);
}

/* One solve of the mode in use (all processes; the data are the root's). */
static int
step_solve (lac_petsc *s, const lac_petsc_command *c, const double *fw,
            const double *gl, double *U, double *lambda)
{
  if (s->ku)
    return step_solve_kw (s, c, fw, U);
  if (s->kp)
    return step_projected (s, c, fw, gl, U, lambda);
  return step_fieldsplit (s, c, fw, gl, U, lambda);
}

/* x = f + C_A W_A g_A (n, the root). */
static void
load_vector (lac_petsc *s, const double *f, const double *g, double *x)
{
  const lac_csc *C = s->sys->C;
  memcpy (x, f, s->n * sizeof *x);
  for (size_t a = 0; a < s->na; a++)
    {
      size_t i = s->idx[a];
      double v = s->w[i] * g[i];
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        x[C->i[p]] += C->x[p] * v;
    }
}

static int
petsc_solve (void *w, const char *active, const double *f, const double *g,
             double rtol, double *U, double *lambda)
{
  lac_petsc *s = w;
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_SOLVE, .rtol = rtol };
  int status;
  if (!s->sys || !s->built)
    LAC_ERROR (LAC_EINVAL, "petsc: set was not called");
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  if ((status = update (s, active)))
    return status;
  s->na = 0;
  for (size_t i = 0; i < s->k; i++)
    {
      if (active[i])
        s->idx[s->na++] = i;
      s->rhs[i] = active[i] ? -g[i] : 0.0;
      s->lst[i] = active[i] ? lambda[i] / s->kappa : 0.0;
    }
  load_vector (s, f, g, s->xv);
  for (size_t j = 0; j < s->n; j++)
    s->xv[j] /= s->kappa;                          /* f_W / kappa */
  if ((status = lac_petsc_command_send (&c))
      || (status = step_solve (s, &c, s->xv, s->rhs, U, s->lst)))
    return status;
  for (size_t i = 0; i < s->k; i++)
    lambda[i] = active[i] ? s->lst[i] * s->kappa : 0.0;
  return LAC_SUCCESS;
}

/* ---- the other processes ------------------------------------------------ */

/* The others: the root's command, the same steps as the root's with
 * none of its data.  A failure is agreed on within the steps (every
 * process returns it) and reported by the root. */
static int
follow (lac_petsc *s, const lac_petsc_command *c)
{
  switch (c->cmd)
    {
    case LAC_PETSC_CMD_BUILD:
      return build (s, c, NULL);
    case LAC_PETSC_CMD_UPDATE:
      return update_values (s, c, NULL);
    case LAC_PETSC_CMD_SOLVE:
      return step_solve (s, c, NULL, NULL, NULL, NULL);
    case LAC_PETSC_CMD_FREE:
      free_petsc (s);
      free_arrays (s);
      return LAC_SUCCESS;
    case LAC_PETSC_CMD_MEMORY:
      return lac_petsc_memory_reply ();
    default:
      LAC_ERROR (LAC_ESANITY, "unknown command %d", c->cmd);
    }
}

int
lac_petsc_serve (void)
{
  lac_petsc *s;
  lac_petsc_command c;
  int status;
  if (!lac_petsc_initialized ())
    LAC_ERROR (LAC_EINVAL, "lac_petsc_initialize was not called");
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR (LAC_ENOMEM, "petsc worker");
  lac_petsc_rank (&s->rank, &s->size);
  if (s->rank == 0)
    {
      lac_free (s);
      LAC_ERROR (LAC_EINVAL, "the root runs the scene; the others serve");
    }
  while (!(status = lac_petsc_command_receive (&c))
         && c.cmd != LAC_PETSC_CMD_QUIT)
    {
      follow (s, &c);
      lac_error_clear ();
    }
  free_petsc (s);
  free_arrays (s);
  lac_free (s);
  return status;
}

const lac_strategy_ops lac_petsc_ops = {
  .alloc = petsc_alloc, .free = petsc_free, .set = petsc_set,
  .solve = petsc_solve, .get_counts = petsc_get_counts,
  .method = petsc_method, .set_coordinates = petsc_set_coordinates,
  .set_mesh = petsc_set_mesh
};

#endif /* LAC_HAVE_PETSC */
