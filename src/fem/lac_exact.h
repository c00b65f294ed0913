/* lac_exact.h -- analytic solutions: errors and `exact` Dirichlet data
 *
 * A solution is one entry of the table in lac_exact.c: its name (the value
 * of [exact] solution in a scene), the models it applies to, a setup that
 * turns the [exact] parameters into coefficients, and u(x), grad u(x).
 * The stress follows from u and grad u by the model's law [LAC (2)], so a
 * new solution (patch test, manufactured solution) gives only those.
 *
 *   lac_exact e;
 *   lac_exact_init (&e, lac_exact_find ("thick_sphere"), model, &params);
 *   lac_exact_u (x, &e, u);          lac_field callbacks: ctx = &e
 *   lac_exact_grad (x, &e, g);       g[i * dim + j] = d u_i / d x_j
 *   lac_exact_sigma (x, &e, s);      Voigt components of the model
 *
 * The kind of a solution is its index in the table; the enum below names
 * the entries that code or tests refer to.
 */
#ifndef LAC_EXACT_H
#define LAC_EXACT_H

#include "fem/lac_material.h"

typedef enum
{
  LAC_EXACT_NONE = -1, LAC_EXACT_THICK_SPHERE = 0, LAC_EXACT_THICK_CYLINDER,
  LAC_EXACT_TAYLOR, LAC_EXACT_MANUFACTURED2D, LAC_EXACT_MANUFACTURED3D,
  LAC_EXACT_BIAXIAL, LAC_EXACT_TAYLOR_SHEAR
} lac_exact_kind;

typedef struct lac_exact_params       /* the keys of [exact] */
{
  double a, b, p;       /* inner, outer radius; inner pressure */
  double E, nu;         /* the material of the solution        */
  double tau;           /* taylor_shear: the shear stress      */
} lac_exact_params;

typedef struct lac_exact              /* a solution ready to evaluate */
{
  int kind;             /* index in the table, LAC_EXACT_NONE       */
  lac_model model;
  int dim;              /* components of u                          */
  lac_exact_params par;
  int nr;               /* radial solutions: coordinates in the radius
                           (u = g(R) x over them); 0 if not radial  */
  int k;                /* radial: g = C1 + C2 / R^k                */
  double C1, C2;
  double c[3];          /* linear solutions: u_i = c_i x_i              */
  double gamma;         /* taylor_shear: u_x += gamma x_v (v the last
                           axis), the shear strain 2 eps_xv = tau / G  */
} lac_exact;

/* An entry of the table; `models` has bit (1 << model) for each model the
 * solution applies to. */
typedef struct lac_exact_solution
{
  const char *name;
  unsigned models;
  const char *params;   /* the [exact] keys it needs: "a b p E nu"     */
  void (*setup) (lac_exact *e);
  void (*u) (const lac_exact *e, const double *x, double *u);
  void (*grad) (const lac_exact *e, const double *x, double *g);
  /* second derivatives h[(i*dim + j)*dim + k] = d2 u_i / dx_j dx_k, or
   * NULL when u solves the equations with no body force */
  void (*hess) (const lac_exact *e, const double *x, double *h);
} lac_exact_solution;

/* The table, terminated by an entry with name NULL (scene files read the
 * names from it). */
extern const lac_exact_solution lac_exact_table[];

/* query */
int lac_exact_count (void);
int lac_exact_find (const char *name);            /* kind, -1 if unknown */
const char *lac_exact_name (int kind);            /* "none" if no such  */
int lac_exact_applies (int kind, lac_model model);

/* Set e up for solution `kind` (LAC_EXACT_NONE: every value zero). */
void lac_exact_init (lac_exact *e, int kind, lac_model model,
                     const lac_exact_params *p);

/* evaluate (signatures of lac_field, ctx = the lac_exact) */
void lac_exact_u (const double *x, void *ctx, double *u);
void lac_exact_grad (const double *x, void *ctx, double *g);
void lac_exact_sigma (const double *x, void *ctx, double *s);
/* The body force f = -div sigma(u) [LAC (1)] (zero without hess). */
void lac_exact_force (const double *x, void *ctx, double *f);
/* The traction sigma(u) n, and its tangential part sigma n - (n.sigma n) n
 * (lac_field_n callbacks). */
void lac_exact_traction (const double *x, const double *n, void *ctx,
                         double *t);
void lac_exact_traction_tangential (const double *x, const double *n,
                                    void *ctx, double *t);
/* n.sigma(u) n, the contact pressure of the exact solution [LAC (6)]. */
double lac_exact_normal_stress (const lac_exact *e, const double *x,
                                const double *n);

/* Radial solutions: R = |x| over the first e->nr coordinates. */
double lac_exact_radius (const lac_exact *e, const double *x);

#endif /* LAC_EXACT_H */
