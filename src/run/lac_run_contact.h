/* lac_run_contact.h -- where the contact is and what it carries
 *                                                [LAC (16)-(18); §5]
 *
 * Part of stage 6 (post) of a linear run with contact, for the outputs
 * (contact.csv, contact.vtu) and the summary:
 *
 *   position   of every macro-element T^m (row m of contact.csv): the
 *              centroid of T^m (not weighted by 2 pi r), whether or not
 *              it carries a multiplier; node-to-segment: the collocation
 *              node of a multiplier, none for a node without one;
 *   abscissa   (2D, LAC) the curvilinear abscissa s of that centroid along
 *              the slave curve: the slave facets are chained by their end
 *              nodes, s = 0 at the free end of smallest x (then y) -- the
 *              symmetry axis of a half model -- and grows along the chain
 *              (a closed curve starts at its node of smallest x; pieces
 *              follow one another);
 *   force      of multiplier i: f_i = lambda_i int_{T^m_i cap Gamma_C} n^S
 *              dGamma (2 pi r dGamma axisymmetric), the force the master
 *              exerts on the slave body through T^m_i; its sum R is the
 *              resultant, which balances the loads of a body held by
 *              contact alone exactly (the columns of C integrate the same
 *              n^S against shape functions that sum to one);
 *   pairs      (several [contact] sections) the slots of pair p are the
 *              set's offset[p] .., its columns data.col[p] ..; positions
 *              and abscissae per pair (s = 0 at the start of each pair's
 *              curve), f_i of each column with its pair's pairing;
 *   summary    contact_force = R . e, e the coordinate axis (with its sign)
 *              nearest to the mean outward slave normal of the active
 *              macro-elements (axisymmetric: the z axis; a rigid obstacle:
 *              -y in 2D, -z in 3D), negative in compression as lambda;
 *              contact_axis (that axis, "-y"); contact_area = the sum of
 *              |T^m cap Gamma_C| over the active macro-elements (2 pi r
 *              dGamma axisymmetric); max_contact_pressure = max over the
 *              active ones of -lambda_i (0 if none);
 *              active_macro_elements; all over every pair.  With several
 *              pairs, then: contact_resultant = R as a vector ("x y" or
 *              "x y z", every digit), and for each pair NAME (its
 *              [contact NAME]):
 *              contact_force.NAME (the sum of its f_i, a vector: the
 *              force its master exerts on its slave body),
 *              contact_normal_force.NAME = sum lambda_i |T^m_i cap
 *              Gamma_C| (its normal component, negative in compression),
 *              contact_area.NAME, max_contact_pressure.NAME and
 *              active_macro_elements.NAME, as above.  (One pair: the keys
 *              above only, as they always were.)
 *
 * Values that do not exist are NAN (written as empty fields).
 */
#ifndef LAC_RUN_CONTACT_H
#define LAC_RUN_CONTACT_H

#include "contact/lac_contact.h"
#include "run/lac_run_setup.h"
#include "run/lac_summary.h"
#include "solve/lac_newton.h"

typedef struct lac_run_contact
{
  size_t n;             /* rows: the macro-elements (nts: slave nodes)     */
  double *x;            /* owned, 3n: position of row m (NAN: none)        */
  double *s;            /* owned, n: abscissa (NAN: none; 3D: all NAN)     */
  size_t k;             /* multipliers                                     */
  double *force;        /* owned, 3k: f_i (zero third component in 2D)     */
  double resultant[3];  /* sum of f_i                                      */
  double *pair_force;   /* owned, 3 npairs: the sum of f_i of each pair    */
  double *pair_tforce;  /* owned, 3 npairs: its tangential part (friction:
                           sum_i sum_b lambda_t,ib int t_b; NULL without)  */
} lac_run_contact;

/* Positions, abscissae, forces; then the summary lines. */
int lac_run_contact_post (const lac_scene *sc, lac_model model,
                          const lac_mesh *m,
                          const lac_run_setup *setup, const lac_contact *c,
                          const lac_newton *nw, lac_run_contact *out,
                          lac_summary *sum);
void lac_run_contact_clear (lac_run_contact *rc);

/* The force f = sum_i lambda_i int_{T^m_i cap Gamma_C} n^S of the columns
 * col0 .. col1 - 1 of c, one pair's (macro-elements M paired by P on the
 * nodes of m, slots from off on): the force its master exerts on its
 * slave body.  Also on the deformed surface of a large-deformation run. */
int lac_run_pair_force (lac_model model, const lac_mesh *m,
                        const lac_macro *M, const lac_pairing *P,
                        const lac_contact *c, size_t col0, size_t col1,
                        size_t off, const double *lambda, double f[3]);

/* What the pairing left out: pairing_widened, the times the loop paired
 * again with a longer reach (solve/lac_newton.h: no silent penetration);
 * pairs_dropped and area_dropped, the pairs of the pairings of d whose
 * projection failed and the slave measure they covered.  Nothing when
 * there is none. */
int lac_run_pairs_dropped (const lac_contact_set_data *d,
                           const lac_newton *nw, lac_summary *sum);

#endif /* LAC_RUN_CONTACT_H */
