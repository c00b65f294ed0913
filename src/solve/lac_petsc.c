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
 *           the near-null space, the solvers of
 *           linalg/lac_petsc_saddle.h (projected CG or fieldsplit GMRES
 *           on (*W); CG on K_W alone when k = 0);
 *   update  the statuses from the root; new numbers: K_W = K / kappa
 *           from the own cells (K checked against them first:
 *           check_assembly), and from K ||K||_inf (for the root's
 *           residuals) and the scales s_i = c_i^T diag(K)^-1 c_i of
 *           W_i = omega / s_i, on every process; then K_W += C (W -
 *           W_old) C^T / kappa by the owners of the columns that
 *           changed; B, D = 1
 *           on the inactive and fieldsplit's Schur preconditioner, given
 *           to the solvers;
 *   solve   the right-hand side and the start from the root, one Krylov
 *           solve, the solution back to the root.
 *   kmul    x from the root, K_W x back: the root's residuals take
 *           K x = kappa K_W x - C W_old C^T x from it when it freed its K
 *           (run/lac_run_solve.c, drop_root_k);
 *   post    u from the root; the stresses and errors of the own cells
 *           summed on the root (fem/lac_post_dist.h).
 *
 * A failure on one process is agreed on by all before the next
 * collective call (lac_petsc_agree), and every command but free and
 * memory ends with that agreement: the root returns it with the message
 * of the process that failed.  PETSc's errors become LAC_EDEP with
 * PETSc's message.
 *
 * Here: the object, the layout, build, solve, kmul and post; update's
 * values in lac_petsc_values.c, the other processes' loop in
 * lac_petsc_serve.c (their state: lac_petsc_internal.h).
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
#include "fem/lac_post_dist.h"
#include "linalg/lac_petsc_saddle.h"
#include "solve/lac_petsc_internal.h"

_Static_assert (sizeof (PetscInt) == sizeof (int), "lac_csc's int indices "
                "are handed to PETSc: a PETSc with 32-bit indices");
_Static_assert (sizeof (PetscScalar) == sizeof (double), "real PETSc");

/* ---- the object --------------------------------------------------------- */

/* lac's options, read on the root (its build command carries them to the
 * others): -lac_contact, -lac_omega, -lac_contact_threshold.  omega is at
 * most LAC_PETSC_OMEGA_MAX: beyond it C W C^T swamps K in K_W (the 3D
 * patch test: 606 CG iterations at 1e6, at 1e8 the loop's residual stalls
 * at rounding, from 1e10 on the CG meets an indefinite preconditioner). */
static int
read_options (lac_petsc *s)
{
  PetscBool set = PETSC_FALSE;
  char mode[32] = "";
  const lac_number_spec omega = { 0, LAC_PETSC_OMEGA_MAX, 1, 0, 0 };
  int status;
  s->omega = LAC_PETSC_OMEGA;
  s->threshold = LAC_PETSC_CONTACT_THRESHOLD;
  if ((status = lac_petsc_option_number ("-lac_omega", &omega, "a finite "
                                         "number > 0 and at most 1e6 "
                                         "(beyond, C W C^T swamps K in "
                                         "K_W)", &s->omega))
      || (status = lac_petsc_option_number ("-lac_contact_threshold", NULL,
                                            "a finite number (< 0: no "
                                            "coupling dropped)",
                                            &s->threshold)))
    return status;
  TRY (PetscOptionsGetString (NULL, NULL, "-lac_contact", mode, sizeof mode,
                              &set));
  s->mode = set && strcmp (mode, "fieldsplit") == 0 ? FIELDSPLIT : PROJECTED;
  if (set && s->mode == PROJECTED && strcmp (mode, "projected") != 0)
    LAC_ERROR (LAC_EINVAL, "-lac_contact %s: expected projected or "
               "fieldsplit", mode);
  return LAC_SUCCESS;
}

static void *
petsc_alloc (void)
{
  lac_petsc *s;
  if (lac_petsc_initialize (NULL))
    return NULL;
  if (!(s = lac_calloc (1, sizeof *s)))
    LAC_ERROR_NULL (LAC_ENOMEM, "petsc strategy");
  if (read_options (s))
    {
      lac_free (s);
      return NULL;
    }
  lac_petsc_rank (&s->rank, &s->size);
  s->root = s->rank == 0;
  return s;
}

#define COUNT(a) (sizeof (a) / sizeof *(a))

void
lac_petsc_free_petsc (lac_petsc *s)
{
  Mat *mat[] = { &s->B, &s->Kw };
  Vec *vec[] = { &s->fw, &s->xu, &s->ru, &s->gk, &s->lk, &s->dk, &s->pk,
                 &s->useq, &s->lseq };
  lac_petsc_saddle_free (s->sv);
  s->sv = NULL;
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

void
lac_petsc_free_arrays (lac_petsc *s)
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
  lac_petsc_free_petsc (s);
  lac_petsc_free_arrays (s);
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
  lac_petsc_free_arrays (s);
  s->idx = lac_malloc (k1 * sizeof *s->idx);
  s->rhs = lac_malloc (k1 * sizeof *s->rhs);
  s->lst = lac_malloc (k1 * sizeof *s->lst);
  s->xv = lac_malloc (n * sizeof *s->xv);
  if (!s->idx || !s->rhs || !s->lst || !s->xv)
    LAC_ERROR (LAC_ENOMEM, "petsc strategy, n = %zu, k = %zu", n, k);
  return LAC_SUCCESS;
}

/* Every process: the statuses, W and the W of K_W now (k each). */
static int
alloc_weights (lac_petsc *s)
{
  size_t k1 = s->k ? s->k : 1;
  lac_free (s->s);
  lac_free (s->w);
  lac_free (s->wold);
  lac_free (s->dw);
  lac_free (s->stat);
  s->s = lac_calloc (k1, sizeof *s->s);
  s->w = lac_calloc (k1, sizeof *s->w);
  s->wold = lac_calloc (k1, sizeof *s->wold);
  s->dw = lac_calloc (k1, sizeof *s->dw);
  s->stat = lac_calloc (k1, 1);
  if (!s->s || !s->w || !s->wold || !s->dw || !s->stat)
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

/* "projected cg + gamg on K_W, 2 processes" from the solvers. */
static int
describe (lac_petsc *s)
{
  char kt[32], pt[32];
  const char *es = s->size > 1 ? "es" : "";
  int status = lac_petsc_saddle_types (s->sv, kt, pt, sizeof kt);
  if (status)
    return status;
  if (s->k == 0)
    snprintf (s->method, sizeof s->method, "%s + %s on K, %d process%s",
              kt, pt, s->size, es);
  else if (s->mode == FIELDSPLIT)
    snprintf (s->method, sizeof s->method, "%s + fieldsplit(%s, W) on "
              "(*W), %d process%s", kt, pt, s->size, es);
  else
    snprintf (s->method, sizeof s->method, "projected %s + %s on K_W, %d "
              "process%s", kt, pt, s->size, es);
  return LAC_SUCCESS;
}

/* The vectors of the multipliers' layout (B's columns) and their scatter
 * from the root. */
static int
multiplier_vectors (lac_petsc *s)
{
  Vec *v[] = { &s->gk, &s->dk, &s->pk };
  TRY (MatCreateVecs (s->B, &s->lk, NULL));
  for (size_t i = 0; i < COUNT (v); i++)
    TRY (VecDuplicate (s->lk, v[i]));
  return root_scatter (s, s->lk, NULL, &s->gl, &s->lseq);
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
int
lac_petsc_build (lac_petsc *s, const lac_petsc_command *c,
                 const lac_contact_system *sys)
{
  int status;
  lac_petsc_free_petsc (s);
  s->n = (size_t) c->n;
  s->k = (size_t) c->k;
  s->bs = c->bs;
  s->mode = c->mode;
  s->omega = c->omega;
  s->threshold = c->threshold;
  s->coords_given = c->coords;
  s->cells = c->cells;
  if ((status = build_layout (s, c, sys ? sys->C : NULL))
      || (status = create_matrices (s, sys && !c->cells ? sys->K : NULL)))
    return status;
  TRY (MatSetOption (s->Kw, MAT_SYMMETRIC, PETSC_TRUE));
  TRY (MatSetOption (s->Kw, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  TRY (MatCreateVecs (s->Kw, &s->xu, &s->fw));
  TRY (VecDuplicate (s->fw, &s->ru));
  if ((status = root_scatter (s, s->xu, lac_dist_row (s->dist), &s->gu,
                              &s->useq))
      || (status = near_null_space (s))
      || (s->k && (status = multiplier_vectors (s)))
      || (status = lac_petsc_saddle_create ((lac_saddle_method) s->mode,
                                            s->Kw, s->k ? s->B : NULL,
                                            s->k ? s->threshold : -1.0,
                                            &s->sv)))
    return status;
  s->built = 1;
  s->counts.analyses++;
  return describe (s);
}

/* The block size of n dofs: dim with the coordinates of dim per node. */
static size_t
block_size (const lac_petsc *s, size_t n)
{
  return s->dim > 0 && n % (size_t) s->dim == 0 ? (size_t) s->dim : 1;
}

/* 1 if K of these n dofs comes from the cells of set_mesh (dim dofs a
 * node, the coordinates given), not from the root's K. */
static int
petsc_own_k (const void *w, size_t n)
{
  const lac_petsc *s = w;
  return s->src && s->src->mesh && (size_t) s->src->mesh->dim
         * s->src->mesh->nnodes == n
         && (int) block_size (s, n) == s->src->mesh->dim;
}

/* The root: the command of a new pattern; K from the cells when a mesh of
 * these dofs was given (set_mesh). */
static int
root_build (lac_petsc *s, const lac_contact_system *sys)
{
  size_t n = lac_system_n (sys), k = sys->C ? sys->C->ncol : 0;
  size_t bs = block_size (s, n);
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_BUILD, .mode = s->mode,
    .bs = (int) bs, .coords = s->coords && s->dim >= 2 && (int) bs == s->dim,
    .n = (long long) n, .k = (long long) k, .cells = petsc_own_k (s, n),
    .omega = s->omega, .threshold = s->threshold };
  int status;
  if (!c.cells && !sys->K)
    LAC_ERROR (LAC_EINVAL, "petsc: no K and no cells of these dofs to "
               "assemble it from");
  if ((status = alloc_arrays (s, n, k))
      || (status = lac_petsc_command_send (&c)))
    return status;
  return lac_petsc_agree (lac_petsc_build (s, &c, sys));
}

static int
petsc_set (void *w, const lac_contact_system *sys)
{
  lac_petsc *s = w;
  unsigned long long hK = sys->K ? lac_csc_pattern_hash (sys->K)
                           : (unsigned long long) sys->Kop->n; /* fixed */
  unsigned long long hC = sys->C ? lac_csc_pattern_hash (sys->C) : 0;
  size_t n = lac_system_n (sys), k = sys->C ? sys->C->ncol : 0;
  int status;
  if (!s->root)
    LAC_ERROR (LAC_ESANITY, "process %d: only the root sets a system",
               s->rank);
  if ((sys->K && sys->K->ncol != sys->K->nrow)
      || (sys->C && sys->C->nrow != n))
    LAC_ERROR (LAC_EBADLEN, "K is %zu x %zu, C %zu x %zu", n, n,
               sys->C ? sys->C->nrow : n, k);
  s->sys = sys;
  if (!s->built || n != s->n || k != s->k || hK != s->hK
      || hC != s->hC)
    {
      s->built = 0;
      if ((status = root_build (s, sys)))
        return status;
      s->hK = hK;
      s->hC = hC;
    }
  s->new_numbers = 1;
  return LAC_SUCCESS;
}

static void
petsc_set_mesh (void *w, const lac_dist_source *src)
{
  lac_petsc *s = w;
  s->src = src;
}

/* ---- collective: the solves --------------------------------------------- */

/* One solve of (*W) (all processes; the data are the root's): f_W (n),
 * gl = -g_A (k, 0 on the inactive), U and lambda (the start and the
 * solution). */
int
lac_petsc_step_solve (lac_petsc *s, const lac_petsc_command *c,
                      const double *fw, const double *gl, double *U,
                      double *lambda)
{
  lac_saddle_counts n;
  int status;
  if ((status = to_dist (s, s->gu, s->useq, fw, s->fw))
      || (status = to_dist (s, s->gu, s->useq, U, s->xu))
      || (s->k && (status = to_dist (s, s->gl, s->lseq, gl, s->gk)))
      || (s->k && s->mode == FIELDSPLIT              /* GMRES's start */
          && (status = to_dist (s, s->gl, s->lseq, lambda, s->lk))))
    return status;
  status = lac_petsc_saddle_solve (s->sv, s->fw, s->k ? s->gk : NULL,
                                   c->rtol, s->k == 0 ? "K" : s->mode
                                   == PROJECTED ? "projected CG on (*W)"
                                   : "(*W)", s->xu, s->k ? s->lk : NULL, &n);
  s->counts.iterations += n.iterations;
  s->counts.last_iterations = n.iterations;
  s->counts.last_residual = n.residual;
  s->counts.solves += n.solves;
  if (status || (status = to_root (s, s->gu, s->xu, s->useq, U)))
    return status;
  return s->k ? to_root (s, s->gl, s->lk, s->lseq, lambda) : LAC_SUCCESS;
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
  if ((status = lac_petsc_update (s, active)))
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
      || (status = lac_petsc_agree (lac_petsc_step_solve (s, &c, s->xv,
                                                          s->rhs, U,
                                                          s->lst))))
    return status;
  for (size_t i = 0; i < s->k; i++)
    lambda[i] = active[i] ? s->lst[i] * s->kappa : 0.0;
  return LAC_SUCCESS;
}

/* ---- K x for the root's residuals --------------------------------------- */

/* K_W x (all processes; x and y: the root's, n). */
int
lac_petsc_step_kmul (lac_petsc *s, const double *x, double *y)
{
  int status = to_dist (s, s->gu, s->useq, x, s->xu);
  if (status)
    return status;
  TRY (MatMult (s->Kw, s->xu, s->ru));
  return to_root (s, s->gu, s->ru, s->useq, y);
}

/* y = K x = kappa K_W x - C W_old C^T x: K_W holds K / kappa and the
 * contact terms of W_old (contact_terms), with the copy of C they were
 * added from; no K on the root.  K_W's K was checked against its cells
 * when it was assembled (new_stiffness). */
static int
petsc_kmul (void *w, const double *x, double *y)
{
  lac_petsc *s = w;
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_KMUL };
  const lac_csc *C = s->dist ? lac_dist_c (s->dist) : NULL;
  int status;
  if (!s->built || !s->have_stat || s->new_numbers)
    LAC_ERROR (LAC_EINVAL, "petsc: K x before the matrices of the last set "
               "were made");
  if ((status = lac_petsc_command_send (&c))
      || (status = lac_petsc_agree (lac_petsc_step_kmul (s, x, y))))
    return status;
  for (size_t j = 0; j < s->n; j++)
    y[j] *= s->kappa;
  for (size_t i = 0; C && i < s->k; i++)
    if (s->wold[i] != 0)
      {
        double t = 0;
        for (int p = C->p[i]; p < C->p[i + 1]; p++)
          t += C->x[p] * x[C->i[p]];
        for (int p = C->p[i]; p < C->p[i + 1]; p++)
          y[C->i[p]] -= s->wold[i] * C->x[p] * t;
      }
  return LAC_SUCCESS;
}

/* ||K||_inf, taken by every process when K was assembled (new_stiffness). */
static int
petsc_knorm (const void *w, double *norm)
{
  const lac_petsc *s = w;
  *norm = 0;
  if (!s->built || !s->have_stat || s->new_numbers)
    LAC_ERROR (LAC_EINVAL, "petsc: ||K|| before the matrices of the last "
               "set were made");
  *norm = s->knorm;
  return LAC_SUCCESS;
}

/* ---- the stresses and errors on the processes ---------------------------- */

/* The root: the processes' cells give p (fem/lac_post_dist.h). */
static int
petsc_post (void *w, lac_post_request *p)
{
  lac_petsc *s = w;
  lac_petsc_command c = { .cmd = LAC_PETSC_CMD_POST };
  int status;
  if (!s->built || !s->cells)
    LAC_ERROR (LAC_EINVAL, "petsc: the stresses on the processes need the "
               "cells K was assembled from");
  if ((status = lac_petsc_command_send (&c)))
    return status;
  return lac_petsc_agree (lac_dist_post (s->dist, p));
}

const lac_strategy_ops lac_petsc_ops = {
  .alloc = petsc_alloc, .free = petsc_free, .set = petsc_set,
  .solve = petsc_solve, .get_counts = petsc_get_counts,
  .method = petsc_method, .set_coordinates = petsc_set_coordinates,
  .set_mesh = petsc_set_mesh, .kmul = petsc_kmul, .knorm = petsc_knorm,
  .own_k = petsc_own_k, .post = petsc_post
};

#endif /* LAC_HAVE_PETSC */
