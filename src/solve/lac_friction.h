/* lac_friction.h -- Coulomb's law on the LAC averages: the status of a
 *                   macro-element and its equations         [LAC (18), Alg. 1]
 *
 * With friction a macro-element m carries, besides its normal multiplier
 * lambda_n (a pressure, <= 0 in contact, solve/lac_system.h), a tangential
 * one lambda_t (ntan = 1 component in 2D and axisymmetry, 2 in 3D: a
 * traction in the tangent frame of contact/lac_tangential.h), paired with
 * the mean tangential jump s = (Ct^T U)_m.  Coulomb's law on the averages,
 * with ds = s - s0 the slip since the last converged load step (s0):
 *
 *   |lambda_t| <= mu |lambda_n|,
 *   stick:  ds = 0,
 *   slip:   lambda_t = -mu |lambda_n| ds / |ds|   (it opposes the slip).
 *
 * As the normal law is A_n = max(lambda_n, -rho d) = 0 (lac_complementarity.h),
 * the tangential one is one equation (Alart and Curnier; Hüeber, Stadler,
 * Wohlmuth 2008, with lac's signs):
 *
 *   lambda_t = P_b(lambda_t - rho ds),   b = mu max(0, -(lambda_n + rho d)),
 *
 * P_b the projection onto the disc (2D: the segment) of radius b.  Newton's
 * method on it gives the three statuses of a macro-element:
 *
 *   INACTIVE  lambda_n + rho d >= 0:    lambda_n = 0, lambda_t = 0;
 *   STICK     in contact, |xi| <= b,    xi = lambda_t - rho ds:
 *                                       d = 0 and ds = 0;
 *   SLIP      in contact, |xi| > b:     d = 0 and lambda_t = -mu lambda_n e,
 *                                       e = xi / |xi| (the direction of the
 *                                       iterate: -ds/|ds| at the solution).
 *
 * In 2D e = sign(xi) and its Newton derivative is 0 (e only flips): the
 * slip equation lambda_t + mu e lambda_n = 0 is Newton's exact
 * linearization, and the method is the semismooth Newton method of Hüeber,
 * Stadler and Wohlmuth.  In 3D e turns with xi: Newton's linearization of
 * lambda_t - b xi/|xi| = 0 at the iterate (b, xi, e = xi/|xi|, M = (b/|xi|)
 * (I - e e^T), the derivative of b xi/|xi| along xi) is
 *
 *   (I - M) lambda_t + mu e lambda_n + rho M c_t^T U - mu rho e c_n^T U
 *     = (I - M) lambda_t^k + mu e lambda_n^k + rho M c_t^T U^k
 *       - mu rho e c_n^T U^k - (lambda_t^k - b e),
 *
 * (with b = -mu (lambda_n + rho d), d = G - c_n^T U, ds = c_t^T U + ...),
 * and the loop counts a turn of e by more than LAC_FRICTION_TURN as a
 * change of status, so that it stops when e has settled.
 *
 * The equations of a macro-element, for the system of solve/lac_system.h
 * (lac_contact_rows): its columns are q = 1 + ntan at a time (normal,
 * then the tangential ones), its equations
 *   P (-[c_n c_t]^T U) + Q [lambda_n; lambda_t] = r,      (q x q blocks)
 * with G the normal constant (d = G - c_n^T U) and gt the tangential one
 * (stick: c_t^T U = gt: gt = s0 minus what the fixed dofs add).
 *
 * rho is the scale of the normal test (lac_newton.h: E / (h |T|)), used
 * for both parts: ds is a mean slip times a measure as d is.
 */
#ifndef LAC_FRICTION_H
#define LAC_FRICTION_H

#include <stddef.h>

enum
{
  LAC_FRICTION_INACTIVE = 0, LAC_FRICTION_STICK = 1, LAC_FRICTION_SLIP = 2
};

#define LAC_FRICTION_TURN 1e-8   /* a turn of the slip direction (rad) that
                                    counts as a change of status (3D)    */
#define LAC_FRICTION_TIE 1e-10   /* |xi| within this of b (relative): at the
                                    limit, stick and slip both hold; the
                                    status stays what it was             */

/* One macro-element at the evaluation. */
typedef struct lac_friction_slot
{
  int ntan;              /* 1 or 2                                          */
  double mu;             /* Coulomb's coefficient (>= 0)                    */
  double rho;            /* the scale of the status test                    */
  double lambda_n;       /* the normal multiplier                           */
  const double *lambda_t; /* ntan: the tangential ones                      */
  double d;              /* the mean gap (> 0 open)                         */
  const double *ds;      /* ntan: the slip since the last converged step    */
  double lmax;           /* max |lambda| (rounding of lambda)               */
  double dscale;         /* the scale of d (rounding of d)                  */
  double sscale;         /* the scale of ds (rounding of ds)                */
} lac_friction_slot;

/* Step 2: the status of the macro-element (first: the first iteration of
 * a run, d <= 0 sticks; current: its status now); *dir (ntan) the slip
 * direction e when SLIP.  A macro-element exactly at the limit (|xi| = b
 * to LAC_FRICTION_TIE: |lambda_t| = b and no slip) satisfies both laws;
 * it keeps its status, else rounding would flip it for ever. */
int lac_friction_status (const lac_friction_slot *x, int first, int current,
                         double *dir);

/* Step 4: the q x q blocks P, Q (row after row) and r (q) of the
 * macro-element's equations for status st at the iterate x (dir: e of
 * SLIP in 2D), with the normal constant G, the tangential ones gt (ntan:
 * stick is c_t^T U = gt), and the iterate's an = c_n^T U and at = c_t^T U
 * (ntan; the columns of the system). */
void lac_friction_rows (int st, const lac_friction_slot *x,
                        const double *dir, double G, const double *gt,
                        double an, const double *at, double *P, double *Q,
                        double *r);

/* How far (x, status, dir) is from Coulomb's law, in the units of a
 * traction: |lambda_t - P_b(lambda_t - rho ds)|. */
double lac_friction_residual (const lac_friction_slot *x);

#endif /* LAC_FRICTION_H */
