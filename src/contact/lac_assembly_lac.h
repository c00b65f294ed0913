/* lac_assembly_lac.h -- the LAC matrices and mean gaps
 *                                                 [LAC (16)-(18), §4.3]
 *
 * Item 2 of lac_contact_build (lac_contact.h): for the k admissible
 * macro-elements of c, the columns of C = C^S - C^M, the mean initial
 * gaps G and the areas |T^m cap Gamma_C| (lac_assembly_lac.c).
 */
#ifndef LAC_ASSEMBLY_LAC_H
#define LAC_ASSEMBLY_LAC_H

#include "contact/lac_contact_types.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_pairing.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

/* C, G and area of c for its k multipliers (c->macro[0..k-1], from
 * lac_admissibility_compute); c->C is replaced.  Master facets are given
 * by `master` (of the same mesh), or master is NULL for a rigid obstacle
 * (no master part in C).  LAC_EINVAL (master of another mesh),
 * LAC_ENOMEM, LAC_ESANITY. */
int lac_assembly_lac (lac_contact *c, const lac_mesh *mesh, lac_model model,
                      const lac_macro *M, const lac_pairing *P,
                      const lac_pairing_facets *master);

#endif /* LAC_ASSEMBLY_LAC_H */
