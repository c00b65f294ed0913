/* lac_run_system.h -- stage 4 of a run: the system to solve
 *                                          [LAC (8), (16)-(18); §4.3]
 * In:  the scene (loads, Dirichlet conditions, [contact]), the model, the
 *      mesh, the material, the contact set-up.
 * Out: K and F [LAC (8)], the Dirichlet data and their elimination (b)
 *      (or, for a solver that assembles K from the cells, only what the
 *      elimination leaves of K: lac_run_system_stiffness);
 *      for a linear scene with contact, admissibility [LAC Def. 1], C and
 *      the mean gaps G [LAC (16)-(18)] of every pair (less the pair's
 *      interference), C turned to the nodal frames of rollers (T^T C),
 *      the Dirichlet values moved into G: into the set-up's contact data
 *      (setup->data, its `all` the columns of every pair,
 *      contact/lac_contact_set.h), which the loop replaces when it pairs
 *      again; the bodies and the rigid motions their Dirichlet conditions
 *      leave free (fem/lac_rigid.h).  A body that touches no contact
 *      surface and is not fixed is an error naming it and its free motion;
 *      the free motions of bodies held by contact alone are N, for the
 *      solve (solve/lac_system.h).  Rigid plates ([load] plate = yes)
 *      condensed into K and F (run/lac_run_plate.h).  A small-strain
 *      scene with [steps]: also F and b of each load curve
 *      (run/lac_run_curves.h), and G0 and C_D of the mean gaps kept
 *      before the Dirichlet values are moved in, for the linear model to
 *      move the values of every step in (solve/lac_linear_model.h).
 */
#ifndef LAC_RUN_SYSTEM_H
#define LAC_RUN_SYSTEM_H

#include <stddef.h>
#include "contact/lac_contact.h"
#include "fem/lac_assembly.h"
#include "fem/lac_assembly_digest.h"
#include "fem/lac_assembly_dist.h"
#include "fem/lac_rigid.h"
#include "io/lac_scene.h"
#include "run/lac_run_curves.h"
#include "run/lac_run_material.h"
#include "run/lac_run_plate.h"
#include "run/lac_run_setup.h"
#include "solve/lac_linear_model.h"

typedef struct lac_run_system
{
  size_t ndof, nfixed, nnz;
  lac_csc *K;              /* owned: K after the Dirichlet elimination   */
  lac_csc *K0;             /* owned, [output] matrix: K before it, or NULL */
  double *F;               /* owned, ndof: the load vector               */
  double *b;               /* owned, ndof: right-hand side after it      */
  lac_dirichlet *dir;      /* owned: the fixed dofs and their values     */
  const lac_contact *contact; /* borrowed: the set-up's contact data, the
                              columns of every pair (setup->data.all;
                              the solve stage points it at the new data
                              when the loop pairs again); NULL without */
  lac_bodies *bodies;      /* owned                                      */
  size_t nfree;            /* free motions of bodies held by contact     */
  double *N;               /* owned, ndof x nfree                        */
  char **N_what;           /* owned, nfree descriptions                  */
  lac_run_ties ties;       /* rigid plates: dofs that follow a plate's  */
  int coord_dim;           /* components per node                       */
  const double *x;         /* borrowed: the mesh's coordinates (ndof), for
                              the rigid motions of the petsc strategy's
                              multigrid; NULL for the axisymmetric model
                              (its one rigid motion: along the axis)    */
  lac_dist_source cells;   /* what K was assembled from, for the petsc
                              strategy's assembly on its processes (mesh
                              NULL: rigid plates, rollers' frames, large
                              deformation)                              */
  char *fixed;             /* owned, ndof: the fixed dofs (cells.fixed)  */
  int k_by_solver;         /* 1: K = NULL because the solver assembles it
                              from the cells (lac_run_system_stiffness) */
  lac_run_curves *curves;  /* owned, small strain with [steps]: F, b and
                              the Dirichlet values by load curve
                              (run/lac_run_curves.h); NULL otherwise    */
  lac_linear_lift lift;    /* owned, with curves: G0 and C_D of the contact
                              data, for the linear model to move the
                              values of each step in (taken by stage 5) */
} lac_run_system;

/* Everything but K (with rigid plates: also K, which their condensation
 * needs). */
int lac_run_system_build (const lac_scene *sc, lac_model model,
                          const lac_mesh *m, const lac_run_material *mat,
                          lac_run_setup *setup, lac_run_system *sys,
                          char *progress, size_t size);
/* Then K and its elimination (b); from_cells: the solve will assemble K
 * from the cells (run/lac_run_solve.h, lac_run_solve_k_from_cells), so,
 * where the cells are what K is made of (no rollers' frames, no
 * [output] matrix), K is never made here: only b and the number of
 * entries (fem/lac_assembly_digest.h, sys->k_by_solver).  The progress
 * line says which. */
int lac_run_system_stiffness (const lac_scene *sc, const lac_mesh *m,
                              const lac_run_material *mat, int from_cells,
                              lac_run_system *sys, char *progress,
                              size_t size);
void lac_run_system_clear (lac_run_system *sys);

#endif /* LAC_RUN_SYSTEM_H */
