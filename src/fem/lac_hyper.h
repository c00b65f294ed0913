/* lac_hyper.h -- hyperelasticity in total Lagrangian form    [LAC §4.5, §5.4]
 *
 * The ring-on-block experiment [LAC §5.4] crushes hyperelastic bodies far
 * beyond small strains; [LAC §4.5] solves such problems with ONE Newton
 * loop for the contact and the mechanical nonlinearities, which needs,
 * for the current displacement u, the internal force F_int(u) and its
 * tangent K_T(u) = dF_int/du.  This module gives both, cell by cell, in
 * the total Lagrangian form: with X the reference coordinates,
 *
 *   F = I + grad_X u                 deformation gradient, J = det F,
 *   F_int(u)_(a,i) = int_Omega0  P(F) : dF^(a,i)  dV,
 *   K_T(u)_(a,i),(b,k) = int_Omega0  dF^(a,i) : A(F) : dF^(b,k)  dV,
 *
 * where dF^(a,i) = e_i (x) grad_X N_a is the variation of F along the dof
 * (node a, component i), P = dW/dF the first Piola-Kirchhoff stress and
 * A = dP/dF (the tangent: material and geometric parts together).
 *
 * Laws (W per unit reference volume, lambda and mu the Lame constants of
 * E and nu: lambda = E nu / ((1+nu)(1-2nu)), mu = E / (2(1+nu))):
 *
 *   LAC_LAW_NEO_HOOKEAN   W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
 *                         I1 = tr(F^T F);
 *                         P = mu (F - F^-T) + lambda ln J F^-T,
 *                         A_iJkL = mu d_ik d_JL + lambda F^-1_Ji F^-1_Lk
 *                                  + (mu - lambda ln J) F^-1_Jk F^-1_Li;
 *   LAC_LAW_LINEAR        Saint Venant-Kirchhoff, Hooke's law on the Green
 *                         strain E = (F^T F - I)/2: S = lambda tr(E) I
 *                         + 2 mu E, P = F S, A_iJkL = d_ik S_JL
 *                         + F_iM C_MJNL F_kN.
 *
 * Both reduce to linear elasticity [LAC (2)] for small displacements: at
 * u = 0, A_iJkL = lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk), the
 * Hooke tensor, so K_T(0) is the linear stiffness of lac_assembly.h (the
 * same quadrature on straight-sided cells).  Both are frame-indifferent:
 * W(R F) = W(F) for a rotation R, so a rigid rotation gives F_int = 0.
 *
 * Models: 3D; plane strain (F_33 = 1); axisymmetric (x = r, y = z,
 * F_tt = 1 + u_r / R, the hoop variation dF_tt = N_a / R for i = r, the
 * weight 2 pi R).  Voigt order of Cauchy stresses as in lac_material.h.
 *
 * Quadrature: degree 2 * order (+ 2 axisymmetric) of the reference element
 * by default, the "full" Gauss rule of lac_assembly.c for straight-sided
 * cells (2x2x2 hex8, 3x3x3 hex20/hex27); `degree` overrides it.
 *
 * Ownership: everything is borrowed; outputs are caller-allocated.
 */
#ifndef LAC_HYPER_H
#define LAC_HYPER_H

#include <stddef.h>
#include "linalg/lac_linalg.h"
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"
#include "fem/lac_pattern.h"
#include "linalg/lac_queue.h"

typedef enum
{
  LAC_LAW_LINEAR = 0,      /* Hooke; Saint Venant-Kirchhoff at finite strain */
  LAC_LAW_NEO_HOOKEAN = 1  /* compressible neo-Hookean (file header)         */
} lac_law;

/* "linear" | "neo_hookean" -> law; -1 if unknown. */
int lac_law_from_name (const char *name);
const char *lac_law_name (lac_law law);

/* Per-cell hyperelastic material. */
typedef struct lac_hyper
{
  lac_model model;
  const double *E;     /* borrowed, ncells; cells with E <= 0 are skipped   */
  const double *nu;    /* borrowed, ncells                                  */
  const char *law;     /* borrowed, ncells: lac_law values; NULL: all
                          neo-Hookean                                       */
  int degree;          /* quadrature degree; 0: the default (header)        */
} lac_hyper;

/* Lame constants of (E, nu); LAC_EINVAL unless E > 0, -1 < nu < 1/2. */
int lac_hyper_lame (double E, double nu, double *lambda, double *mu);

/* The law at one point: P (3x3, row-major P[i*3+J]) and, if A != NULL,
 * A[((i*3+J)*3+k)*3+L] = dP_iJ/dF_kL.  LAC_ESING if det F <= 0. */
int lac_hyper_stress (lac_law law, double E, double nu, const double *F,
                      double *P, double *A);

/* Cell c at displacement u (dim*nnodes, global): fe += internal force
 * (nen*dim, dof a*dim + i) and Ke += tangent ((nen*dim)^2, row-major,
 * symmetric); either may be NULL.  LAC_ESING (message: cell, point) if
 * det F <= 0 or det J <= 0 at a quadrature point, LAC_EINVAL. */
int lac_hyper_cell (const lac_mesh *m, const lac_hyper *h, size_t c,
                    const double *u, double *fe, double *Ke);

/* Fint += F_int(u) (ndof) and K += K_T(u) (triplets ndof x ndof) over the
 * cells with E > 0; Fint or K may be NULL. */
int lac_hyper_assemble (const lac_mesh *m, const lac_hyper *h,
                        const double *u, double *Fint, lac_triplet *K);

/* The same with K scattered into a kept pattern (lac_pattern.h, built
 * once on the cells with E > 0): its values are overwritten, no triplet,
 * no search; on both cores (lac_hyper_job below, two threads from the
 * start: linalg/lac_tasks.h).  LAC_EINVAL if a cell with E > 0 is not in
 * the pattern. */
int lac_hyper_assemble_pattern (const lac_mesh *m, const lac_hyper *h,
                                const double *u, double *Fint,
                                lac_pattern *K);

/* An assembly into a kept pattern that the threads share, each coming
 * when it is free (linalg/lac_queue.h): the runs of the pattern's slabs
 * (lac_pattern_slabs), phase after phase; a pattern without slabs is one
 * run, every cell in order, on one thread.  The sums are those of the
 * pattern's order whoever adds which run (lac_pattern.h): the same bits
 * on one thread or two, whenever the second one comes; and F_int has the
 * same bits whether K_T is asked for or not.
 *
 *   lac_hyper_job_init    checks, K's values zeroed if want_K (Fint is
 *                         added to, as above), the runs set up;
 *   lac_hyper_job_work    in each thread that comes: takes runs (at most
 *                         `most`; SIZE_MAX: as many as are left), then
 *                         waits for the runs the others are doing;
 *                         returns the assembly's status (the first
 *                         failing cell in the pattern's order, with its
 *                         message, as one thread alone would meet it);
 *   lac_hyper_job_clear   after the last worker returned.
 *
 * Ownership: the job is the caller's and must not move between init and
 * clear; everything in it is borrowed.  Nothing to clear if init fails. */
typedef struct lac_hyper_job
{
  const lac_mesh *m;
  const lac_hyper *h;
  const double *u;
  double *Fint;          /* NULL: not assembled                          */
  lac_pattern *K;        /* its runs; its values if want_K               */
  int want_K;
  size_t all[2];         /* the one phase of a pattern without slabs     */
  lac_queue q;
} lac_hyper_job;

int lac_hyper_job_init (lac_hyper_job *j, const lac_mesh *m,
                        const lac_hyper *h, const double *u, double *Fint,
                        lac_pattern *K, int want_K);
int lac_hyper_job_work (lac_hyper_job *j, size_t most);
void lac_hyper_job_clear (lac_hyper_job *j);

/* Cauchy stress sigma = P F^T / J at reference point xi of cell c, in
 * the Voigt order of lac_material.h (plane strain: s[2] = sigma_zz). */
int lac_hyper_cauchy_at (const lac_mesh *m, const lac_hyper *h,
                         const double *u, size_t c, const double *xi,
                         double *s);

/* Nodal means of the Cauchy stress over the cells (E > 0, and cells[c]
 * != 0 if cells is given) at the nodes' reference coordinates, and the von
 * Mises stress (vm may be NULL), as lac_post_stress_nodal (lac_nodal.h). */
int lac_hyper_cauchy_nodal (const lac_mesh *m, const lac_hyper *h,
                            const double *u, const char *cells,
                            double *sigma, double *vm);

#endif /* LAC_HYPER_H */
