/* lac_run_setup.h -- stage 2 of a run: the contact set-up
 *                                           [LAC Hyp. 1, §4.4, §4.6, Rem. 3]
 * In:  the scene's [contact] section, the mesh (refined here: the first
 *      layer of slave cells is cut where Hypothesis 1 needs it, so the
 *      mesh is replaced).
 * Out: the macro-mesh of the slave group (contact/lac_macromesh.h); the
 *      master facets or the rigid obstacle; for a linear scene the pairing
 *      of the slave sub-facets with them (contact/lac_pairing.h), which a
 *      large-deformation scene recomputes at every Newton iteration
 *      instead [LAC Remark 3]; the nodes on a contact surface (their
 *      bodies may be held by contact alone).
 * A scene without [contact] gets an empty set-up: no search, no pairing.
 * The set-up points into the mesh: it must not move after this stage.
 */
#ifndef LAC_RUN_SETUP_H
#define LAC_RUN_SETUP_H

#include <stddef.h>
#include "contact/lac_contact_pair.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_obstacle.h"
#include "contact/lac_pairing.h"
#include "io/lac_scene.h"

typedef struct lac_run_setup
{
  lac_macro *macro;            /* owned, NULL without [contact]           */
  lac_pairing *pairing;        /* owned: linear scenes only (else NULL)   */
  lac_pairing_facets master;   /* points into the mesh; n = 0: obstacle   */
  lac_obstacle obstacle;       /* the rigid master when master.n = 0      */
  lac_contact_pair pair;       /* all of it, for pairing again (points
                                  into the mesh and the fields above)     */
  char *on_contact;            /* owned, nnodes: node on a contact surface */
  double time_refine;          /* seconds: macro-mesh and refinement      */
  double time_pairing;         /* seconds: pairing                        */
} lac_run_setup;

/* large: 1 for a large-deformation scene (no pairing here).  *mesh is
 * replaced by its refinement. */
int lac_run_setup_build (const lac_scene *sc, int large, lac_mesh **mesh,
                         lac_run_setup *s, char *progress, size_t size);
void lac_run_setup_clear (lac_run_setup *s);

#endif /* LAC_RUN_SETUP_H */
