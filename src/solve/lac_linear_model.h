/* lac_linear_model.h -- the contact model of a small-strain scene
 *                                          [LAC (8), (16)-(18), Alg. 1]
 *
 * The contact model (solve/lac_contact_model.h) of linear elasticity with
 * the pairing made once, on the reference shape: K, F, C and the initial
 * mean gaps G do not depend on U, so that at U
 *
 *   r(U) = F - K U,        d(U) = G - C^T U,
 *
 * and the system (*) of solve/lac_system.h, solved for the statuses of
 * the moment, gives U itself: one solve per active set is exact, and the
 * strategy factorizes K (or K + C_A W C_A^T) for the whole loop.
 *
 * Built from a lac_contact_system alone (C and G given, one multiplier per
 * column: the unit tests and the book's small examples), or from the
 * contact data of a set of pairs (contact/lac_contact_set.h: one pair or
 * several): then its slots are the macro-elements of the slave surfaces
 * (pair p's from the set's offset[p]), its columns those of all pairs side
 * by side, and the loop can ask which macro-elements without a multiplier
 * the solution pushed into the master (uncovered) and have the pairs made
 * again with a longer reach (widen: the caller's contact data are
 * replaced; the pairs' `widened` is the largest reach asked, their own
 * reach, popts.dist_abs, stays as it is).  A new model starts from the
 * pairs' own reach (their `widened` set to 0).  The node-to-segment
 * method of comparison is checked the same way, node by node (its slots
 * are the slave nodes); a node that no reach gives a multiplier (its
 * projection misses the master in the reference shape) is an error of
 * widen that names it.
 *
 * With friction (the contact data of the set has tangential columns,
 * contact/lac_tangential.h) the model's ntan is theirs, evaluate gives
 * the tangential columns and jumps too, and linearize a system whose
 * columns are [c_n c_t] of every macro-element side by side.
 *
 * Load steps (run/lac_run_steps.h): from one loop to the next the caller
 * changes F and the Dirichlet values in place; K, C and the pairing stay,
 * so that the strategy keeps its factorization.  The Dirichlet part of
 * the mean gaps,
 *
 *   G = G0 - C_D^T g        (C_D: the rows of C at the Dirichlet dofs,
 *                            g: their values; then C_D is zeroed),
 *
 * is made again from the values of the moment (lac_linear_model_dirichlet)
 * out of G0 and C_D, kept when the values were first moved in
 * (lac_linear_lift_record, by the caller), then by the model for every
 * new contact data (widen).
 *
 * Ownership: the system, the set and the Dirichlet data are borrowed;
 * with a set, *data is the caller's, replaced (the old one cleared) by
 * widen.
 */
#ifndef LAC_LINEAR_MODEL_H
#define LAC_LINEAR_MODEL_H

#include "contact/lac_contact_set.h"
#include "fem/lac_assembly.h"
#include "solve/lac_contact_model.h"

/* An entry of C_D: C(dof, col) = x. */
typedef struct lac_linear_lift_entry
{
  size_t col, dof;
  double x;
} lac_linear_lift_entry;

/* The Dirichlet part of the mean gaps of one contact data (load steps). */
typedef struct lac_linear_lift
{
  double *G0;                 /* owned, k: G without the Dirichlet values  */
  size_t n, cap;
  lac_linear_lift_entry *e;   /* owned, n: C_D column by column            */
  size_t nt, capt;            /* with friction: Ct_D, the rows of Ct at    */
  lac_linear_lift_entry *et;  /* the Dirichlet dofs (owned, nt), from
                                 which sfix = Ct_D^T g is made again      */
} lac_linear_lift;

typedef struct lac_linear_model
{
  lac_contact_system sys;     /* K, F (Dirichlet applied), C, G, N         */
  const size_t *slot;         /* k: macro-element of column i, or NULL     */
  const double *area, *size;  /* k, or NULL                                */
  lac_contact_set *set;       /* borrowed, or NULL                         */
  lac_contact_set_data *data; /* the caller's, with a set: its `all` is C,
                                 G (the Dirichlet values moved in)        */
  const lac_dirichlet *dir;   /* its frames turn a new contact's C, its
                                 values are moved into its G              */
  int news;                   /* what linearize reports next (LAC_MODEL_*) */
  lac_contact_uncovered miss; /* what uncovered found last                 */
  lac_linear_lift lift;       /* owned, load steps: G0 and C_D (G0 NULL:
                                 not kept)                                */
  double *d, *r, *x;          /* owned: nslot, n, n (coordinates X + U)    */
  /* Coulomb friction (the contact data has tangential columns): */
  lac_csc *Call;              /* owned: [c_n c_t] of every column, side by
                                 side (lac_contact_rows of lac_system.h)  */
  double *Gall;               /* owned: zero, k (1 + ntan)                */
  double *slip;               /* owned, k ntan: Ct^T U + sfix at U        */
  lac_contact_system sys_rows; /* sys with Call: what linearize gives     */
} lac_linear_model;

/* A model over sys (C, G: one multiplier per column; E: the reference
 * Young modulus, 0: 1).  *m is the interface the loop is given. */
int lac_linear_model_init (lac_linear_model *lm,
                           const lac_contact_system *sys, double E,
                           lac_contact_model *m);
/* The same over the contact data of a set (*data, already built on the
 * reference shape, data->all->C turned to dir's nodal frames if any and
 * the Dirichlet values moved into data->all): sys's C
 * and G are taken from it; the slots are the macro-elements. */
int lac_linear_model_init_set (lac_linear_model *lm,
                               const lac_contact_system *sys,
                               lac_contact_set *set,
                               lac_contact_set_data *data,
                               const lac_dirichlet *dir, double E,
                               lac_contact_model *m);
void lac_linear_model_clear (lac_linear_model *lm);
/* Load steps: the Dirichlet values of dir moved into the mean gaps of
 * `all` (lac_contact_apply_dirichlet, C_D zeroed), G0 and C_D kept first
 * in *l (new; lac_linear_lift_clear). */
int lac_linear_lift_record (const lac_dirichlet *dir, lac_contact *all,
                            lac_linear_lift *l);
void lac_linear_lift_clear (lac_linear_lift *l);
/* After init_set: *l (recorded on the model's contact data) moved into the
 * model (l emptied), G made from the values of dir now; every new contact
 * data of widen keeps its own from then on. */
void lac_linear_model_keep_lift (lac_linear_model *lm, lac_linear_lift *l);
/* G = G0 - C_D^T g for the values g of dir now (later entries of a dof
 * win), the arithmetic of lac_contact_apply_dirichlet. */
void lac_linear_model_dirichlet (lac_linear_model *lm);

#endif /* LAC_LINEAR_MODEL_H */
