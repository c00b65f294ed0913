/* lac_petsc.c -- the LAC system by Krylov methods and algebraic multigrid
 *                (see lac_petsc.h)                [LAC (17), Alg. 1 l. 21]
 *
 * The root (process 0) holds the whole system; every step that involves
 * PETSc is a collective one, which the root starts by a command
 * (linalg/lac_petsc_env.h) and the other processes make in
 * lac_petsc_serve:
 *
 *   build   the layout (nodes and multipliers cut in N ranges), the
 *           matrices K_W and B = -C_A (n x k) preallocated from the counts
 *           the root makes for every row, the near-null space, the
 *           solvers (projected: the multigrid of K_W, CG on P K_W;
 *           fieldsplit: the nest [K_W B; B^T D], GMRES);
 *   update  the values: every row of K_W (new numbers) or its contact
 *           rows (K + C_A W_A C_A^T changes only there): the root inserts
 *           its own and sends each process its rows in messages of at most
 *           `chunk` entries (compressed rows), which that process inserts
 *           (one message per chunk, not PETSc's stash of single entries);
 *           B for the statuses (through PETSc's assembly); then B^T B + D
 *           (projected) or D and the Schur preconditioner Sp
 *           (fieldsplit), D = 1 on the inactive;
 *   solve   the right-hand side and the start from the root, one Krylov
 *           solve, its true residual, the solution back to the root.
 *
 * Before a command the root prepares what is its alone (the transpose of
 * C, the pattern of the contact rows, W), so that a failure there sends
 * nothing.  PETSc's errors become LAC_EDEP with PETSc's message.
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

_Static_assert (sizeof (PetscInt) == sizeof (int), "lac_csc's int indices "
                "are handed to PETSc: a PETSc with 32-bit indices");
_Static_assert (sizeof (PetscScalar) == sizeof (double), "real PETSc");

#define KSP_MAXIT 2000        /* Krylov iterations at most per solve     */
#define CORRECTION_RTOL 1e-6  /* fieldsplit: of its correction step      */
#define ROWS_CHUNK (1 << 18)  /* entries of K_W per message, at least    */
#define TAG_ROWS 7301         /* the messages of K_W's rows: indices     */
#define TAG_VALS 7302         /*   and values                            */

enum { PROJECTED, FIELDSPLIT };   /* the contact solvers (-lac_contact)  */

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

typedef struct lac_petsc
{
  double omega;                    /* W_i = omega / s_i                   */
  int rank, size, root;            /* root: rank 0                        */
  size_t n, k;
  int mode, coords_given, built;
  PetscInt bs, r0, r1, l0, l1;     /* block size; own rows of U, lambda   */
  /* the root's: the whole system */
  const lac_contact_system *sys;   /* borrowed                            */
  int dim;                         /* components per node (coordinates)   */
  const double *coords;            /* borrowed, n, or NULL                */
  unsigned long long hK, hC;       /* patterns the matrices were made for */
  lac_csc *Ct;                     /* owned: C^T, k x n                   */
  PetscInt nc, *crow, *cp, *ci;    /* owned: the contact rows of K_W (C
                                      touches them), their pattern (CSR)  */
  double *cx;                      /* owned: their values                 */
  double *s, *w;                   /* owned, k: c_i^T diag(K)^-1 c_i, W   */
  double kappa;                    /* the mean of diag(K): PETSc's K_W and
                                      f_W are divided by it              */
  char *stat;                      /* owned, k: statuses of the matrices  */
  int have_stat, new_numbers;
  double *acc, *xv, *yv;           /* owned, n: scratch                   */
  size_t na, *idx;                 /* owned, k: the active multipliers    */
  double *rhs, *lst;               /* owned, k                            */
  /* every process: its rows */
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
  VecScatter gu, gl;               /* distributed <-> root                */
  Mat Bl, Gl;                      /* projected, N > 1: the own rows of
                                      B (k columns), a copy of G          */
  KSP kl;                          /*   its LU (prefix gram_local_)       */
  Vec vl, ul, tl, tg, sl;          /*   their vectors (own rows; k)       */
  int chunk;                       /* entries per message of K_W's rows  */
  PetscInt *mi;                    /* owned, 3 + 3 chunk: a message's
                                      rows, lengths, columns (N > 1)      */
  double *mx;                      /* owned, chunk: its values            */
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
  lac_free (s->mi);
  lac_free (s->mx);
  s->mi = NULL;
  s->mx = NULL;
  s->built = 0;
}

static void
free_arrays (lac_petsc *s)
{
  lac_csc_free (s->Ct);
  s->Ct = NULL;
  lac_free (s->crow);
  lac_free (s->cp);
  lac_free (s->ci);
  lac_free (s->cx);
  lac_free (s->s);
  lac_free (s->w);
  lac_free (s->stat);
  lac_free (s->acc);
  lac_free (s->xv);
  lac_free (s->yv);
  lac_free (s->idx);
  lac_free (s->rhs);
  lac_free (s->lst);
  s->crow = s->cp = s->ci = NULL;
  s->cx = s->s = s->w = s->acc = s->xv = s->yv = NULL;
  s->rhs = s->lst = NULL;
  s->stat = NULL;
  s->idx = NULL;
  s->nc = 0;
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

/* Rows [a, b) of U on process p: whole nodes (blocks of bs) in N
 * contiguous ranges. */
static void
u_range (const lac_petsc *s, int p, PetscInt *a, PetscInt *b)
{
  size_t bs = (size_t) s->bs, nb = s->n / bs;
  *a = (PetscInt) (bs * (nb * (size_t) p / (size_t) s->size));
  *b = (PetscInt) (bs * (nb * ((size_t) p + 1) / (size_t) s->size));
}

/* Multipliers [a, b) on process p: PETSc's split of k in N ranges. */
static void
l_range (const lac_petsc *s, int p, PetscInt *a, PetscInt *b)
{
  PetscInt k = (PetscInt) s->k, q = k / s->size, r = k % s->size;
  *a = p * q + (p < r ? p : r);
  *b = *a + q + (p < r);
}

/* ---- the root: patterns ------------------------------------------------- */

static int
alloc_arrays (lac_petsc *s, size_t n, size_t k)
{
  size_t k1 = k ? k : 1;
  free_arrays (s);
  s->s = lac_calloc (k1, sizeof *s->s);
  s->w = lac_calloc (k1, sizeof *s->w);
  s->stat = lac_calloc (k1, 1);
  s->idx = lac_malloc (k1 * sizeof *s->idx);
  s->rhs = lac_malloc (k1 * sizeof *s->rhs);
  s->lst = lac_malloc (k1 * sizeof *s->lst);
  s->acc = lac_calloc (n, sizeof *s->acc);
  s->xv = lac_malloc (n * sizeof *s->xv);
  s->yv = lac_malloc (n * sizeof *s->yv);
  if (!s->s || !s->w || !s->stat || !s->idx || !s->rhs
      || !s->lst || !s->acc || !s->xv || !s->yv)
    LAC_ERROR (LAC_ENOMEM, "petsc strategy, n = %zu, k = %zu", n, k);
  return LAC_SUCCESS;
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

/* Append row j's pattern (m entries) to ci, growing it; 0 or ENOMEM. */
static int
append_row (lac_petsc *s, const PetscInt *cols, PetscInt m, size_t *cap)
{
  size_t nnz = (size_t) s->cp[s->nc];
  if (nnz + (size_t) m > *cap)
    {
      PetscInt *ci;
      *cap = 2 * (nnz + (size_t) m);
      if (!(ci = lac_realloc (s->ci, *cap * sizeof *ci)))
        return LAC_ENOMEM;
      s->ci = ci;
    }
  memcpy (s->ci + nnz, cols, (size_t) m * sizeof *cols);
  s->cp[s->nc + 1] = (PetscInt) (nnz + (size_t) m);
  return LAC_SUCCESS;
}

/* The contact rows (those C touches) and their pattern (crow, cp, ci). */
static int
contact_pattern (lac_petsc *s)
{
  const lac_csc *Ct = s->Ct;
  size_t cap = 0, rows = 0;
  int *mark = lac_calloc (s->n, sizeof *mark), status = LAC_SUCCESS;
  PetscInt *cols = lac_malloc (s->n * sizeof *cols);
  for (size_t j = 0; Ct && j < s->n; j++)
    rows += Ct->p[j + 1] > Ct->p[j];
  s->nc = 0;
  s->crow = lac_malloc ((rows + 1) * sizeof *s->crow);
  s->cp = lac_calloc (rows + 1, sizeof *s->cp);
  if (!mark || !cols || !s->crow || !s->cp)
    status = LAC_ENOMEM;
  for (PetscInt j = 0; Ct && !status && j < (PetscInt) s->n; j++)
    if (Ct->p[j + 1] > Ct->p[j])
      {
        PetscInt m = contact_row (s, j, mark, cols);
        if (!(status = append_row (s, cols, m, &cap)))
          s->crow[s->nc++] = j;
      }
  lac_free (cols);
  lac_free (mark);
  if (!status && !(s->cx = lac_malloc (((size_t) s->cp[s->nc] + 1)
                                       * sizeof *s->cx)))
    status = LAC_ENOMEM;
  if (status)
    LAC_ERROR (status, "the contact rows of K_W, n = %zu", s->n);
  return LAC_SUCCESS;
}

/* The pattern of row j of K_W: a contact row (*c advanced) or K's; rows
 * are visited in increasing order. */
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

/* The root: for every row j of K_W (lam = 0) or of B (lam = 1), the
 * entries in the columns of j's own process (d) and the others (o). */
static void
count_rows (const lac_petsc *s, int lam, PetscInt *d, PetscInt *o)
{
  PetscInt c = 0;
  for (int p = 0; p < s->size; p++)
    {
      PetscInt a, b, c0, c1;
      u_range (s, p, &a, &b);
      if (lam)
        l_range (s, p, &c0, &c1);
      else
        c0 = a, c1 = b;
      for (PetscInt j = a; j < b; j++)
        {
          const PetscInt *cols = s->Ct ? s->Ct->i + s->Ct->p[j] : NULL;
          PetscInt m = lam ? s->Ct->p[j + 1] - s->Ct->p[j]
                       : row_pattern (s, j, &c, &cols);
          d[j] = o[j] = 0;
          for (PetscInt t = 0; t < m; t++)
            cols[t] >= c0 && cols[t] < c1 ? d[j]++ : o[j]++;
        }
    }
}

/* ---- collective: build -------------------------------------------------- */

/* dnz, onz of the own rows of K_W (lam = 0) or B (lam = 1): counted by the
 * root, sent to each process. */
static int
own_counts (lac_petsc *s, int lam, PetscInt *dnz, PetscInt *onz)
{
  PetscInt *d = NULL, *o = NULL;
  int *cnt = lac_malloc ((size_t) s->size * sizeof *cnt);
  int *dsp = lac_malloc ((size_t) s->size * sizeof *dsp), status = 0;
  if (s->root)
    {
      d = lac_malloc ((s->n + 1) * sizeof *d);
      o = lac_malloc ((s->n + 1) * sizeof *o);
    }
  if (!cnt || !dsp || (s->root && (!d || !o)))
    status = LAC_ENOMEM;        /* the root: memory is all it can lack */
  for (int p = 0; !status && p < s->size; p++)
    {
      PetscInt a, b;
      u_range (s, p, &a, &b);
      dsp[p] = (int) a;
      cnt[p] = (int) (b - a);
    }
  if (!status && s->root)
    count_rows (s, lam, d, o);
  if (!status
      && (MPI_Scatterv (d, cnt, dsp, MPI_INT, dnz, (int) (s->r1 - s->r0),
                        MPI_INT, 0, PETSC_COMM_WORLD)
          || MPI_Scatterv (o, cnt, dsp, MPI_INT, onz, (int) (s->r1 - s->r0),
                           MPI_INT, 0, PETSC_COMM_WORLD)))
    status = LAC_EDEP;
  lac_free (cnt);
  lac_free (dsp);
  lac_free (d);
  lac_free (o);
  if (status)
    LAC_ERROR (status, "the preallocation of %s, n = %zu",
               lam ? "B" : "K_W", s->n);
  return LAC_SUCCESS;
}

/* A preallocated, empty matrix with the own rows of U, columns of U (lam
 * = 0, K_W) or of the multipliers (lam = 1, B). */
static int
create_rows (lac_petsc *s, int lam, Mat *M)
{
  PetscInt nl = s->r1 - s->r0, cl = lam ? s->l1 - s->l0 : nl;
  PetscInt *dnz = lac_calloc ((size_t) nl + 1, sizeof *dnz);
  PetscInt *onz = lac_calloc ((size_t) nl + 1, sizeof *onz);
  PetscErrorCode e = 0;
  int status = !dnz || !onz ? LAC_ENOMEM : LAC_SUCCESS;
  if (status)
    lac_error_set (status, __func__, "%d rows", (int) nl);
  status = status ? status : own_counts (s, lam, dnz, onz);
  if (!status)
    {
      e = MatCreate (PETSC_COMM_WORLD, M);
      e = e ? e : MatSetSizes (*M, nl, cl, (PetscInt) s->n,
                               lam ? (PetscInt) s->k : (PetscInt) s->n);
      e = e ? e : MatSetType (*M, MATAIJ);
      e = e ? e : MatSetBlockSize (*M, lam ? 1 : s->bs);
      e = e ? e : MatSeqAIJSetPreallocation (*M, 0, dnz);
      e = e ? e : MatMPIAIJSetPreallocation (*M, 0, dnz, 0, onz);
    }
  lac_free (dnz);
  lac_free (onz);
  if (e)
    return lac_petsc_fail ((int) e, __func__, lam ? "B" : "K_W");
  return status;
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
  TRY (VecScatterBegin (sc, seq, v, INSERT_VALUES, SCATTER_REVERSE));
  TRY (VecScatterEnd (sc, seq, v, INSERT_VALUES, SCATTER_REVERSE));
  return LAC_SUCCESS;
}

/* The root's y = the distributed v (nothing copied elsewhere). */
static int
to_root (const lac_petsc *s, VecScatter sc, Vec v, Vec seq, double *y)
{
  TRY (VecScatterBegin (sc, v, seq, INSERT_VALUES, SCATTER_FORWARD));
  TRY (VecScatterEnd (sc, v, seq, INSERT_VALUES, SCATTER_FORWARD));
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
  TRY (VecScatterCreateToZero (s->sk, &s->gl, &s->lseq));
  return LAC_SUCCESS;
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
  TRY (VecScatterCreateToZero (xl, &s->gl, &s->lseq));
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

/* Everything that depends on the sizes and patterns (all processes; the
 * root has prepared its arrays). */
static int
build (lac_petsc *s, const lac_petsc_command *c)
{
  int status;
  free_petsc (s);
  s->n = (size_t) c->n;
  s->k = (size_t) c->k;
  s->bs = c->bs;
  s->mode = c->mode;
  s->coords_given = c->coords;
  u_range (s, s->rank, &s->r0, &s->r1);
  l_range (s, s->rank, &s->l0, &s->l1);
  if ((status = create_rows (s, 0, &s->Kw)))
    return status;
  s->chunk = c->chunk;
  if (s->size > 1
      && (!(s->mi = lac_malloc ((3 + 3 * (size_t) s->chunk) * sizeof *s->mi))
          || !(s->mx = lac_malloc ((size_t) s->chunk * sizeof *s->mx))))
    LAC_ERROR (LAC_ENOMEM, "the messages of K_W's rows, %d entries",
               s->chunk);
  TRY (MatSetOption (s->Kw, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE));
  TRY (MatSetOption (s->Kw, MAT_SYMMETRIC, PETSC_TRUE));
  TRY (MatSetOption (s->Kw, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  TRY (MatCreateVecs (s->Kw, &s->xu, &s->bu));
  TRY (VecDuplicate (s->bu, &s->ru));
  TRY (VecScatterCreateToZero (s->xu, &s->gu, &s->useq));
  if ((status = near_null_space (s)))
    return status;
  if (s->k == 0)
    status = create_ku (s);
  else if (!(status = create_rows (s, 1, &s->B)))
    status = s->mode == FIELDSPLIT ? create_fieldsplit (s)
             : create_projected (s);
  if (status)
    return status;
  s->built = 1;
  s->counts.analyses++;
  return describe (s);
}

/* The root: the entries per message of K_W's rows, ROWS_CHUNK or the
 * longest row (after contact_pattern). */
static int
chunk_size (const lac_petsc *s)
{
  PetscInt c = 0, longest = ROWS_CHUNK;
  for (PetscInt j = 0; j < (PetscInt) s->n; j++)
    {
      const PetscInt *cols;
      PetscInt m = row_pattern (s, j, &c, &cols);
      longest = m > longest ? m : longest;
    }
  return (int) longest;
}

/* The root: its arrays for a new pattern, then the build command. */
static int
root_build (lac_petsc *s, const lac_contact_system *sys)
{
  size_t n = sys->K->ncol, k = sys->C ? sys->C->ncol : 0;
  size_t bs = s->dim > 0 && n % (size_t) s->dim == 0 ? (size_t) s->dim : 1;
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_BUILD, .mode = s->mode,
    .bs = (int) bs, .coords = s->coords && s->dim >= 2 && (int) bs == s->dim,
    .n = (long long) n, .k = (long long) k };
  int status;
  if (s->built && s->size > 1)
    {
      lac_petsc_command f = { .cmd = LAC_PETSC_CMD_FREE };
      if ((status = lac_petsc_command_send (&f)))
        return status;
    }
  free_petsc (s);
  if ((status = alloc_arrays (s, n, k)))
    return status;
  s->sys = sys;
  s->n = n;
  s->k = k;
  if (k && !(s->Ct = lac_csc_transpose (sys->C)))
    LAC_ERROR (LAC_ENOMEM, "C^T, k = %zu", k);
  if ((status = contact_pattern (s)))
    return status;
  c.chunk = chunk_size (s);
  if ((status = lac_petsc_command_send (&c)))
    return status;
  return build (s, &c);
}

/* The mean of |K_jj|: the stiffness K_W and the forces f_W are handed to
 * PETSc divided by it (not with fieldsplit, whose GMRES weighs forces
 * against gaps: tuned as it is), so that PETSc sees the same numbers
 * whatever the units (its GAMG with the rigid motions is not
 * scale-invariant: with lengths and moduli scaled by powers of two, the
 * results changed in their last bits, which the projected CG amplifies to
 * 1e-9; chapter 13). */
static double
mean_diagonal (const lac_csc *K)
{
  double sum = 0;
  for (size_t j = 0; j < K->ncol; j++)
    for (int p = K->p[j]; p < K->p[j + 1]; p++)
      if ((size_t) K->i[p] == j)
        sum += fabs (K->x[p]);
  return sum > 0 ? sum / (double) K->ncol : 1.0;
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
  if (!s->built || sys->K->ncol != s->n || k != s->k || hK != s->hK
      || hC != s->hC)
    {
      if ((status = root_build (s, sys)))
        return status;
      s->hK = hK;
      s->hC = hC;
    }
  s->sys = sys;
  if (k)
    lac_system_column_scales (s->sys, s->xv, s->s);
  s->kappa = s->mode == FIELDSPLIT ? 1.0 : mean_diagonal (sys->K);
  s->new_numbers = 1;
  return LAC_SUCCESS;
}

/* ---- collective: the values for the statuses ---------------------------- */

/* Values of contact row c of K_W = K + C diag(w) C^T, times sc, into
 * cx. */
static void
contact_values (lac_petsc *s, PetscInt c, double sc)
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
      s->cx[t] = s->acc[s->ci[t]] * sc;
      s->acc[s->ci[t]] = 0;
    }
}

/* The root: message `last` (1: the last one) of the rows packed in mi,
 * mx for process p: mi = [rows, entries, last | the rows | their lengths
 * | their columns], mx = their values. */
static int
send_rows (lac_petsc *s, int p, int last)
{
  PetscInt nr = s->mi[0], nz = s->mi[1];
  s->mi[2] = last;
  memmove (s->mi + 3 + nr, s->mi + 3 + s->chunk,       /* the lengths,   */
           (size_t) nr * sizeof *s->mi);
  memmove (s->mi + 3 + 2 * nr, s->mi + 3 + 2 * s->chunk,
           (size_t) nz * sizeof *s->mi);               /* then columns   */
  if (MPI_Send (s->mi, (int) (3 + 2 * nr + nz), MPI_INT, p, TAG_ROWS,
                PETSC_COMM_WORLD)
      || MPI_Send (s->mx, (int) nz, MPI_DOUBLE, p, TAG_VALS,
                   PETSC_COMM_WORLD))
    LAC_ERROR (LAC_EDEP, "MPI_Send of the rows of K_W to process %d", p);
  s->mi[0] = s->mi[1] = 0;
  return LAC_SUCCESS;
}

/* The root: row j (m entries) into the message for process p, the
 * message sent first if it is full.  While packing, the rows are at mi +
 * 3, the lengths at mi + 3 + chunk, the columns at mi + 3 + 2 chunk. */
static int
pack_row (lac_petsc *s, int p, PetscInt j, PetscInt m, const PetscInt *cols,
          const double *x)
{
  int status;
  if ((s->mi[0] == s->chunk || s->mi[1] + m > s->chunk)
      && (status = send_rows (s, p, 0)))
    return status;
  PetscInt nr = s->mi[0], nz = s->mi[1];
  s->mi[3 + nr] = j;
  s->mi[3 + s->chunk + nr] = m;
  memcpy (s->mi + 3 + 2 * s->chunk + nz, cols, (size_t) m * sizeof *cols);
  memcpy (s->mx + nz, x, (size_t) m * sizeof *x);
  s->mi[0] = nr + 1;
  s->mi[1] = nz + m;
  return LAC_SUCCESS;
}

/* The root: every row of K_W (new numbers) or its contact rows; its own
 * inserted, the others' sent to their processes.  After an error the
 * other processes still get their last (empty) message. */
static int
insert_kw (lac_petsc *s, int all)
{
  const lac_csc *K = s->sys->K;
  PetscInt c = 0;
  int status = LAC_SUCCESS;
  for (int p = 0; p < s->size; p++)
    {
      PetscInt a, b;
      u_range (s, p, &a, &b);
      if (s->mi)
        s->mi[0] = s->mi[1] = 0;
      for (PetscInt j = a; !status && j < b; j++)
        {
          const PetscInt *cols;
          PetscInt c0 = c, m = row_pattern (s, j, &c, &cols);
          const double *x = c > c0 ? s->cx + s->cp[c0] : K->x + K->p[j];
          if (c > c0)
            contact_values (s, c0, all ? 1.0 : 1 / s->kappa);
          else if (!all)
            continue;
          if (p > 0)
            status = pack_row (s, p, j, m, cols, x);
          else
            {
              PetscErrorCode e = MatSetValues (s->Kw, 1, &j, m, cols, x,
                                               INSERT_VALUES);
              if (e)
                status = lac_petsc_fail ((int) e, __func__, "MatSetValues");
            }
        }
      if (p > 0)
        {
          if (status)
            s->mi[0] = s->mi[1] = 0;
          int st = send_rows (s, p, 1);
          status = status ? status : st;
        }
    }
  return status;
}

/* The others: their rows of K_W from the root's messages. */
static int
receive_rows (lac_petsc *s)
{
  int last = 0, status = LAC_SUCCESS;
  while (!last)
    {
      if (MPI_Recv (s->mi, 3 + 3 * s->chunk, MPI_INT, 0, TAG_ROWS,
                    PETSC_COMM_WORLD, MPI_STATUS_IGNORE)
          || MPI_Recv (s->mx, s->chunk, MPI_DOUBLE, 0, TAG_VALS,
                       PETSC_COMM_WORLD, MPI_STATUS_IGNORE))
        LAC_ERROR (LAC_EDEP, "MPI_Recv of the rows of K_W");
      PetscInt nr = s->mi[0], off = 0;
      const PetscInt *rows = s->mi + 3, *len = rows + nr, *cols = len + nr;
      last = (int) s->mi[2];
      for (PetscInt r = 0; !status && r < nr; off += len[r++])
        {
          PetscErrorCode e = MatSetValues (s->Kw, 1, rows + r, len[r],
                                           cols + off, s->mx + off,
                                           INSERT_VALUES);
          if (e)
            status = lac_petsc_fail ((int) e, __func__, "MatSetValues");
        }
    }
  return status;
}

/* The root: B = -C_A (the inactive columns are zeros); fieldsplit: D = 1
 * and Sp = 1 on the inactive, Sp = -1/w on the active (-S_W^-1 is about
 * -W_A: the Schur complement of (*W) is -S_W). */
static int
insert_multipliers (lac_petsc *s)
{
  const lac_csc *Ct = s->Ct;
  for (PetscInt j = 0; j < (PetscInt) s->n; j++)
    for (int q = Ct->p[j]; q < Ct->p[j + 1]; q++)
      TRY (MatSetValue (s->B, j, Ct->i[q], s->stat[Ct->i[q]] ? -Ct->x[q]
                        : 0.0, INSERT_VALUES));
  for (PetscInt i = 0; s->D && i < (PetscInt) s->k; i++)
    {
      int on = s->stat[i] && s->w[i] > 0;
      TRY (MatSetValue (s->D, i, i, on ? 0.0 : 1.0, INSERT_VALUES));
      TRY (MatSetValue (s->Sp, i, i, on ? -s->kappa / s->w[i] : 1.0,
                        INSERT_VALUES));
    }
  for (size_t i = 0; i < s->k; i++)
    s->lst[i] = s->stat[i] ? 0.0 : 1.0;
  return LAC_SUCCESS;
}

static int
assemble (Mat M)
{
  TRY (MatAssemblyBegin (M, MAT_FINAL_ASSEMBLY));
  TRY (MatAssemblyEnd (M, MAT_FINAL_ASSEMBLY));
  return LAC_SUCCESS;
}

/* projected: G = B^T B + D (D = 1 on the inactive multipliers, from the
 * root's lst), its solver, and the multigrid of the new K_W. */
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
  if ((status = to_dist (s, s->gl, s->lseq, s->lst, s->dk)))
    return status;
  TRY (MatDiagonalSet (s->G, s->dk, ADD_VALUES));
  TRY (KSPSetOperators (s->kg, s->G, s->G));
  if (s->size > 1 && (status = update_local (s)))
    return status;
  TRY (PCSetOperators (s->pg, s->Kw, s->Kw));
  return LAC_SUCCESS;
}

/* The values (all processes; the root inserts, the assembly sends each
 * process its rows).  A failure of the root's insertion is reported after
 * the collective calls, so that the processes stay in step. */
static int
update_values (lac_petsc *s, const lac_petsc_command *c)
{
  int status = s->root ? insert_kw (s, c->all)
               : s->size > 1 ? receive_rows (s) : LAC_SUCCESS, st;
  if ((st = assemble (s->Kw)))
    return st;
  if (c->all)                             /* dimensionless for PETSc */
    TRY (MatScale (s->Kw, 1 / c->scale));
  if (s->B && !status && s->root)
    status = insert_multipliers (s);
  if (s->B && (st = assemble (s->B)))
    return st;
  if (s->ks)
    {
      if ((st = assemble (s->D)) || (st = assemble (s->Sp))
          || (st = assemble (s->A)))
        return st;
      TRY (KSPSetOperators (s->ks, s->A, s->A));
    }
  if (s->kp && (st = update_projected (s)))
    return st;
  if (s->ku)
    TRY (KSPSetOperators (s->ku, s->Kw, s->Kw));
  s->counts.factorizations++;
  return status;
}

/* The root: the matrices for the statuses, when they or the numbers
 * changed. */
static int
update (lac_petsc *s, const char *active)
{
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_UPDATE,
                          .all = s->new_numbers, .scale = s->kappa };
  int status;
  if (!s->new_numbers && s->have_stat
      && (s->k == 0 || memcmp (active, s->stat, s->k) == 0))
    return LAC_SUCCESS;
  for (size_t i = 0; i < s->k; i++)
    s->w[i] = active[i] && s->s[i] > 0 ? s->omega / s->s[i] : 0.0;
  if (s->k)
    memcpy (s->stat, active, s->k);
  if ((status = lac_petsc_command_send (&c))
      || (status = update_values (s, &c)))
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

/* One command of the root (errors are the root's to report). */
static void
serve_one (lac_petsc *s, const lac_petsc_command *c)
{
  if (c->cmd == LAC_PETSC_CMD_BUILD)
    build (s, c);
  else if (c->cmd == LAC_PETSC_CMD_UPDATE)
    update_values (s, c);
  else if (c->cmd == LAC_PETSC_CMD_SOLVE)
    step_solve (s, c, NULL, NULL, NULL, NULL);
  else if (c->cmd == LAC_PETSC_CMD_FREE)
    free_petsc (s);
  else if (c->cmd == LAC_PETSC_CMD_MEMORY)
    lac_petsc_memory_reply ();
  lac_error_clear ();
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
    serve_one (s, &c);
  free_petsc (s);
  lac_free (s);
  return status;
}

const lac_strategy_ops lac_petsc_ops = {
  .alloc = petsc_alloc, .free = petsc_free, .set = petsc_set,
  .solve = petsc_solve, .get_counts = petsc_get_counts,
  .method = petsc_method, .set_coordinates = petsc_set_coordinates
};

#endif /* LAC_HAVE_PETSC */
