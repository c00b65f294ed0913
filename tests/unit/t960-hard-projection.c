/* t960: hard case -- a slave point whose Newton projection diverges
 *                                      [LAC §4.6 item 2; issue 6 item 3]
 *
 * 1. lac_pairing_project on strongly curved faces -- a seg3 arch whose
 *    middle node is 3 facet lengths above the chord, a folded seg3 whose
 *    middle node lies beyond an end (x(xi) not monotone), a quad9 dome
 *    (centre node 3 sizes up) and a saddle -- from a grid of points up to
 *    1e6 away, along 8 directions and by closest point.  Every call must
 *    return LAC_SUCCESS with a true solution (|X(xi) - x - t dir| <= 1e-8
 *    |x|, or the closest point's optimality), or LAC_EMAXITER / LAC_ESING
 *    with a one-line message; an iteration count in the message is at most
 *    50 (PROJ_MAXITER), so that nothing loops (the time of the grid, about
 *    10^4 calls, is printed with LAC_TEST_VERBOSE, not asserted: a
 *    wall-clock limit fails on a loaded machine; speed is benchmarked).
 * 2. The pairing with such a geometry: the master is the top of quad9
 *    cells whose top middle nodes are folded sideways / raised, the slave
 *    the bottom of a block above (2D), and a hex27 master face with its
 *    centre node raised 2 h, and hex27 master faces folded over themselves
 *    (mid-edge nodes shifted by 1.2 h along the face: many projections
 *    fail) (3D).  lac_pairing_build must return: either
 *    LAC_SUCCESS (points that fail to project drop their pair, counted in
 *    P->nfail -- asserted > 0 for the folded faces -- and every point kept
 *    is finite) or an error with a one-line message; and then the contact
 *    stage must either build finite C and G or stop with a message.
 *    (lac run does not report P->nfail: a dropped pair lowers the covered
 *    fraction silently.)
 */
#include "t95-hard.h"
#include "contact/lac_pairing_project.h"

/* the largest integer n in "N iteration(s)" or "iteration N" (-1: none) */
static int
msg_iterations (const char *m)
{
  int best = -1;
  for (const char *p = m; (p = strstr (p, "iteration")); p++)
    {
      const char *q = p;
      while (q > m && q[-1] == ' ')
        q--;
      const char *e = q;
      while (q > m && q[-1] >= '0' && q[-1] <= '9')
        q--;
      if (q < e)
        best = (int) fmax (best, atoi (q));
      const char *a = p + strlen ("iteration");
      if (*a == 's')
        a++;
      while (*a == ' ')
        a++;
      if (*a >= '0' && *a <= '9')
        best = (int) fmax (best, atoi (a));
    }
  return best;
}

typedef struct tally
{
  long ok, maxiter, sing, other, bad_sol, bad_msg, calls;
} tally;

static void
one (const lac_refelem *re, const double *xe, const double *x,
     const double *dir, tally *T, const char *what)
{
  int sdim = re->dim + 1, d = re->dim;
  double xi[2] = { re->shape == LAC_SHAPE_TRI ? 1.0 / 3 : 0,
                   re->shape == LAC_SHAPE_TRI ? 1.0 / 3 : 0 }, t = NAN;
  lac_error_clear ();
  int st = lac_pairing_project (re, sdim, xe, x, dir, xi, &t);
  T->calls++;
  if (st == LAC_SUCCESS)
    {
      lac_map m;
      lac_map_face (re, sdim, xe, xi, &m);
      double r = 0, xm = 0;
      for (int i = 0; i < sdim; i++)
        xm = fmax (xm, fabs (x[i]));
      if (dir)
        for (int i = 0; i < sdim; i++)
          r = fmax (r, fabs (m.x[i] - x[i] - t * dir[i]));
      else                     /* (x - X) orthogonal to the tangents */
        for (int k = 0; k < d; k++)
          {
            double s = 0, tn = 0;
            for (int i = 0; i < sdim; i++)
              s += (x[i] - m.x[i]) * m.J[i * d + k],
                tn += m.J[i * d + k] * m.J[i * d + k];
            r = fmax (r, fabs (s) / sqrt (tn));
          }
      int good = isfinite (t) && isfinite (xi[0]) && isfinite (xi[d - 1])
        && r <= 1e-8 * fmax (xm, 1.0);
      T->ok++;
      if (!good)
        {
          T->bad_sol++;
          if (T->bad_sol <= 3)
            printf ("%s: x = (%g, %g, %g): success with residual %.3g\n",
                    what, x[0], x[1], sdim == 3 ? x[2] : 0.0, r);
        }
      return;
    }
  if (st == LAC_EMAXITER)
    T->maxiter++;
  else if (st == LAC_ESING)
    T->sing++;
  else
    T->other++;
  const char *msg = lac_error_message ();
  int it = msg_iterations (msg);
  if (!*msg || strchr (msg, '\n') || it > 50)
    {
      T->bad_msg++;
      if (T->bad_msg <= 3)
        printf ("%s: status %d, message '%s'\n", what, st, msg);
    }
}

static void
grid (const lac_refelem *re, const double *xe, const char *what)
{
  int sdim = re->dim + 1;
  tally T = { 0 };
  double t0 = hard_now ();
  const double R[] = { 0.3, 3, 30, 1e3, 1e6 };
  for (int r = 0; r < 5; r++)
    for (int a = 0; a < 16; a++)
      for (int b = 0; b < (sdim == 3 ? 8 : 1); b++)
        {
          double th = 2 * 3.14159265358979 * (a + 0.37) / 16;
          double ph = sdim == 3 ? 3.14159265358979 * (b + 0.5) / 8 : 0;
          double x[3];
          if (sdim == 2)
            x[0] = 0.5 + R[r] * cos (th), x[1] = R[r] * sin (th);
          else
            x[0] = 0.5 + R[r] * cos (th) * sin (ph),
              x[1] = 0.5 + R[r] * sin (th) * sin (ph), x[2] = R[r] * cos (ph);
          one (re, xe, x, NULL, &T, what);
          for (int k = 0; k < 8; k++)
            {
              double al = 2 * 3.14159265358979 * k / 8 + 0.1;
              double dir[3] = { cos (al), sin (al), 0 };
              if (sdim == 3)
                dir[0] *= 0.6, dir[1] *= 0.6, dir[2] = (k & 1) ? 0.8 : -0.8;
              one (re, xe, x, dir, &T, what);
            }
        }
  double sec = hard_now () - t0;
  check_true (T.bad_sol == 0, "%s: %ld successes that are not solutions",
              what, T.bad_sol);
  check_true (T.bad_msg == 0, "%s: %ld failures without a proper message",
              what, T.bad_msg);
  check_true (T.other == 0, "%s: %ld other statuses", what, T.other);
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: %ld calls: %ld success, %ld EMAXITER, %ld ESING (%.3f s)\n",
            what, T.calls, T.ok, T.maxiter, T.sing, sec);
  char st[160];
  snprintf (st, sizeof st, "%s: %ld success, %ld EMAXITER, %ld ESING in "
            "%.2f s", T.bad_sol || T.bad_msg || T.other ? "FAILS" : "ok",
            T.ok, T.maxiter, T.sing, sec);
  char name[96];
  snprintf (name, sizeof name, "projection grid, %s", what);
  hard_row_raw (name, -1, -1, -1, NULL, 0, st);
}

/* ---- 2. the whole pairing --------------------------------------------- */

typedef struct bendctx { int mode; double amp; } bendctx;

/* deform the top edge's middle nodes of the lower quad9 block (y = 50):
 * mode 0: fold sideways by amp (x += amp where the node is a mid-edge
 * node), mode 1: raise the mid-edge nodes by amp. 2D, cells 25 wide. */
static void
fold (double *x, const void *ctx)
{
  const bendctx *b = ctx;
  double h = 25;
  if (fabs (x[1] - 50) > 1e-12)
    return;
  double r = fmod (x[0], h);
  if (fabs (r - h / 2) > 1e-9)
    return;                            /* a vertex */
  if (b->mode == 0)
    x[0] += b->amp;
  else
    x[1] += b->amp;
}

/* 3D: raise the centre node of each top face of the hex27 block */
static void
dome (double *x, const void *ctx)
{
  const bendctx *b = ctx;
  double h = 25;
  if (fabs (x[2] - 50) > 1e-12)
    return;
  double rx = fmod (x[0], h), ry = fmod (x[1], h);
  if (fabs (rx - h / 2) < 1e-9 && fabs (ry - h / 2) < 1e-9)
    x[2] += b->amp;
}

/* 3D: shift the mid-edge nodes of the top faces of the hex27 block
 * tangentially by amp (> h/2: the quad9 faces fold over themselves) and
 * raise the centre nodes by 0.3 amp */
static void
edge3 (double *x, const void *ctx)
{
  const bendctx *b = ctx;
  double h = 25;
  if (fabs (x[2] - 50) > 1e-12)
    return;
  double rx = fmod (x[0], h), ry = fmod (x[1], h);
  int mx = fabs (rx - h / 2) < 1e-9, my = fabs (ry - h / 2) < 1e-9;
  if (mx && !my)
    x[0] += b->amp;
  if (my && !mx)
    x[1] += b->amp;
  if (mx && my)
    x[2] += 0.3 * b->amp;
}

static void
pairing_case (const char *name, lac_elem_type tm,
              void (*map) (double *, const void *), const bendctx *bc,
              int want_fail)
{
  int dim = lac_refelem_get (tm)->dim;
  hard_body lo = { tm, { 2, 1, 1 }, { 50, 50, 50 }, { 0, 0, 0 }, 2000, 0.3,
                   map, bc };
  if (dim == 3)
    lo.n[1] = 2;
  hard_body up = { dim == 2 ? LAC_QUAD4 : LAC_HEX8, { 7, 7, 2 },
                   { 50, 50, 50 }, { 0, 0, 0 }, 2000, 0.3, NULL, NULL };
  if (dim == 2)
    up.n[1] = 2;
  up.shift[dim - 1] = 50;
  lac_mesh *a = NULL, *b = NULL, *m = NULL;
  lac_macro *M = NULL;
  lac_pairing *P = NULL;
  lac_contact *c = NULL;
  double t0 = hard_now ();
  hard_box (&lo, &a);
  hard_box (&up, &b);
  lac_mesh_merge (a, "lo.", b, "up.", &m);
  lac_mesh_free (a);
  lac_mesh_free (b);
  int st = lac_macromesh_build (&m, dim == 2 ? "up.ymin" : "up.zmin", NULL, &M);
  check_status (st, LAC_SUCCESS, "%s: macromesh", name);
  lac_pairing_facets S = { m, M->ptr[M->n], M->cell, M->face };
  lac_pairing_facets Mf = lac_pairing_facets_of (m, lac_mesh_group
                                                 (m, dim == 2 ? "lo.ymax"
                                                  : "lo.zmax"));
  lac_pairing_opts po;
  lac_pairing_opts_init (&po);
  lac_error_clear ();
  st = lac_pairing_build (&S, &Mf, &po, &P);
  char status[400];
  long k = -1;
  if (st)
    {
      const char *msg = lac_error_message ();
      check_true (*msg && !strchr (msg, '\n'), "%s: pairing stops with a "
                  "one-line message: '%s'", name, msg);
      snprintf (status, sizeof status, "%s, stops: pairing %s: %s",
                *msg && !strchr (msg, '\n') ? "ok" : "FAILS",
                hard_stname (st), msg);
    }
  else
    {
      int fin = 1;
      for (size_t p = 0; p < P->npoints; p++)
        fin &= isfinite (P->w[p]) && isfinite (P->gap[p])
          && isfinite (P->xm[p * (size_t) (dim - 1)]);
      check_true (fin, "%s: finite points", name);
      if (want_fail)
        check_true (P->nfail > 0, "%s: failed projections reported (nfail "
                    "%zu)", name, P->nfail);
      int cst = lac_contact_build (m, dim == 2 ? LAC_PLANE_STRAIN : LAC_SOLID3D,
                                   M, P, &Mf, LAC_EPSILON_DEFAULT, &c);
      if (!cst)
        {
          for (size_t i = 0; i < c->k; i++)
            fin &= isfinite (c->G[i]);
          for (int q = 0; q < c->C->p[c->k]; q++)
            fin &= isfinite (c->C->x[q]);
          check_true (fin, "%s: finite C, G", name);
          k = (long) c->k;
        }
      else
        check_true (*lac_error_message () != 0, "%s: contact stops with a "
                    "message", name);
      snprintf (status, sizeof status, "%s: pairing ok, %zu points, %zu pairs "
                "dropped (nfail)%s%s", fin ? "ok" : "FAILS", P->npoints,
                P->nfail, cst ? "; contact stops: " : "",
                cst ? lac_error_message () : "");
    }
  double sec = hard_now () - t0;
  if (getenv ("LAC_TEST_VERBOSE"))
    printf ("%s: %s (%.3f s)\n", name, status, sec);
  hard_row_raw (name, k, -1, -1, NULL, 0, status);
  lac_contact_free (c);
  lac_pairing_free (P);
  lac_macromesh_free (M);
  lac_mesh_free (m);
}

/* face element nodes */
static void
seg3 (double *xe, double mx, double my)
{
  double v[6] = { 0, 0, 1, 0, mx, my };
  memcpy (xe, v, sizeof v);
}

int
main (void)
{
  lac_init ();
  const lac_refelem *s3 = lac_refelem_get (LAC_SEG3);
  const lac_refelem *q9 = lac_refelem_get (LAC_QUAD9);
  double xe[LAC_MAX_FACE_NODES * 3];
  seg3 (xe, 0.5, 3.0);
  grid (s3, xe, "seg3 arch (middle node 3 up)");
  seg3 (xe, 1.6, 0.4);
  grid (s3, xe, "seg3 folded back");
  /* quad9: corners of the unit square, mid-edge nodes, centre raised */
  for (int a = 0; a < 9; a++)
    {
      xe[3 * a] = 0.5 * (1 + q9->xi[2 * a]);
      xe[3 * a + 1] = 0.5 * (1 + q9->xi[2 * a + 1]);
      xe[3 * a + 2] = a == 8 ? 3.0 : 0.0;
    }
  grid (q9, xe, "quad9 dome (centre 3 up)");
  for (int a = 0; a < 9; a++)
    xe[3 * a + 2] = 1.5 * q9->xi[2 * a] * q9->xi[2 * a + 1]
      + (a >= 4 ? 0.8 * q9->xi[2 * a] : 0);
  grid (q9, xe, "quad9 saddle");
  bendctx f0 = { 0, 20.0 }, f1 = { 1, 30.0 }, f2 = { 1, -12.0 };
  bendctx d3 = { 0, 50.0 }, e3 = { 0, -30.0 };
  pairing_case ("pairing, quad9 master folded sideways", LAC_QUAD9, fold, &f0,
                0);
  pairing_case ("pairing, quad9 master arched up into the slave", LAC_QUAD9,
                fold, &f1, 0);
  pairing_case ("pairing, quad9 master sagging", LAC_QUAD9, fold, &f2, 0);
  pairing_case ("pairing, hex27 master faces domed 2 h", LAC_HEX27, dome,
                &d3, 0);
  pairing_case ("pairing, hex27 master faces folded over", LAC_HEX27, edge3,
                &e3, 1);
  lac_finalize ();
  return check_summary ();
}
