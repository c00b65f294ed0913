/* lac_contact_types.h -- the LAC contact data of one slave/master pair
 *                                          [LAC Def. 1, (16)-(18), §4.3]
 *
 * Header only.  The struct that the stages fill one after the other: the
 * admissibility of the macro-elements (lac_admissibility.h, item 1 of
 * lac_contact.h), then C, G and the areas of the admissible ones
 * (lac_assembly_lac.h, item 2); lac_contact_build (lac_contact.h) runs
 * both, lac_contact_build_nts fills it for node-to-segment.
 *
 * Ownership: lac_contact_alloc / lac_contact_free (lac_contact.h); the
 * struct owns its arrays and refers to the mesh, macro-mesh and pairing by
 * indices only.
 */
#ifndef LAC_CONTACT_TYPES_H
#define LAC_CONTACT_TYPES_H

#include <stddef.h>
#include "linalg/lac_linalg.h"

typedef struct lac_contact
{
  size_t nmacro;      /* macro-elements of T^M                             */
  double *meas;       /* owned, nmacro: |T^m| (2 pi r weighted if axisym.)  */
  double *covered;    /* owned, nmacro: |T^m cap Gamma_C|                   */
  size_t *inode;      /* owned, nmacro: the interior node x_{m*+1} used, the
                         one of largest int over T^m cap Gamma_C
                         [LAC Remark 1]                                    */
  double *phiint;     /* owned, nmacro: int_{T^m cap Gamma_C} phi_{m*+1}    */
  double *crit;       /* owned, nmacro: phiint / sqrt(covered meas)         */
  char *admissible;   /* owned, nmacro                                     */
  long *mult;         /* owned, nmacro: multiplier index of T^m, -1 if none */
  size_t k;           /* number of multipliers = admissible macro-elements  */
  size_t *macro;      /* owned, k: macro-element of multiplier i            */
  lac_csc *C;         /* owned, ndof x k                     [LAC (16)-(17)] */
  double *G;          /* owned, k: mean initial gaps           [LAC (18)]    */
  double *area;       /* owned, k: |T^m cap Gamma_C| = M^LAC_ii [LAC (16)]
                         (2 pi r weighted if axisym., as G)                */
  double *size;       /* owned, k: the same measure without the weight: a
                         length in 2D and axisym., an area in 3D; h_i, the
                         size of the contact part of the macro-element, is
                         size (2D) or sqrt(size) (3D)                      */
  double *lost;       /* owned, k: the part of T^m cap Gamma_C (a measure,
                         no weight) that the pairing lost to projections
                         that failed (lac_pairing.h): C, G and area miss it */
  double *xpt, *npt;  /* owned, 3k, node-to-segment only (else NULL): the
                         collocation point and unit normal of multiplier i */
  double offset;      /* the interference delta taken from every gap: G_i =
                         int (g0 - delta) (lac_contact_set_offset); 0: none */
  /* Coulomb friction (lac_tangential.h); ntan = 0 and NULL without: */
  int ntan;           /* tangential components of a multiplier: 1 in 2D
                         and axisymmetry, 2 in 3D                          */
  lac_csc *Ct;        /* owned, ndof x k ntan: column i ntan + b holds
                         int (phi^S - phi^M) t_b, so that (Ct^T U)_{i,b} =
                         int [u] . t_b, the mean tangential jump            */
  double *sfix;       /* owned, k ntan: what the fixed dofs' values add to
                         Ct^T U (their rows of Ct are zeroed, like C's)    */
  double *mu;         /* owned, k: the friction coefficient of multiplier i */
} lac_contact;

#endif /* LAC_CONTACT_TYPES_H */
