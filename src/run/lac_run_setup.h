/* lac_run_setup.h -- stage 2 of a run: the contact set-up
 *                                           [LAC Hyp. 1, §4.4, §4.6, Rem. 3]
 * In:  the scene's [contact NAME] sections (one per contact pair), the
 *      mesh (refined here: the first layer of slave cells is cut where
 *      Hypothesis 1 needs it, so the mesh is replaced).
 * Out: the macro-mesh of each pair's slave group (contact/lac_macromesh.h:
 *      all slave groups in one pass, so that every index stays valid);
 *      each pair's master facets or rigid obstacle; the pairs as one
 *      contact set (contact/lac_contact_set.h: pair p's macro-elements are
 *      the multipliers offset[p] ..); for a linear scene the pairing of
 *      every pair's slave sub-facets with its master (contact/lac_pairing.h),
 *      which a large-deformation scene recomputes at every Newton
 *      iteration instead [LAC Remark 3]; the nodes on a contact surface
 *      (their bodies may be held by contact alone).
 * The roles are checked on the mesh: a facet is the slave of one pair at
 * most (lac_macromesh_build_set), and never the slave of one pair and the
 * master of another (the same interface constrained twice).
 * Stage 4 (run/lac_run_system.h) adds the contact data of the pairings to
 * `data`; the loop replaces them when it pairs again (lac_newton.h).
 * A scene without [contact] gets an empty set-up: no search, no pairing.
 * The set-up points into the mesh and into itself: neither may move after
 * this stage.
 */
#ifndef LAC_RUN_SETUP_H
#define LAC_RUN_SETUP_H

#include <stddef.h>
#include "contact/lac_contact_set.h"
#include "contact/lac_macromesh.h"
#include "contact/lac_obstacle.h"
#include "contact/lac_pairing.h"
#include "io/lac_scene.h"

typedef struct lac_run_setup
{
  size_t npairs;               /* [contact] sections, 0 without           */
  lac_macro **macro;           /* owned, npairs: the slave macro-meshes   */
  lac_pairing_facets *master;  /* owned array, npairs (each points into the
                                  mesh); master[p].n = 0: an obstacle    */
  lac_obstacle *obstacle;      /* owned, npairs: the rigid masters        */
  lac_contact_pair *pair;      /* owned, npairs: all of it, for pairing
                                  again (points into the arrays above)   */
  lac_contact_set set;         /* the pairs as one problem                */
  lac_contact_set_data data;   /* linear scenes: the pairings (here), the
                                  contact data (stage 4)                 */
  char *on_contact;            /* owned, nnodes: node on a contact surface */
  double time_refine;          /* seconds: macro-mesh and refinement      */
  double time_pairing;         /* seconds: pairing                        */
} lac_run_setup;

/* large: 1 for a large-deformation scene (no pairing here).  *mesh is
 * replaced by its refinement. */
int lac_run_setup_build (const lac_scene *sc, int large, lac_mesh **mesh,
                         lac_run_setup *s, char *progress, size_t size);
void lac_run_setup_clear (lac_run_setup *s);

/* The error of the contact set's pair data->failed, placed at its
 * section (key: the key to point at, or NULL). */
int lac_run_setup_error (const lac_scene *sc, const lac_run_setup *s,
                         const char *key, int status);

#endif /* LAC_RUN_SETUP_H */
