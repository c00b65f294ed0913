/* lac_admissibility.h -- which macro-elements carry a multiplier
 *                                                 [LAC Def. 1, Remark 1]
 *
 * Item 1 of lac_contact_build (lac_contact.h): for every macro-element T^m
 * its covered fraction delta = |T^m cap Gamma_C| / |T^m| and the mean
 * phibar of its interior basis function over T^m cap Gamma_C; T^m is
 * admissible iff phibar sqrt(delta) >= epsilon (lac_admissibility.c).
 */
#ifndef LAC_ADMISSIBILITY_H
#define LAC_ADMISSIBILITY_H

#include "contact/lac_contact_types.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_pairing.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

/* meas, covered, inode, phiint, crit, admissible, mult, k and macro of c,
 * which must have nmacro = M->n and those arrays allocated
 * (lac_contact_alloc).  The pairing's slave list must be the sub-facets of
 * M in order.  LAC_EINVAL (epsilon outside (0, 1], list mismatch),
 * LAC_ENOMEM, LAC_ESANITY.  k = 0 is not an error here. */
int lac_admissibility_compute (lac_contact *c, const lac_mesh *mesh,
                               lac_model model, const lac_macro *M,
                               const lac_pairing *P, double epsilon);

#endif /* LAC_ADMISSIBILITY_H */
