/* lac_petsc.c -- the LAC system by Krylov methods and algebraic multigrid
 *                (see lac_petsc.h)                [LAC (17), Alg. 1 l. 21]
 *
 * set:   the layout (nodes and multipliers cut in N ranges), the pattern
 *        of the own rows of K_W (those of K, and of K + C C^T on the rows
 *        that C touches: the contact rows), the distributed matrices K_W,
 *        B = -C_A (n x k), D = 1 on the inactive multipliers (k x k), the
 *        Schur preconditioner Sp (k x k), the near-null space;
 * solve: the values of the contact rows of K_W, of B, D and Sp for the
 *        statuses when they changed; the right-hand side of (*W); one
 *        Krylov solve (fieldsplit) or the conjugate gradients of the
 *        multipliers around solves of K_W (nested); U and lambda gathered
 *        on every process.
 * PETSc's errors are kept by an error handler (nothing is printed) and
 * turned into LAC_EDEP with PETSc's message.
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
lac_petsc_available (void)
{
  return 0;
}

int
lac_petsc_initialize (const char *options)
{
  (void) options;
  return NO_PETSC (__func__);
}

void
lac_petsc_finalize (void)
{
}

void
lac_petsc_rank (int *rank, int *size)
{
  *rank = 0;
  *size = 1;
}

lac_petsc *
lac_petsc_alloc (double omega)
{
  (void) omega;
  NO_PETSC (__func__);
  return NULL;
}

void
lac_petsc_free (lac_petsc *s)
{
  (void) s;
}

void
lac_petsc_set_coordinates (lac_petsc *s, int dim, const double *x)
{
  (void) s, (void) dim, (void) x;
}

int
lac_petsc_set (lac_petsc *s, const lac_contact_system *sys)
{
  (void) s, (void) sys;
  return NO_PETSC (__func__);
}

int
lac_petsc_solve (lac_petsc *s, const char *active, const double *f,
                 const double *g, double rtol, double *U, double *lambda)
{
  (void) s, (void) active, (void) f, (void) g, (void) rtol, (void) U;
  (void) lambda;
  return NO_PETSC (__func__);
}

void
lac_petsc_get_counts (const lac_petsc *s, lac_solve_counts *c)
{
  (void) s;
  memset (c, 0, sizeof *c);
}

const char *
lac_petsc_method (const lac_petsc *s)
{
  (void) s;
  return "none (built without PETSc)";
}

#else /* LAC_HAVE_PETSC */

#include <petscksp.h>
#include "linalg/lac_pcg.h"

_Static_assert (sizeof (PetscInt) == sizeof (int), "lac_csc's int indices "
                "are handed to PETSc: a PETSc with 32-bit indices");
_Static_assert (sizeof (PetscScalar) == sizeof (double), "real PETSc");

#define KSP_MAXIT 2000        /* Krylov iterations at most per solve     */
#define NESTED_MAXIT 300      /* conjugate gradients on the multipliers  */
#define NESTED_INNER 1e-2     /* inner tolerance / outer (nested)        */

/* ---- errors, initialization --------------------------------------------- */

static char petsc_msg[400];       /* PETSc's first message of an error   */
static int lac_started_petsc;     /* PetscInitialize called by lac       */

static PetscErrorCode
keep_message (MPI_Comm comm, int line, const char *fun, const char *file,
              PetscErrorCode n, PetscErrorType p, const char *mess,
              void *ctx)
{
  (void) comm, (void) file, (void) ctx;
  if (p == PETSC_ERROR_INITIAL)
    snprintf (petsc_msg, sizeof petsc_msg, "%s (in %s, line %d)",
              mess && *mess ? mess : "error", fun, line);
  return n;
}

/* LAC_EDEP (LAC_ENOMEM) with PETSc's message for a failed call. */
static int
petsc_fail (PetscErrorCode e, const char *func, const char *call)
{
  const char *text = NULL;
  int status;
  if (!petsc_msg[0])
    PetscErrorMessage (e, &text, NULL);
  status = lac_error_set (e == PETSC_ERR_MEM ? LAC_ENOMEM : LAC_EDEP, func,
                          "PETSc: %s: %s", call, petsc_msg[0] ? petsc_msg
                          : text ? text : "error");
  petsc_msg[0] = 0;
  return status;
}

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return petsc_fail (e_, __func__, #call); } while (0)

int
lac_petsc_available (void)
{
  return 1;
}

int
lac_petsc_initialize (const char *options)
{
  PetscBool up = PETSC_FALSE;
  PetscInitialized (&up);
  if (!up)
    {
      /* lac's signals are its caller's (and the sanitizers'). */
      PetscOptionsSetValue (NULL, "-no_signal_handler", NULL);
      if (PetscInitializeNoArguments ())
        LAC_ERROR (LAC_EDEP, "PetscInitialize failed (MPI could not start)");
      lac_started_petsc = 1;
      PetscPushErrorHandler (keep_message, NULL);
    }
  if (options && *options)
    TRY (PetscOptionsInsertString (NULL, options));
  return LAC_SUCCESS;
}

void
lac_petsc_finalize (void)
{
  if (!lac_started_petsc)
    return;
  PetscFinalize ();
  lac_started_petsc = 0;
}

void
lac_petsc_rank (int *rank, int *size)
{
  PetscBool up = PETSC_FALSE;
  *rank = 0;
  *size = 1;
  PetscInitialized (&up);
  if (up)
    {
      MPI_Comm_rank (PETSC_COMM_WORLD, rank);
      MPI_Comm_size (PETSC_COMM_WORLD, size);
    }
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

/* ---- the object --------------------------------------------------------- */

struct lac_petsc
{
  double omega;                    /* W_i = omega / s_i                   */
  const lac_contact_system *sys;   /* borrowed                            */
  int dim;                         /* components per node (coordinates)   */
  const double *coords;            /* borrowed, n, or NULL                */
  size_t n, k;
  int nested;                      /* -lac_contact nested                 */
  double inner_rtol;               /* nested: tolerance of the products   */
  int rank, size;
  PetscInt bs, r0, r1, l0, l1;     /* block size; own rows of U, lambda   */
  unsigned long long hK, hC;       /* patterns the matrices were made for */
  lac_csc *Ct;                     /* owned: C^T, k x n                   */
  PetscInt nc, *crow, *cp, *ci;    /* owned: the own contact rows of K_W,
                                      their pattern (CSR)                 */
  double *cx;                      /* owned: their values                 */
  double *s, *w;                   /* owned, k: c_i^T diag(K)^-1 c_i, W   */
  char *stat;                      /* owned, k: statuses of the matrices  */
  int have_stat, new_numbers;
  double *acc, *xv, *yv;           /* owned, n: scratch                   */
  size_t na, *idx;                 /* owned, k: the active multipliers    */
  double *lamA, *rhs;              /* owned, k                            */
  Mat Kw, B, Bt, D, Sp, A;         /* A = [K_W B; B^T D] (nest)           */
  KSP ku, ks;                      /* K_W alone; the whole of (*W)        */
  Vec bu, xu, uall, lall, b, x, r;
  VecScatter gu, gl;               /* to every process                    */
  lac_solve_counts counts;
  char method[200];
};

lac_petsc *
lac_petsc_alloc (double omega)
{
  lac_petsc *s;
  PetscBool nested = PETSC_FALSE;
  char mode[32] = "";
  if (lac_petsc_initialize (NULL))
    return NULL;
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR_NULL (LAC_ENOMEM, "petsc strategy");
  s->omega = omega;
  PetscOptionsGetString (NULL, NULL, "-lac_contact", mode, sizeof mode,
                         &nested);
  s->nested = nested && strcmp (mode, "nested") == 0;
  if (nested && !s->nested && strcmp (mode, "fieldsplit") != 0)
    {
      lac_error_set (LAC_EINVAL, __func__, "-lac_contact %s: expected "
                     "fieldsplit or nested", mode);
      lac_free (s);
      return NULL;
    }
  lac_petsc_rank (&s->rank, &s->size);
  return s;
}

static void
free_petsc (lac_petsc *s)
{
  KSPDestroy (&s->ku);
  KSPDestroy (&s->ks);
  MatDestroy (&s->A);
  MatDestroy (&s->Bt);
  MatDestroy (&s->B);
  MatDestroy (&s->D);
  MatDestroy (&s->Sp);
  MatDestroy (&s->Kw);
  VecDestroy (&s->bu);
  VecDestroy (&s->xu);
  VecDestroy (&s->uall);
  VecDestroy (&s->lall);
  VecDestroy (&s->b);
  VecDestroy (&s->x);
  VecDestroy (&s->r);
  VecScatterDestroy (&s->gu);
  VecScatterDestroy (&s->gl);
}

static void
free_arrays (lac_petsc *s)
{
  lac_csc_free (s->Ct);
  s->Ct = NULL;
  PetscFree (s->crow);
  PetscFree (s->cp);
  PetscFree (s->ci);
  lac_free (s->cx);
  lac_free (s->s);
  lac_free (s->w);
  lac_free (s->stat);
  lac_free (s->acc);
  lac_free (s->xv);
  lac_free (s->yv);
  lac_free (s->idx);
  lac_free (s->lamA);
  lac_free (s->rhs);
  s->cx = s->s = s->w = s->acc = s->xv = s->yv = s->lamA = s->rhs = NULL;
  s->stat = NULL;
  s->idx = NULL;
  s->nc = 0;
}

void
lac_petsc_free (lac_petsc *s)
{
  if (!s)
    return;
  free_petsc (s);
  free_arrays (s);
  lac_free (s);
}

void
lac_petsc_set_coordinates (lac_petsc *s, int dim, const double *x)
{
  s->dim = dim;
  s->coords = x;
}

void
lac_petsc_get_counts (const lac_petsc *s, lac_solve_counts *c)
{
  *c = s->counts;
}

const char *
lac_petsc_method (const lac_petsc *s)
{
  return s->method[0] ? s->method : "petsc (not set)";
}

/* ---- set: layout and patterns ------------------------------------------- */

static int
alloc_arrays (lac_petsc *s, size_t n, size_t k)
{
  size_t k1 = k ? k : 1;
  free_arrays (s);
  s->s = lac_calloc (k1, sizeof *s->s);
  s->w = lac_calloc (k1, sizeof *s->w);
  s->stat = lac_calloc (k1, 1);
  s->idx = lac_malloc (k1 * sizeof *s->idx);
  s->lamA = lac_malloc (k1 * sizeof *s->lamA);
  s->rhs = lac_malloc (k1 * sizeof *s->rhs);
  s->acc = lac_calloc (n, sizeof *s->acc);
  s->xv = lac_malloc (n * sizeof *s->xv);
  s->yv = lac_malloc (n * sizeof *s->yv);
  if (!s->s || !s->w || !s->stat || !s->idx || !s->lamA || !s->rhs
      || !s->acc || !s->xv || !s->yv)
    LAC_ERROR (LAC_ENOMEM, "petsc strategy, n = %zu, k = %zu", n, k);
  s->n = n;
  s->k = k;
  return LAC_SUCCESS;
}

/* The own rows: whole nodes in N contiguous ranges (block size dim) when
 * n is a multiple of dim, else rows in N ranges. */
static void
layout (lac_petsc *s)
{
  size_t bs = s->dim > 0 && s->n % (size_t) s->dim == 0 ? (size_t) s->dim
              : 1, nb = s->n / bs;
  s->bs = (PetscInt) bs;
  s->r0 = (PetscInt) (bs * (nb * (size_t) s->rank / (size_t) s->size));
  s->r1 = (PetscInt) (bs * (nb * ((size_t) s->rank + 1) / (size_t) s->size));
}

/* s_i = c_i^T diag(K)^-1 c_i, as in lac_augmented.c. */
static void
column_scales (lac_petsc *s)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C;
  for (size_t j = 0; j < s->n; j++)
    {
      double kjj = 0;
      for (int p = K->p[j]; p < K->p[j + 1]; p++)
        if ((size_t) K->i[p] == j)
          kjj = fabs (K->x[p]);
      s->xv[j] = kjj > 0 ? 1 / kjj : 0.0;
    }
  for (size_t i = 0; i < s->k; i++)
    {
      s->s[i] = 0;
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        s->s[i] += C->x[p] * C->x[p] * s->xv[C->i[p]];
    }
}

static int
cmp_int (const void *a, const void *b)
{
  int x = *(const int *) a, y = *(const int *) b;
  return (x > y) - (x < y);
}

/* Pattern of row j of K + C C^T (j a contact row) into cols (sorted);
 * returns its length.  mark: n ints, != j + 1 on entry. */
static PetscInt
contact_row (const lac_petsc *s, PetscInt j, int *mark, PetscInt *cols)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C, *Ct = s->Ct;
  PetscInt m = 0;
  for (int p = K->p[j]; p < K->p[j + 1]; p++)
    if (mark[K->i[p]] != j + 1)
      mark[K->i[p]] = j + 1, cols[m++] = K->i[p];
  for (int q = Ct->p[j]; q < Ct->p[j + 1]; q++)
    for (int p = C->p[Ct->i[q]]; p < C->p[Ct->i[q] + 1]; p++)
      if (mark[C->i[p]] != j + 1)
        mark[C->i[p]] = j + 1, cols[m++] = C->i[p];
  qsort (cols, (size_t) m, sizeof *cols, cmp_int);
  return m;
}

/* The own contact rows and their pattern (crow, cp, ci). */
static int
contact_pattern (lac_petsc *s)
{
  const lac_csc *Ct = s->Ct;
  size_t cap = 0, nnz = 0;
  int *mark = lac_calloc (s->n, sizeof *mark);
  PetscInt *cols = lac_malloc (s->n * sizeof *cols);
  s->nc = 0;
  for (PetscInt j = s->r0; j < s->r1; j++)
    s->nc += Ct->p[j + 1] > Ct->p[j];
  s->crow = lac_malloc ((size_t) (s->nc + 1) * sizeof *s->crow);
  s->cp = lac_malloc ((size_t) (s->nc + 1) * sizeof *s->cp);
  for (PetscInt j = s->r0, c = 0; mark && cols && s->crow && s->cp
       && j < s->r1; j++)
    if (Ct->p[j + 1] > Ct->p[j])
      {
        PetscInt m = contact_row (s, j, mark, cols), *ci = s->ci;
        if (nnz + (size_t) m > cap)
          {
            cap = 2 * (nnz + (size_t) m);
            if (!(ci = lac_realloc (s->ci, cap * sizeof *ci)))
              break;
            s->ci = ci;
          }
        memcpy (s->ci + nnz, cols, (size_t) m * sizeof *cols);
        nnz += (size_t) m;
        s->crow[c] = j;
        s->cp[0] = 0;
        s->cp[++c] = (PetscInt) nnz;
      }
  lac_free (cols);
  lac_free (mark);
  if (s->nc && s->cp && s->cp[s->nc] == (PetscInt) nnz && s->ci)
    s->cx = lac_malloc (nnz * sizeof *s->cx);
  if (!mark || !cols || !s->crow || !s->cp || (s->nc && !s->cx))
    LAC_ERROR (LAC_ENOMEM, "the contact rows of K_W, n = %zu", s->n);
  return LAC_SUCCESS;
}

/* The pattern of own row j of K_W: a contact row (*c advanced) or K's. */
static PetscInt
row_pattern (const lac_petsc *s, PetscInt j, PetscInt *c,
             const PetscInt **cols)
{
  const lac_csc *K = s->sys->K;
  if (*c < s->nc && s->crow[*c] == j)
    {
      *cols = s->ci + s->cp[*c];
      (*c)++;
      return s->cp[*c] - s->cp[*c - 1];
    }
  *cols = K->i + K->p[j];
  return K->p[j + 1] - K->p[j];
}

/* Preallocated, empty K_W with the near-null space. */
static int
create_kw (lac_petsc *s)
{
  PetscInt nl = s->r1 - s->r0, c = 0;
  PetscInt *dnz = lac_calloc ((size_t) nl + 1, sizeof *dnz);
  PetscInt *onz = lac_calloc ((size_t) nl + 1, sizeof *onz);
  if (!dnz || !onz)
    {
      lac_free (dnz);
      lac_free (onz);
      LAC_ERROR (LAC_ENOMEM, "%d rows", (int) nl);
    }
  for (PetscInt j = s->r0; j < s->r1; j++)
    {
      const PetscInt *cols;
      PetscInt m = row_pattern (s, j, &c, &cols);
      for (PetscInt t = 0; t < m; t++)
        if (cols[t] >= s->r0 && cols[t] < s->r1)
          dnz[j - s->r0]++;
        else
          onz[j - s->r0]++;
    }
  PetscErrorCode e = MatCreate (PETSC_COMM_WORLD, &s->Kw);
  e = e ? e : MatSetSizes (s->Kw, nl, nl, (PetscInt) s->n, (PetscInt) s->n);
  e = e ? e : MatSetType (s->Kw, MATAIJ);
  e = e ? e : MatSetBlockSize (s->Kw, s->bs);
  e = e ? e : MatSeqAIJSetPreallocation (s->Kw, 0, dnz);
  e = e ? e : MatMPIAIJSetPreallocation (s->Kw, 0, dnz, 0, onz);
  lac_free (dnz);
  lac_free (onz);
  if (e)
    return petsc_fail (e, __func__, "the matrix K_W");
  TRY (MatSetOption (s->Kw, MAT_SYMMETRIC, PETSC_TRUE));
  TRY (MatSetOption (s->Kw, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  return LAC_SUCCESS;
}

/* The rigid motions of the own nodes as K_W's near-null space. */
static int
near_null_space (lac_petsc *s)
{
  Vec xc;
  MatNullSpace nsp;
  PetscScalar *a;
  if (!s->coords || s->dim < 2 || s->bs != s->dim)
    return LAC_SUCCESS;
  TRY (VecCreateMPI (PETSC_COMM_WORLD, s->r1 - s->r0, (PetscInt) s->n,
                     &xc));
  TRY (VecSetBlockSize (xc, s->bs));
  TRY (VecGetArray (xc, &a));
  memcpy (a, s->coords + s->r0, (size_t) (s->r1 - s->r0) * sizeof *a);
  TRY (VecRestoreArray (xc, &a));
  TRY (MatNullSpaceCreateRigidBody (xc, &nsp));
  TRY (MatSetNearNullSpace (s->Kw, nsp));
  TRY (MatNullSpaceDestroy (&nsp));
  TRY (VecDestroy (&xc));
  return LAC_SUCCESS;
}

/* The own multipliers [l0, l1): PETSc's split of k in N ranges. */
static void
multiplier_layout (lac_petsc *s)
{
  PetscInt k = (PetscInt) s->k, q = k / s->size, r = k % s->size;
  s->l0 = s->rank * q + (s->rank < r ? s->rank : r);
  s->l1 = s->l0 + q + (s->rank < r);
}

/* k x k diagonal matrix of the multipliers' layout. */
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

/* B = -C_A (n x k, own rows of U), pattern of C: row j is C^T's column j. */
static int
create_b (lac_petsc *s)
{
  const lac_csc *Ct = s->Ct;
  PetscInt nl = s->r1 - s->r0, kl = s->l1 - s->l0;
  PetscInt *dnz = lac_calloc ((size_t) nl + 1, sizeof *dnz);
  PetscInt *onz = lac_calloc ((size_t) nl + 1, sizeof *onz);
  PetscErrorCode e;
  if (!dnz || !onz)
    {
      lac_free (dnz);
      lac_free (onz);
      LAC_ERROR (LAC_ENOMEM, "%d rows", (int) nl);
    }
  for (PetscInt j = s->r0; j < s->r1; j++)
    for (int q = Ct->p[j]; q < Ct->p[j + 1]; q++)
      if (Ct->i[q] >= s->l0 && Ct->i[q] < s->l1)
        dnz[j - s->r0]++;
      else
        onz[j - s->r0]++;
  e = MatCreateAIJ (PETSC_COMM_WORLD, nl, kl, (PetscInt) s->n,
                    (PetscInt) s->k, 0, dnz, 0, onz, &s->B);
  lac_free (dnz);
  lac_free (onz);
  if (e)
    return petsc_fail (e, __func__, "the matrix B = -C_A");
  return LAC_SUCCESS;
}

/* The nest A = [K_W B; B^T D], its vectors and the Schur preconditioner. */
static int
create_saddle (lac_petsc *s)
{
  Mat blocks[4];
  Vec xl;
  int status;
  multiplier_layout (s);
  if ((status = create_b (s)) || (status = create_diagonal (s, &s->D))
      || (status = create_diagonal (s, &s->Sp)))
    return status;
  TRY (MatCreateTranspose (s->B, &s->Bt));
  blocks[0] = s->Kw, blocks[1] = s->B, blocks[2] = s->Bt, blocks[3] = s->D;
  TRY (MatCreateNest (PETSC_COMM_WORLD, 2, NULL, 2, NULL, blocks, &s->A));
  TRY (MatCreateVecs (s->A, &s->x, &s->b));
  TRY (VecDuplicate (s->b, &s->r));
  TRY (MatCreateVecs (s->D, &xl, NULL));
  TRY (VecScatterCreateToAll (xl, &s->gl, &s->lall));
  TRY (VecDestroy (&xl));
  return LAC_SUCCESS;
}

/* ---- the solvers and their defaults ------------------------------------- */

/* Conjugate gradients and GAMG on K_W (prefix elast_). */
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

/* GMRES and the Schur factorization of PCFIELDSPLIT on (*W). */
static int
create_ks (lac_petsc *s)
{
  PC pc;
  IS is[2];
  int status;
  if ((status = default_option ("-fieldsplit_u_ksp_type", "preonly"))
      || (status = default_option ("-fieldsplit_u_pc_type", "gamg"))
      || (status = default_option ("-fieldsplit_u_pc_gamg_reuse_interpolation",
                                   "true"))
      || (status = default_option ("-fieldsplit_lambda_ksp_type", "preonly"))
      || (status = default_option ("-fieldsplit_lambda_pc_type", "jacobi")))
    return status;
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

/* Everything that depends on the patterns of K and C. */
static int
build (lac_petsc *s, const lac_contact_system *sys)
{
  int status;
  free_petsc (s);
  if ((status = alloc_arrays (s, sys->K->ncol, sys->C->ncol)))
    return status;
  s->sys = sys;
  if (!(s->Ct = lac_csc_transpose (sys->C)))
    LAC_ERROR (LAC_ENOMEM, "C^T, k = %zu", s->k);
  layout (s);
  if ((status = contact_pattern (s)) || (status = create_kw (s))
      || (status = near_null_space (s)))
    return status;
  TRY (MatCreateVecs (s->Kw, &s->xu, &s->bu));
  TRY (VecScatterCreateToAll (s->xu, &s->gu, &s->uall));
  if (s->k > 0 && !s->nested && (status = create_saddle (s)))
    return status;
  if ((s->k == 0 || s->nested) && (status = create_ku (s)))
    return status;
  if (s->k > 0 && !s->nested && (status = create_ks (s)))
    return status;
  s->counts.analyses++;
  return LAC_SUCCESS;
}

int
lac_petsc_set (lac_petsc *s, const lac_contact_system *sys)
{
  unsigned long long hK = lac_csc_pattern_hash (sys->K);
  unsigned long long hC = lac_csc_pattern_hash (sys->C);
  int status;
  if (sys->K->ncol != sys->K->nrow || sys->C->nrow != sys->K->ncol)
    LAC_ERROR (LAC_EBADLEN, "K is %zu x %zu, C %zu x %zu", sys->K->nrow,
               sys->K->ncol, sys->C->nrow, sys->C->ncol);
  if (!s->Kw || sys->K->ncol != s->n || sys->C->ncol != s->k
      || hK != s->hK || hC != s->hC)
    {
      if ((status = build (s, sys)))
        return status;
      s->hK = hK;
      s->hC = hC;
    }
  s->sys = sys;
  column_scales (s);
  s->new_numbers = 1;
  return LAC_SUCCESS;
}

/* ---- solve: the values for the statuses --------------------------------- */

/* Values of contact row c of K_W = K + C diag(w) C^T into cx. */
static void
contact_values (lac_petsc *s, PetscInt c)
{
  const lac_csc *K = s->sys->K, *C = s->sys->C, *Ct = s->Ct;
  PetscInt j = s->crow[c];
  for (int p = K->p[j]; p < K->p[j + 1]; p++)
    s->acc[K->i[p]] += K->x[p];
  for (int q = Ct->p[j]; q < Ct->p[j + 1]; q++)
    {
      int i = Ct->i[q];
      double v = s->w[i] * Ct->x[q];
      if (v != 0)
        for (int p = C->p[i]; p < C->p[i + 1]; p++)
          s->acc[C->i[p]] += v * C->x[p];
    }
  for (PetscInt t = s->cp[c]; t < s->cp[c + 1]; t++)
    {
      s->cx[t] = s->acc[s->ci[t]];
      s->acc[s->ci[t]] = 0;
    }
}

/* The own rows of K_W: all (new numbers) or the contact rows. */
static int
insert_kw (lac_petsc *s, int all)
{
  const lac_csc *K = s->sys->K;
  PetscInt c = 0;
  for (PetscInt j = s->r0; j < s->r1; j++)
    {
      const PetscInt *cols;
      PetscInt c0 = c, m = row_pattern (s, j, &c, &cols);
      if (c > c0)
        {
          contact_values (s, c0);
          TRY (MatSetValues (s->Kw, 1, &j, m, cols, s->cx + s->cp[c0],
                             INSERT_VALUES));
        }
      else if (all)
        TRY (MatSetValues (s->Kw, 1, &j, m, cols, K->x + K->p[j],
                           INSERT_VALUES));
    }
  TRY (MatAssemblyBegin (s->Kw, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (s->Kw, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* B = -C_A, D = 1 and Sp = 1 on the inactive, Sp = -1/w on the active
 * (-S_W^-1 is about -W_A: the Schur complement of (*W) is -S_W). */
static int
insert_saddle (lac_petsc *s, const char *active)
{
  const lac_csc *Ct = s->Ct;
  for (PetscInt j = s->r0; j < s->r1; j++)
    for (int q = Ct->p[j]; q < Ct->p[j + 1]; q++)
      TRY (MatSetValue (s->B, j, Ct->i[q], active[Ct->i[q]] ? -Ct->x[q]
                        : 0.0, INSERT_VALUES));
  for (PetscInt i = s->l0; i < s->l1; i++)
    {
      int on = active[i] && s->w[i] > 0;
      TRY (MatSetValue (s->D, i, i, on ? 0.0 : 1.0, INSERT_VALUES));
      TRY (MatSetValue (s->Sp, i, i, on ? -1 / s->w[i] : 1.0,
                        INSERT_VALUES));
    }
  TRY (MatAssemblyBegin (s->B, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (s->B, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyBegin (s->D, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (s->D, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyBegin (s->Sp, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (s->Sp, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyBegin (s->A, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (s->A, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* The matrices for the statuses, when they or the numbers changed. */
static int
update (lac_petsc *s, const char *active)
{
  int status;
  if (!s->new_numbers && s->have_stat && memcmp (active, s->stat, s->k) == 0)
    return LAC_SUCCESS;
  for (size_t i = 0; i < s->k; i++)
    s->w[i] = active[i] && s->s[i] > 0 ? s->omega / s->s[i] : 0.0;
  if ((status = insert_kw (s, s->new_numbers)))
    return status;
  if (s->ks && (status = insert_saddle (s, active)))
    return status;
  if (s->ks)
    TRY (KSPSetOperators (s->ks, s->A, s->A));
  if (s->ku)
    TRY (KSPSetOperators (s->ku, s->Kw, s->Kw));
  memcpy (s->stat, active, s->k);
  s->have_stat = 1;
  s->new_numbers = 0;
  s->counts.factorizations++;
  return LAC_SUCCESS;
}

/* ---- solve -------------------------------------------------------------- */

/* y (n, every process) = the distributed v (K_W's layout). */
static int
gather_u (lac_petsc *s, Vec v, double *y)
{
  const PetscScalar *a;
  TRY (VecScatterBegin (s->gu, v, s->uall, INSERT_VALUES, SCATTER_FORWARD));
  TRY (VecScatterEnd (s->gu, v, s->uall, INSERT_VALUES, SCATTER_FORWARD));
  TRY (VecGetArrayRead (s->uall, &a));
  memcpy (y, a, s->n * sizeof *y);
  TRY (VecRestoreArrayRead (s->uall, &a));
  return LAC_SUCCESS;
}

static int
gather_lambda (lac_petsc *s, Vec v, double *lambda)
{
  const PetscScalar *a;
  TRY (VecScatterBegin (s->gl, v, s->lall, INSERT_VALUES, SCATTER_FORWARD));
  TRY (VecScatterEnd (s->gl, v, s->lall, INSERT_VALUES, SCATTER_FORWARD));
  TRY (VecGetArrayRead (s->lall, &a));
  memcpy (lambda, a, s->k * sizeof *lambda);
  TRY (VecRestoreArrayRead (s->lall, &a));
  return LAC_SUCCESS;
}

/* v's own entries [lo, hi) from the whole x. */
static int
scatter_own (Vec v, const double *x, PetscInt lo, PetscInt hi)
{
  PetscScalar *a;
  TRY (VecGetArray (v, &a));
  memcpy (a, x + lo, (size_t) (hi - lo) * sizeof *a);
  TRY (VecRestoreArray (v, &a));
  return LAC_SUCCESS;
}

/* After KSPSolve: iterations, true residual ||b - A x|| / ||b||, reason. */
static int
check_ksp (lac_petsc *s, KSP ksp, Mat A, Vec b, Vec x, Vec r,
           const char *what)
{
  KSPConvergedReason why;
  PetscInt its;
  PetscReal nb, nr;
  TRY (KSPGetIterationNumber (ksp, &its));
  TRY (KSPGetConvergedReason (ksp, &why));
  TRY (MatMult (A, x, r));
  TRY (VecAYPX (r, -1.0, b));
  TRY (VecNorm (r, NORM_2, &nr));
  TRY (VecNorm (b, NORM_2, &nb));
  s->counts.iterations += (int) its;
  s->counts.last_iterations = (int) its;
  s->counts.last_residual = nb > 0 ? nr / nb : nr;
  if (why < 0)
    LAC_ERROR (why == KSP_DIVERGED_INDEFINITE_PC
               || why == KSP_DIVERGED_INDEFINITE_MAT ? LAC_ESING
               : LAC_EMAXITER, "%s: %s after %d iterations, relative "
               "residual %.3g", what, KSPConvergedReasons[why], (int) its,
               s->counts.last_residual);
  return LAC_SUCCESS;
}

/* y = K_W^-1 x (both n, on every process) to rtol; y is the start if
 * warm, else 0. */
static int
solve_kw (lac_petsc *s, const double *x, double *y, double rtol, int warm)
{
  int status;
  if ((status = scatter_own (s->bu, x, s->r0, s->r1)))
    return status;
  if (warm && (status = scatter_own (s->xu, y, s->r0, s->r1)))
    return status;
  TRY (KSPSetInitialGuessNonzero (s->ku, warm ? PETSC_TRUE : PETSC_FALSE));
  TRY (KSPSetTolerances (s->ku, rtol, 0.0, PETSC_DEFAULT, KSP_MAXIT));
  TRY (KSPSolve (s->ku, s->bu, s->xu));
  s->counts.solves++;
  if (!s->r)
    TRY (VecDuplicate (s->bu, &s->r));
  if ((status = check_ksp (s, s->ku, s->Kw, s->bu, s->xu, s->r, "K_W")))
    return status;
  return gather_u (s, s->xu, y);
}

/* x = f + C_A (W_A g_A + lambda_A) (n, every process); lamA NULL: 0. */
static void
load_vector (lac_petsc *s, const double *f, const double *g,
             const double *lamA, double *x)
{
  const lac_csc *C = s->sys->C;
  memcpy (x, f, s->n * sizeof *x);
  for (size_t a = 0; a < s->na; a++)
    {
      size_t i = s->idx[a];
      double v = s->w[i] * g[i] + (lamA ? lamA[a] : 0.0);
      for (int p = C->p[i]; p < C->p[i + 1]; p++)
        x[C->i[p]] += C->x[p] * v;
    }
}

/* Own entries of a vector of (*W): U's rows from u, lambda's from l. */
static int
fill_saddle (lac_petsc *s, Vec v, const double *u, const double *l)
{
  IS is[2];
  Vec vu, vl;
  int status;
  TRY (MatNestGetISs (s->A, is, NULL));
  TRY (VecGetSubVector (v, is[0], &vu));
  status = scatter_own (vu, u, s->r0, s->r1);
  TRY (VecRestoreSubVector (v, is[0], &vu));
  TRY (VecGetSubVector (v, is[1], &vl));
  status = status ? status : scatter_own (vl, l, s->l0, s->l1);
  TRY (VecRestoreSubVector (v, is[1], &vl));
  return status;
}

/* fieldsplit: (*W) as a whole; U, lambda the start and the result. */
static int
solve_saddle (lac_petsc *s, const char *active, const double *f,
              const double *g, double rtol, double *U, double *lambda)
{
  IS is[2];
  Vec v;
  int status;
  load_vector (s, f, g, NULL, s->xv);
  for (size_t i = 0; i < s->k; i++)
    s->rhs[i] = active[i] ? -g[i] : 0.0;
  if ((status = fill_saddle (s, s->b, s->xv, s->rhs)))
    return status;
  for (size_t i = 0; i < s->k; i++)
    s->rhs[i] = active[i] ? lambda[i] : 0.0;
  if ((status = fill_saddle (s, s->x, U, s->rhs)))
    return status;
  TRY (KSPSetInitialGuessNonzero (s->ks, PETSC_TRUE));
  TRY (KSPSetTolerances (s->ks, rtol, 0.0, PETSC_DEFAULT, KSP_MAXIT));
  TRY (KSPSolve (s->ks, s->b, s->x));
  s->counts.solves++;
  if ((status = check_ksp (s, s->ks, s->A, s->b, s->x, s->r, "(*W)")))
    return status;
  TRY (MatNestGetISs (s->A, is, NULL));
  TRY (VecGetSubVector (s->x, is[0], &v));
  status = gather_u (s, v, U);
  TRY (VecRestoreSubVector (s->x, is[0], &v));
  TRY (VecGetSubVector (s->x, is[1], &v));
  status = status ? status : gather_lambda (s, v, lambda);
  TRY (VecRestoreSubVector (s->x, is[1], &v));
  for (size_t i = 0; i < s->k; i++)
    if (!active[i])
      lambda[i] = 0;
  return status;
}

/* nested: q = S_W v = C_A^T K_W^-1 C_A v, one solve of K_W. */
static int
nested_product (void *ctx, const double *v, double *q)
{
  lac_petsc *s = ctx;
  const lac_csc *C = s->sys->C;
  int status;
  memset (s->xv, 0, s->n * sizeof *s->xv);
  for (size_t a = 0; a < s->na; a++)
    for (int p = C->p[s->idx[a]]; p < C->p[s->idx[a] + 1]; p++)
      s->xv[C->i[p]] += C->x[p] * v[a];
  if ((status = solve_kw (s, s->xv, s->yv, s->inner_rtol, 0)))
    return status;
  for (size_t a = 0; a < s->na; a++)
    {
      double sum = 0;
      for (int p = C->p[s->idx[a]]; p < C->p[s->idx[a] + 1]; p++)
        sum += C->x[p] * s->yv[C->i[p]];
      q[a] = sum;
    }
  return LAC_SUCCESS;
}

static int
nested_precondition (void *ctx, const double *r, double *z)
{
  const lac_petsc *s = ctx;
  for (size_t a = 0; a < s->na; a++)
    z[a] = s->w[s->idx[a]] * r[a];
  return LAC_SUCCESS;
}

/* nested: the conjugate gradients of lac_augmented.c on the multipliers. */
static int
solve_nested (lac_petsc *s, const double *f, const double *g, double rtol,
              double *U, double *lambda)
{
  const lac_csc *C = s->sys->C;
  lac_pcg_info info;
  int status, outer;
  load_vector (s, f, g, NULL, s->xv);
  if ((status = solve_kw (s, s->xv, U, rtol * NESTED_INNER, 1)))
    return status;
  for (size_t a = 0; a < s->na; a++)
    {
      double cu = 0;
      for (int p = C->p[s->idx[a]]; p < C->p[s->idx[a] + 1]; p++)
        cu += C->x[p] * U[C->i[p]];
      s->rhs[a] = g[s->idx[a]] - cu;
    }
  s->inner_rtol = rtol * NESTED_INNER;
  status = lac_pcg (s->na, nested_product, nested_precondition, s, s->rhs,
                    s->lamA, rtol, NESTED_MAXIT, &info);
  outer = info.iterations;
  if (status)
    return status;
  for (size_t i = 0; i < s->k; i++)
    lambda[i] = 0;
  for (size_t a = 0; a < s->na; a++)
    lambda[s->idx[a]] = s->lamA[a];
  load_vector (s, f, g, s->lamA, s->xv);
  status = solve_kw (s, s->xv, U, rtol * NESTED_INNER, 1);
  s->counts.last_iterations = outer;
  s->counts.last_residual = info.residual;
  return status;
}

int
lac_petsc_solve (lac_petsc *s, const char *active, const double *f,
                 const double *g, double rtol, double *U, double *lambda)
{
  int status;
  if (!s->sys)
    LAC_ERROR (LAC_EINVAL, "lac_petsc_set was not called");
  f = f ? f : s->sys->F;
  g = g ? g : s->sys->G;
  if ((status = update (s, active)))
    return status;
  s->na = 0;
  for (size_t i = 0; i < s->k; i++)
    if (active[i])
      s->lamA[s->na] = lambda[i], s->idx[s->na++] = i;
  if (s->ks)
    status = solve_saddle (s, active, f, g, rtol, U, lambda);
  else if (s->na > 0)
    status = solve_nested (s, f, g, rtol, U, lambda);
  else
    {
      for (size_t i = 0; i < s->k; i++)
        lambda[i] = 0;
      status = solve_kw (s, f, U, rtol, 1);
    }
  return status;
}

#endif /* LAC_HAVE_PETSC */
