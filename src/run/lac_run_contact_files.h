/* lac_run_contact_files.h -- contact.csv and contact.vtu of a linear run
 *                                                    [LAC (16)-(18); §5]
 *
 * Part of stage 7 (output) of a linear run with contact.
 *
 * contact.csv: one row per macro-element (node-to-segment: per slave node)
 *   macro,x,y,z,measure,covered,criterion,admissible,multiplier,lambda,
 *   lambda_exact,mean_gap,active,s,force_x,force_y,force_z,pair
 * x, y, z: the position (run/lac_run_contact.h; axisymmetric x = r,
 * y = z); measure |T^m|, covered |T^m cap Gamma_C| (2 pi r dGamma
 * axisymmetric), criterion and admissible of Definition 1; multiplier
 * (its index), lambda, mean_gap (d_i / |T^m cap Gamma_C|), active (1 in
 * contact, 0 not) for the macro-elements that carry one; lambda_exact the
 * mean of the exact n.sigma.n over T^m cap Gamma_C with an [exact]
 * solution; s the curvilinear abscissa (2D); force_* the force f_i the
 * master exerts through T^m (its sum is the resultant); pair the NAME of
 * the [contact NAME] section of the macro-element (several pairs: macro
 * is the slot, pair p's from the set's offset[p] on).  A field with no
 * value is empty (z in 2D, s in 3D, the multiplier columns of a
 * macro-element without one, lambda_exact without [exact]); never a 0
 * that stands for nothing.
 *
 * contact.vtu: the slave surface (its sub-facets, as VTK cells of
 *   dimension dim - 1), point data displacement, cell data macro (the
 *   macro-element of the facet), lambda, mean_gap (NaN without a
 *   multiplier), status (1 active, 0 inactive, -1 no multiplier), pair
 *   (cell data: the index of the facet's [contact] section in the scene,
 *   from 0);
 *   node-to-segment: lambda, mean_gap and status are point data at the
 *   slave nodes instead.  Binary unless ascii (io/lac_vtu.h).
 */
#ifndef LAC_RUN_CONTACT_FILES_H
#define LAC_RUN_CONTACT_FILES_H

#include "run/lac_run_contact.h"
#include "run/lac_run_multipliers.h"

/* What both files read (everything borrowed). */
typedef struct lac_run_contact_data
{
  lac_model model;
  const lac_mesh *mesh;
  const lac_run_setup *setup;
  const lac_contact *contact;
  const lac_newton *newton;
  const lac_run_multipliers *mult;
  const lac_run_contact *where;
  int has_exact;                  /* the scene has an [exact] solution   */
  const lac_scene *sc;            /* its [contact NAME] sections         */
  const double *u;                /* ndof                                */
} lac_run_contact_data;

int lac_run_contact_csv (const lac_run_contact_data *d, const char *path);
int lac_run_contact_vtu (const lac_run_contact_data *d, int ascii,
                         const char *path);

#endif /* LAC_RUN_CONTACT_FILES_H */
