/* lac_assembly.h -- stiffness, loads and Dirichlet data          [LAC §2, §4.3]
 *
 * The bilinear form a(u,v) = sum_l int A eps(u):eps(v)  and the linear form
 * l(v) = int f.v + int_{Gamma_N} F.v  of [LAC (8)], discretized on the mesh:
 * K (triplets, then CSC) and the load vector F (length ndof = dim*nnodes,
 * dof = dim*node + component).  Axisymmetric integrals carry the weight
 * 2*pi*r.  Element routines are pure functions of element data; the
 * contact terms C^S, C^M and the mean gaps [LAC (16)-(18)] join this module
 * with the contact core.
 *
 * Ownership: inputs are borrowed; outputs are caller-allocated or
 * caller-freed (_alloc/_free).
 */
#ifndef LAC_ASSEMBLY_H
#define LAC_ASSEMBLY_H

#include <stddef.h>
#include "linalg/lac_linalg.h"
#include "fem/lac_frames.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"
#include "fem/lac_quadrature.h"

/* A vector field given by a function: out[0..dim-1] = f(x). */
typedef void lac_field (const double *x, void *ctx, double *out);
/* A field that depends on the outward unit normal n at x (tractions). */
typedef void lac_field_n (const double *x, const double *n, void *ctx,
                          double *out);
/* Its gradient: out[i*dim + k] = d f_i / d x_k. */
typedef void lac_field_grad (const double *x, void *ctx, double *out);

/* Per-cell material: E[c], nu[c] (arrays of length mesh->ncells). */
typedef struct lac_elastic
{
  lac_model model;
  const double *E;   /* borrowed, ncells */
  const double *nu;  /* borrowed, ncells */
} lac_elastic;

/* Element stiffness of cell c: Ke (nen*dim)^2, row-major, dofs ordered
 * (node a, component i) -> a*dim + i.  Returns LAC_ESING if det J <= 0. */
int lac_assembly_cell_stiffness (const lac_mesh *m, const lac_elastic *mat,
                                 size_t c, double *Ke);
/* The same with the caller's cache of quadrature rules (a loop over many
 * cells; fem/lac_quadrature.h). */
int lac_assembly_cell_stiffness_q (const lac_mesh *m, const lac_elastic *mat,
                                   size_t c, lac_quad_cache *qc, double *Ke);

/* K += sum_c Ke (all cells with E[c] > 0). */
int lac_assembly_stiffness (const lac_mesh *m, const lac_elastic *mat,
                            lac_triplet *K);
/* The same K, built straight into its compressed columns: the pattern
 * from the mesh, then each Ke added in place (fem/lac_pattern.h: no
 * triplet list, no sort; the same entries and sums as through triplets).
 * *K: a new ndof x ndof matrix, the caller's to free. */
int lac_assembly_stiffness_csc (const lac_mesh *m, const lac_elastic *mat,
                                lac_csc **K);

/* F += int_{cells of group g (or all cells if g == NULL)} f . v */
int lac_assembly_volume_force (const lac_mesh *m, lac_model model,
                               const lac_group *g, lac_field *f, void *ctx,
                               double *F);
/* F += int_{facets of g} t . v, traction t(x) given by a field. */
int lac_assembly_traction (const lac_mesh *m, lac_model model,
                           const lac_group *g, lac_field *t, void *ctx,
                           double *F);
/* The same with a traction t(x, n) depending on the outward normal. */
int lac_assembly_traction_n (const lac_mesh *m, lac_model model,
                             const lac_group *g, lac_field_n *t, void *ctx,
                             double *F);
/* F += int_{facets of g} (-p n) . v  (pressure p > 0 pushes inward). */
int lac_assembly_pressure (const lac_mesh *m, lac_model model,
                           const lac_group *g, double p, double *F);

/* Dirichlet data: list of (dof, value); later entries for a dof win.
 * With frames (rollers on inclined or curved faces, fem/lac_frames.h),
 * the dofs of a node with a frame are its components along the frame's
 * axes: K, F and C must be rotated to the frames (lac_frames_rotate_*,
 * lac_frames_to_local) before the entries are eliminated, and the
 * solution rotated back (lac_frames_to_global). */
typedef struct lac_dirichlet
{
  size_t n, cap;
  size_t *dof;    /* owned */
  double *val;    /* owned */
  lac_frames *frames;  /* owned, or NULL: every dof along the axes */
} lac_dirichlet;

lac_dirichlet *lac_dirichlet_alloc (void);
void lac_dirichlet_free (lac_dirichlet *d);     /* and its frames */
/* One more entry: dof fixed to val. */
int lac_dirichlet_add (lac_dirichlet *d, size_t dof, double val);
/* Fix component comp (0..dim-1) of every node of group g to `value`. */
int lac_dirichlet_add_group (lac_dirichlet *d, const lac_mesh *m,
                             const lac_group *g, int comp, double value);
/* Fix every component of the nodes of g to the field u(x) (manufactured
 * solutions, patch tests). */
int lac_dirichlet_add_field (lac_dirichlet *d, const lac_mesh *m,
                             const lac_group *g, lac_field *u, void *ctx);
/* Symmetric elimination: for each fixed dof k with value g_k,
 * F -= K(:,k) g_k, then row and column k of K are zeroed except the
 * diagonal, which keeps its value d_k (1 if it was <= 0; a unit diagonal
 * next to stiffnesses of size E h would spoil the pivot tests), and
 * F(k) = d_k g_k.  K stays symmetric (positive definite if the body is
 * fixed against rigid motions).  Works on the CSC in place. */
int lac_dirichlet_apply (const lac_dirichlet *d, lac_csc *K, double *F);
/* lac_dirichlet_apply for one column only: column jl of K, which is dof
 * j (rows are dofs), with fixed[] and g[] of lac_dirichlet_dense; g[j]
 * becomes d_j g_j, F(j) is left to the caller.  Column by column in dof
 * order it gives lac_dirichlet_apply's numbers. */
int lac_dirichlet_column (lac_csc *K, size_t jl, size_t j, const char *fixed,
                          double *g, double *F);
/* The pairs of d as dense arrays of n dofs: fixed[k] = 1 and g[k] the
 * value (later pairs win), new (the caller frees them, also on error). */
int lac_dirichlet_dense (const lac_dirichlet *d, size_t n, char **fixed,
                         double **g);

#endif /* LAC_ASSEMBLY_H */
