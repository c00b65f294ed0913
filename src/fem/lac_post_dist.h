/* lac_post_dist.h -- the stresses and errors of a linear run on the
 *                    processes that own the cells  [LAC (2), §5; ch. 13]
 *
 * When the petsc strategy assembled K from the cells on N processes
 * (fem/lac_assembly_dist.h), every process holds the mesh, the material
 * and its share of the cells.  After the solve the root sends them u and
 * the exact solution of the scene, if it has one; each process sums over
 * its own cells the nodal stresses (lac_post_stress_sum) and the squares
 * of the errors (lac_post_error_sums); the sums go to the root
 * (lac_petsc_sum_to_root), which takes the means, the von Mises stresses
 * and the square roots.  The root then holds what lac_post_stress_nodal
 * and lac_post_errors give, up to the order of the sums (the last digits;
 * tests/cases-petsc.sh compares 1, 2 and 4 processes), and writes the
 * output itself: only u and the nodal stresses cross, never the cells'
 * work.
 *
 * Collective: the root calls lac_dist_post with its request (through the
 * strategy: lac_strategy_post), the others (lac_petsc_serve) with NULL.  A failure on one process (an inverted
 * cell, memory) is agreed on by all before the sums (lac_petsc_agree).
 */
#ifndef LAC_POST_DIST_H
#define LAC_POST_DIST_H

#include "fem/lac_assembly_dist.h"
#include "fem/lac_exact.h"

typedef struct lac_post_request
{
  const double *u;          /* the root's displacement, dim * nnodes       */
  const lac_exact *exact;   /* the exact solution, or NULL: no errors      */
  double *sigma, *vm;       /* out: nnodes * ns, nnodes (lac_post.h)       */
  double err[4];            /* out, with exact: ||u - u_h||_0, |u - u_h|_1,
                               ||u||_0, |u|_1                              */
} lac_post_request;

#ifdef LAC_HAVE_PETSC
/* The root: p's outputs from the cells of every process; the others:
 * p NULL.  d must hold the cells (lac_dist_mesh not NULL).
 *   returns LAC_SUCCESS, LAC_EINVAL, LAC_ESING, LAC_ENOMEM, LAC_EDEP */
int lac_dist_post (const lac_dist *d, lac_post_request *p);
#endif

#endif /* LAC_POST_DIST_H */
