/* lac_run_post.h -- stage 6 of a run: the results               [LAC §5]
 *
 * In:  the scene ([exact]), the model, the mesh, the material, the contact
 *      set-up, the system, the solution (linear: U and the active set;
 *      large deformation: U and the records of the load steps), the list
 *      of effects the run simulates.
 * Out: nodal stresses and von Mises (linear: fem/lac_post.h; large
 *      deformation: Cauchy stresses), errors in L2 and H1 against the
 *      exact solution, the multipliers' positions and errors
 *      (run/lac_run_multipliers.h), where the macro-elements are and the
 *      contact forces (run/lac_run_contact.h), and the summary: "name = value" lines
 *      in fixed formats (run/lac_summary.h).  For the radial solutions the
 *      summary also has the mean radial displacement on the inner and
 *      outer surfaces.
 */
#ifndef LAC_RUN_POST_H
#define LAC_RUN_POST_H

#include <stddef.h>
#include "io/lac_scene.h"
#include "run/lac_run_contact.h"
#include "run/lac_run_material.h"
#include "run/lac_run_multipliers.h"
#include "run/lac_run_nonlinear.h"
#include "run/lac_run_setup.h"
#include "run/lac_run_solve.h"
#include "run/lac_run_steps.h"
#include "run/lac_run_system.h"
#include "run/lac_summary.h"

typedef struct lac_run_results
{
  double *sigma;           /* owned, nnodes x ns: nodal stresses         */
  double *vm;              /* owned, nnodes: von Mises                   */
  double *u_exact;         /* owned, ndof, or NULL without [exact]        */
  double err_l2, err_h1, norm_l2, norm_h1;
  lac_run_multipliers mult;   /* with contact (linear scenes)           */
  lac_run_contact contact;    /* positions, forces (linear, contact)    */
  lac_summary summary;
} lac_run_results;

/* What stage 6 reads. */
typedef struct lac_run_post_in
{
  const lac_scene *sc;
  lac_model model;
  const lac_mesh *mesh;
  const lac_run_material *mat;
  const lac_run_setup *setup;
  const lac_run_system *sys;
  const double *u;                 /* ndof: the displacement              */
  const lac_run_solution *sol;     /* linear scenes, else NULL            */
  const lac_run_nl *nl;            /* large deformation, else NULL        */
  const lac_run_steps *steps;      /* small strain with [steps], else NULL */
  const char *effects;             /* "plane strain, small strain, ..."   */
} lac_run_post_in;

int lac_run_post (const lac_run_post_in *in, lac_run_results *res,
                  char *progress, size_t size);
void lac_run_results_clear (lac_run_results *res);

#endif /* LAC_RUN_POST_H */
