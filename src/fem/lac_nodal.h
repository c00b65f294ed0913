/* lac_nodal.h -- nodal averages of a stress computed cell by cell [LAC (2)]
 *
 * A stress computed from the gradient of u_h jumps across cells.  For the
 * results it is averaged at the nodes: the unweighted mean, over the
 * cells sharing a node, of each cell's value at that node (its reference
 * coordinates), and the von Mises stress of the mean.  The law is a
 * function of the cell and the point: the linear law of lac_post.c and
 * the Cauchy stress of the hyperelastic laws of lac_hyper.c both use this
 * loop.  Components as in lac_material.h.
 */
#ifndef LAC_NODAL_H
#define LAC_NODAL_H

#include <stddef.h>
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

/* The stress s[ns] of cell c at reference point xi for the displacement
 * u, by the material `law` (a lac_elastic, a lac_hyper, ...). */
typedef int lac_cell_stress (const lac_mesh *m, const void *law,
                             const double *u, size_t c, const double *xi,
                             double *s);

/* The stress f gives at reference point xi of cell c, s[ns]: f itself,
 * after the checks of the public point functions.  Returns LAC_EINVAL if
 * c is out of range or u, xi or s is NULL, else what f returns. */
int lac_nodal_point (const lac_mesh *m, lac_cell_stress *f, const void *law,
                     const double *u, size_t c, const double *xi,
                     double *s);

/* Nodal averages of the stress f gives (cells with cells[c] != 0 and
 * E[c] > 0; cells may be NULL): sigma[nnodes*ns], vm[nnodes] (may be
 * NULL).  Nodes in no such cell get zeros.  Returns LAC_SUCCESS,
 * LAC_EINVAL (u or sigma NULL, a cell of unknown type), LAC_ENOMEM, or
 * what f returns. */
int lac_nodal_average (const lac_mesh *m, lac_model model, const double *E,
                       const char *cells, lac_cell_stress *f,
                       const void *law, const double *u, double *sigma,
                       double *vm);

/* The two halves of lac_nodal_average, for cells shared out between
 * processes (fem/lac_post_dist.h): lac_nodal_sum adds to sigma[a*ns + k]
 * the stress of each cell at its node a and 1 to count[a] (the caller
 * zeroes them; returns as lac_nodal_average); lac_nodal_mean divides by
 * the counts of the sums of all the cells and sets vm (may be NULL). */
int lac_nodal_sum (const lac_mesh *m, lac_model model, const double *E,
                   const char *cells, lac_cell_stress *f, const void *law,
                   const double *u, double *sigma, double *count);
void lac_nodal_mean (const lac_mesh *m, lac_model model, const double *count,
                     double *sigma, double *vm);

#endif /* LAC_NODAL_H */
