/* lac_post.h -- post-processing: stresses and errors
 *
 * Stresses sigma = A eps(u_h) at the quadrature points, averaged at the
 * nodes (unweighted mean over the cells sharing a node), von Mises;
 * L2 and H1-seminorm errors of u_h against an exact solution; the
 * displacement at a point.  Components as in lac_material.h.
 */
#ifndef LAC_POST_H
#define LAC_POST_H

#include "fem/lac_assembly.h"

/* Stress at reference point xi of cell c: s[ns]. */
int lac_post_stress_at (const lac_mesh *m, const lac_elastic *mat,
                        const double *u, size_t c, const double *xi,
                        double *s);

/* Nodal averages (lac_nodal.h): sigma[nnodes*ns], vm[nnodes] (vm may be
 * NULL).  Nodes in no cell get zeros; cells with E <= 0 are skipped.  If
 * cells != NULL only cells with cells[c] != 0 contribute (per-body
 * averages keep interface jumps). */
int lac_post_stress_nodal (const lac_mesh *m, const lac_elastic *mat,
                           const double *u, const char *cells,
                           double *sigma, double *vm);

/* Errors over all cells: l2 = ||u - u_h||_0, h1 = |u - u_h|_1 (seminorm),
 * also the norms of the exact solution (for relative errors; any output
 * pointer may be NULL).  Quadrature exact to degree 2*order + 2 of the
 * reference element (curved cells: an approximation).  Axisymmetric: the
 * weight 2 pi r, the H1 seminorm includes the hoop term (u_r/r)^2, and the
 * quadrature degree is one higher. */
int lac_post_errors (const lac_mesh *m, lac_model model, const double *u,
                     lac_field *exact, lac_field_grad *grad, void *ctx,
                     double *l2, double *h1, double *l2_exact,
                     double *h1_exact);

/* The halves of the two above for cells shared out between processes
 * (fem/lac_post_dist.h), over the cells with cells[c] != 0 (NULL: all):
 * lac_post_stress_sum adds the sums of lac_nodal_sum to sigma and count
 * (lac_nodal_mean finishes them); lac_post_error_sums gives the squares
 * sq = { ||u - u_h||_0^2, |u - u_h|_1^2, ||u||_0^2, |u|_1^2 } (grad NULL:
 * the H1 terms 0), whose square roots lac_post_error_roots takes once
 * they are summed (outputs may be NULL). */
int lac_post_stress_sum (const lac_mesh *m, const lac_elastic *mat,
                         const double *u, const char *cells, double *sigma,
                         double *count);
int lac_post_error_sums (const lac_mesh *m, lac_model model, const double *u,
                         const char *cells, lac_field *exact,
                         lac_field_grad *grad, void *ctx, double sq[4]);
void lac_post_error_roots (const double sq[4], double *l2, double *h1,
                           double *l2_exact, double *h1_exact);

#endif /* LAC_POST_H */
