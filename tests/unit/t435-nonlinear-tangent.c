/* t435: the consistent tangent of the large-deformation loop against finite
 *       differences of its residual       [LAC (16)-(18), §4.5, Alg. 1]
 *
 * The residual of solve/lac_nonlinear.h at fixed multipliers lambda,
 *   R(U) = -F_int(U) + C(U) lambda,   d(U) = the mean gaps,
 * on the current coordinates X + U (pairing, C and d recomputed), has the
 * derivatives -K_T + H and -B^T (contact/lac_contact_tangent.h).  Every
 * column j is compared with the central difference (R(U + h e_j) -
 * R(U - h e_j)) / 2h, h = 1e-6 (relative error <= 1e-6 of the largest
 * entry of the block), at a deformed state U with mixed gaps and
 * penetrations, non-parallel facets and random negative lambda:
 *   1. 2D plane strain, quad4 on quad4, both bodies deformable (the
 *      slave's segments gathered two by two), the slave randomly deformed;
 *   2. 3D, hex8 on hex8 (slave faces cut into triangles by the macro-mesh),
 *      the slave randomly deformed, the master by an affine map;
 *   3. 2D axisymmetric, quad8 against a curved rigid obstacle;
 *   4. 3D, hex20 against a curved rigid obstacle;
 *   5-6. cases 3 and 4 with the gap along the slave normal (the
 *      obstacle's slave_normal flag) instead of the obstacle's normal.
 * The slave lies inside the master surface (the edge of the contact zone
 * is not differentiated), and the pairs are exact for the quadrature
 * (flat slave sub-facets, masters flat or rigid), so the differences
 * measure the derivatives and nothing else.  The contact part is checked
 * on its own (H against the difference of C lambda; B against that of d),
 * and the frozen-geometry tangent (H = 0, B = C) must fail the same
 * check, so that the comparison can tell them apart.  The tangent built
 * in two pieces of columns (lac_contact_tangent_build_cols, cut anywhere)
 * and put side by side is the whole one, bit for bit.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "contact/lac_contact.h"
#include "contact/lac_contact_tangent.h"
#include "fem/lac_hyper.h"
#include "base/lac_status.h"

#define FD_H 1e-6
#define TOL 1e-6

typedef struct fdcase
{
  const char *name;
  lac_mesh *m;            /* the reference mesh (after the macro-mesh)     */
  lac_macro *M;
  lac_pairing_facets master;   /* n = 0: the obstacle                       */
  lac_obstacle ob;
  lac_hyper mat;
  double *E, *nu;
  double *lambda;         /* per macro-element                             */
} fdcase;

/* Pseudo-random numbers in [-1, 1] (fixed sequence). */
static double
rnd (unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 32767.5 - 1.0;
}

/* 1 if a and b hold the same numbers, bit for bit. */
static int
same_tangent (const lac_contact_tangent *a, const lac_contact_tangent *b)
{
  size_t nz = (size_t) a->B->p[a->k];
  if (a->k != b->k || a->nblock != b->nblock || a->ndof != b->ndof
      || memcmp (a->B->p, b->B->p, (a->k + 1) * sizeof (int))
      || (nz && (memcmp (a->B->i, b->B->i, nz * sizeof (int))
                 || memcmp (a->B->x, b->B->x, nz * sizeof (double))))
      || memcmp (a->bptr, b->bptr, (a->nblock + 1) * sizeof (size_t))
      || memcmp (a->vptr, b->vptr, (a->nblock + 1) * sizeof (size_t)))
    return 0;
  return (!a->bptr[a->nblock] || !memcmp (a->dof, b->dof, a->bptr[a->nblock]
                                          * sizeof (size_t)))
         && (!a->vptr[a->nblock] || !memcmp (a->val, b->val,
                                             a->vptr[a->nblock]
                                             * sizeof (double)));
}

/* The columns [0, i) and [i, k) built apart and put side by side are the
 * whole tangent t, for cuts at the ends and inside; a range past the
 * columns is refused. */
static void
check_pieces (const fdcase *fc, const lac_mesh *cur, const lac_pairing *P,
              const lac_pairing_facets *Mf, const lac_contact *c,
              const double *lk, const lac_contact_tangent *t)
{
  size_t cuts[4] = { 0, c->k / 3, c->k / 2 + 1, c->k };
  for (int q = 0; q < 4; q++)
    {
      size_t i = cuts[q] < c->k ? cuts[q] : c->k;
      lac_contact_tangent *pc[2] = { NULL, NULL }, *whole = NULL;
      int st = lac_contact_tangent_build_cols (cur, fc->mat.model, fc->M, P,
                                               Mf, &fc->ob, c, lk, NULL, 0,
                                               i, &pc[0])
               || lac_contact_tangent_build_cols (cur, fc->mat.model, fc->M,
                                                  P, Mf, &fc->ob, c, lk, NULL,
                                                  i, c->k, &pc[1])
               || lac_contact_tangent_cat (pc, 2, &whole);
      check_true (!st && same_tangent (whole, t), "%s: columns cut at %zu "
                  "of %zu: the two pieces are the tangent, bit for bit",
                  fc->name, i, c->k);
      lac_contact_tangent_free (pc[0]);
      lac_contact_tangent_free (pc[1]);
      lac_contact_tangent_free (whole);
    }
  lac_contact_tangent *bad = NULL;
  check_status (lac_contact_tangent_build_cols (cur, fc->mat.model, fc->M, P,
                                                Mf, &fc->ob, c, lk, NULL, 1,
                                                c->k + 1, &bad),
                LAC_EINVAL, "%s: columns past the last refused", fc->name);
  check_true (bad == NULL, "%s: nothing built for a bad range", fc->name);
}

/* Contact data on X + U: C lambda (ndof), d (k); optionally the tangent
 * and a copy of C. */
static int
evaluate (const fdcase *fc, const double *U, double *Cl, double *d,
          size_t *k, lac_contact_tangent **tan, lac_csc **C)
{
  const lac_mesh *m = fc->m;
  size_t ndof = (size_t) m->dim * m->nnodes;
  lac_mesh cur = *m;
  double *x = malloc (ndof * sizeof *x);
  for (size_t j = 0; j < ndof; j++)
    x[j] = m->x[j] + U[j];
  cur.x = x;
  lac_pairing_facets S = { &cur, fc->M->ptr[fc->M->n], fc->M->cell,
                           fc->M->face }, Mf = fc->master;
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_pairing *P = NULL;
  lac_contact *c = NULL;
  int st;
  Mf.mesh = &cur;
  if (fc->master.n)
    st = lac_pairing_build (&S, &Mf, &po, &P);
  else
    st = lac_obstacle_pairing (&S, &fc->ob, 0, &P);
  if (!st)
    st = lac_contact_build (&cur, fc->mat.model, fc->M, P,
                            fc->master.n ? &Mf : NULL, 0.01, &c);
  if (!st)
    {
      double *lk = malloc ((c->k + 1) * sizeof *lk);
      memset (Cl, 0, ndof * sizeof *Cl);
      for (size_t i = 0; i < c->k; i++)
        {
          lk[i] = fc->lambda[c->macro[i]];
          d[i] = c->G[i];
          for (int q = c->C->p[i]; q < c->C->p[i + 1]; q++)
            Cl[c->C->i[q]] += c->C->x[q] * lk[i];
        }
      *k = c->k;
      if (tan)
        st = lac_contact_tangent_build (&cur, fc->mat.model, fc->M, P,
                                        fc->master.n ? &Mf : NULL, &fc->ob,
                                        c, lk, NULL, tan);
      if (tan && !st)
        check_pieces (fc, &cur, P, fc->master.n ? &Mf : NULL, c, lk, *tan);
      if (C)
        *C = lac_csc_copy (c->C);
      free (lk);
    }
  lac_contact_free (c);
  lac_pairing_free (P);
  free (x);
  return st;
}

/* Internal force and tangent (dense ndof x ndof, column-major). */
static int
internal (const fdcase *fc, const double *U, double *Fint, double *K)
{
  size_t n = (size_t) fc->m->dim * fc->m->nnodes;
  lac_triplet *T = K ? lac_triplet_alloc (n, n, 0) : NULL;
  memset (Fint, 0, n * sizeof *Fint);
  int st = lac_hyper_assemble (fc->m, &fc->mat, U, Fint, T);
  if (!st && K)
    {
      memset (K, 0, n * n * sizeof *K);
      for (size_t q = 0; q < T->nz; q++)
        K[(size_t) T->j[q] * n + (size_t) T->i[q]] += T->x[q];
    }
  lac_triplet_free (T);
  return st;
}

/* Entry (r, i) of a CSC matrix. */
static double
entry (const lac_csc *A, size_t r, size_t i)
{
  for (int q = A->p[i]; q < A->p[i + 1]; q++)
    if ((size_t) A->i[q] == r)
      return A->x[q];
  return 0;
}

/* The errors of the analytic columns against the central differences,
 * each relative to the largest entry of its analytic block:
 *   err[0]  H          against  d(C lambda)/dU
 *   err[1]  -B^T       against  d(d)/dU
 *   err[2]  -K_T + H   against  dR/dU
 *   err[3]  0          against  d(C lambda)/dU   (frozen geometry)
 *   err[4]  -C^T       against  d(d)/dU          (frozen geometry) */
static void
compare (const fdcase *fc, const double *U, double err[5])
{
  size_t n = (size_t) fc->m->dim * fc->m->nnodes, k = 0, kp = 0, km = 0;
  double *Cl = malloc (n * sizeof *Cl), *d = malloc (n * sizeof *d);
  double *Clp = malloc (n * sizeof *Clp), *Clm = malloc (n * sizeof *Clm);
  double *dp = malloc (n * sizeof *dp), *dm = malloc (n * sizeof *dm);
  double *Fp = malloc (n * sizeof *Fp), *Fm = malloc (n * sizeof *Fm);
  double *K = malloc (n * n * sizeof *K), *Up = malloc (n * sizeof *Up);
  double *e = calloc (n, sizeof *e), *He = malloc (n * sizeof *He);
  double mx[3] = { 0, 0, 0 }, df[5] = { 0, 0, 0, 0, 0 };
  lac_contact_tangent *t = NULL;
  lac_csc *C = NULL;
  check_status (evaluate (fc, U, Cl, d, &k, &t, &C), LAC_SUCCESS,
                "%s: evaluate", fc->name);
  check_status (internal (fc, U, Fp, K), LAC_SUCCESS, "%s: K_T", fc->name);
  check_true (k > 0, "%s: no multiplier", fc->name);
  for (size_t j = 0; t && C && j < n; j++)
    {
      memcpy (Up, U, n * sizeof *Up);
      Up[j] += FD_H;
      int s1 = evaluate (fc, Up, Clp, dp, &kp, NULL, NULL)
               || internal (fc, Up, Fp, NULL);
      Up[j] -= 2 * FD_H;
      int s2 = evaluate (fc, Up, Clm, dm, &km, NULL, NULL)
               || internal (fc, Up, Fm, NULL);
      if (s1 || s2 || kp != k || km != k)
        {
          check_true (0, "%s: dof %zu: evaluation failed or k changed",
                      fc->name, j);
          break;
        }
      e[j] = 1;
      memset (He, 0, n * sizeof *He);
      lac_contact_tangent_apply (t, e, He);
      e[j] = 0;
      for (size_t r = 0; r < n; r++)
        {
          double fdc = (Clp[r] - Clm[r]) / (2 * FD_H);
          double fdr = fdc - (Fp[r] - Fm[r]) / (2 * FD_H);
          double kr = K[j * n + r];
          mx[0] = fmax (mx[0], fabs (He[r]));
          mx[2] = fmax (mx[2], fabs (He[r] - kr));
          df[0] = fmax (df[0], fabs (fdc - He[r]));
          df[2] = fmax (df[2], fabs (fdr - (He[r] - kr)));
          df[3] = fmax (df[3], fabs (fdc));
        }
      for (size_t i = 0; i < k; i++)
        {
          double fdd = (dp[i] - dm[i]) / (2 * FD_H), b = entry (t->B, j, i);
          mx[1] = fmax (mx[1], fabs (b));
          df[1] = fmax (df[1], fabs (fdd + b));
          df[4] = fmax (df[4], fabs (fdd + entry (C, j, i)));
        }
    }
  for (int q = 0; q < 5; q++)
    {
      double s = mx[q == 3 ? 0 : q == 4 ? 1 : q];
      err[q] = s > 0 ? df[q] / s : df[q];
    }
  lac_contact_tangent_free (t);
  lac_csc_free (C);
  free (Cl), free (d), free (Clp), free (Clm), free (dp), free (dm);
  free (Fp), free (Fm), free (K), free (Up), free (e), free (He);
}

/* Body of every node: 1 if a cell of the volume group `up` holds it. */
static char *
node_body (const lac_mesh *m, const char *up)
{
  char *b = calloc (m->nnodes, 1);
  int gi = -1;
  for (size_t g = 0; g < m->ngroups; g++)
    if (!strcmp (m->group[g].name, up))
      gi = (int) g;
  for (size_t c = 0; c < m->ncells; c++)
    if (m->body[c] == gi)
      for (size_t p = m->ptr[c]; p < m->ptr[c + 1]; p++)
        b[m->conn[p]] = 1;
  return b;
}

/* Two boxes: the lower one (the master, wider) and the upper one (the
 * slave), or one box (against the obstacle). */
static lac_mesh *
make_mesh (lac_elem_type type, int two)
{
  int dim = lac_refelem_get (type)->dim;
  size_t nlo[3] = { 5, 3, 2 }, nup[3] = { 3, 2, 1 };
  double Llo[3] = { 1.4, 1, 1 }, Lup[3] = { 1, 0.5, 0.5 };
  if (dim == 3)
    {
      nlo[0] = nlo[1] = 4, nup[0] = nup[1] = 2, Llo[1] = 1.4, Lup[1] = 1;
      if (!two)
        nup[0] = nup[1] = 2, nup[2] = 1;
    }
  lac_mesh *lo = NULL, *up = NULL, *m = NULL;
  lac_mesh_box (type, nup, Lup, 0.0, &up);
  if (!two)
    {
      for (size_t a = 0; a < up->nnodes; a++)
        up->x[a * dim] += 0.2;                       /* r > 0 */
      return up;
    }
  lac_mesh_box (type, nlo, Llo, 0.0, &lo);
  for (size_t a = 0; a < lo->nnodes; a++)
    for (int c = 0; c < dim - 1; c++)
      lo->x[a * dim + c] -= 0.2;
  for (size_t a = 0; a < up->nnodes; a++)
    up->x[a * dim + dim - 1] += 1.0;
  lac_mesh_merge (lo, "lo.", up, "up.", &m);
  lac_mesh_free (lo);
  lac_mesh_free (up);
  return m;
}

/* The deformed state: the slave body randomly deformed, shifted down and
 * turned a little; the master body by an affine map. */
static double *
deformed (const lac_mesh *m, int two, unsigned seed)
{
  int dim = m->dim, v = dim - 1;
  size_t n = (size_t) dim * m->nnodes;
  double *U = malloc (n * sizeof *U);
  char *up = two ? node_body (m, "up.body") : NULL;
  double A[3][3] = { { 0.01, 0.02, -0.01 }, { -0.02, 0.015, 0.01 },
                     { -0.03, 0.02, 0.01 } };
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *X = m->x + a * (size_t) dim;
      for (int c = 0; c < dim; c++)
        {
          double u = 0;
          if (!two || up[a])
            {
              u = 0.02 * rnd (&seed) + (c == v ? -0.006 : 0.0);
              u += c == v ? 0.03 * (X[0] - 0.5) : -0.03 * (X[v] - 1.0);
            }
          else
            for (int k = 0; k < dim; k++)
              u += A[c][k] * X[k];
          U[a * (size_t) dim + c] = u;
        }
    }
  free (up);
  return U;
}

static void
run_case (const char *name, lac_elem_type type, int two, lac_model model,
          int slave_normal)
{
  fdcase fc;
  memset (&fc, 0, sizeof fc);
  fc.name = name;
  fc.m = make_mesh (type, two);
  int dim = fc.m->dim;
  const char *slave = two ? (dim == 2 ? "up.ymin" : "up.zmin")
                          : (dim == 2 ? "ymin" : "zmin");
  check_status (lac_macromesh_build (&fc.m, slave, NULL, &fc.M), LAC_SUCCESS,
                "%s: macro-mesh", name);
  if (two)
    fc.master = lac_pairing_facets_of (fc.m, lac_mesh_group (fc.m, dim == 2
                                       ? "lo.ymax" : "lo.zmax"));
  fc.ob = (lac_obstacle) { dim, -0.01, { -0.05, -0.08 }, { 0.7, 0.6 },
                          slave_normal };
  fc.E = malloc (fc.m->ncells * sizeof *fc.E);
  fc.nu = malloc (fc.m->ncells * sizeof *fc.nu);
  for (size_t c = 0; c < fc.m->ncells; c++)
    fc.E[c] = 300, fc.nu[c] = 0.3;
  fc.mat = (lac_hyper) { model, fc.E, fc.nu, NULL, 0 };
  unsigned seed = 12345;
  fc.lambda = malloc (fc.M->n * sizeof *fc.lambda);
  for (size_t q = 0; q < fc.M->n; q++)
    fc.lambda[q] = -50 * (1 + 0.5 * rnd (&seed));
  double *U = deformed (fc.m, two, 777), err[5];
  compare (&fc, U, err);
  check_true (err[0] <= TOL, "%s: H against d(C lambda)/dU: %.2e", name,
              err[0]);
  check_true (err[1] <= TOL, "%s: B against -d(d)/dU: %.2e", name, err[1]);
  check_true (err[2] <= TOL, "%s: -K_T + H against dR/dU: %.2e", name,
              err[2]);
  check_true (err[3] > 0.5 && err[4] > 1e-3, "%s: the frozen tangent "
              "fails the same check (H %.2e, B %.2e)", name, err[3], err[4]);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%-22s H %.2e  B %.2e  full %.2e  frozen: H %.2e  B %.2e\n",
            name, err[0], err[1], err[2], err[3], err[4]);
  free (U);
  free (fc.lambda);
  free (fc.E);
  free (fc.nu);
  lac_macromesh_free (fc.M);
  lac_mesh_free (fc.m);
}

int
main (void)
{
  lac_init ();
  run_case ("2D quad4 / quad4", LAC_QUAD4, 1, LAC_PLANE_STRAIN, 0);
  run_case ("3D hex8 / hex8", LAC_HEX8, 1, LAC_SOLID3D, 0);
  run_case ("axisym. quad8 / obstacle", LAC_QUAD8, 0, LAC_AXISYMMETRIC, 0);
  run_case ("3D hex20 / obstacle", LAC_HEX20, 0, LAC_SOLID3D, 0);
  run_case ("axisym. quad8 / obst. n^S", LAC_QUAD8, 0, LAC_AXISYMMETRIC, 1);
  run_case ("3D hex20 / obst. n^S", LAC_HEX20, 0, LAC_SOLID3D, 1);
  lac_finalize ();
  return check_summary ();
}
