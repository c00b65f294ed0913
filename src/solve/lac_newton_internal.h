/* lac_newton_internal.h -- the state of the loop of Algorithm 1, shared by
 *                          the loop (lac_newton.c), its workspace
 *                          (lac_newton_work.c), the units of a column
 *                          (lac_newton_units.c) and the friction steps
 *                          (lac_newton_friction.c); not part of the API
 */
#ifndef LAC_NEWTON_INTERNAL_H
#define LAC_NEWTON_INTERNAL_H

#include <stddef.h>
#include "solve/lac_newton.h"
#include "solve/lac_newton_rules.h"

struct lac_linear_model;

/* All arrays owned.  A model has at most one column per slot, so the
 * arrays per column have nslot entries. */
struct lac_newton_work
{
  /* the unknowns of (*) and the step */
  double *klam;          /* nslot: lambda per column, the unknown of (*)   */
  char *kact;            /* nslot: statuses per column                     */
  double *klin;          /* nslot: lambda of the linearization point       */
  double *x;             /* n: the solution of (*) (U or dU)               */
  double *dU;            /* n: the last step                               */
  double *lam_step;      /* nslot: lambda before the last solve            */
  double *lam_lin;       /* nslot: lambda before the statuses of step 2    */
  /* the statuses of step 2 */
  char *want;            /* nslot: statuses asked for by the rule          */
  long *col;             /* nslot: the column of the slot (-1: none)       */
  double *pair;          /* 2 nslot: (value, index) to sort                */
  char *target;          /* nslot: the statuses of the rule, before the
                            cycle guard                                   */
  char *active0;         /* nslot: the statuses the loop began with        */
  int first0;            /* and s->first then                              */
  /* the loop */
  int it;                /* solves in the loop                             */
  int converged;
  int last_change;       /* the solves before the last status change       */
  size_t nactive1;       /* active multipliers of the loop's first solve   */
  int settled;           /* the last solve changed no status               */
  double res_solved;     /* the residual it started from                   */
  long worst_gap;        /* the slot of step 3's gap residual (-1: none)   */
  int strategy_set;      /* the strategy holds a factorization             */
  size_t *set_slot;      /* nslot: the slots of the columns of the C the
                            strategy was last set or reset with            */
  size_t nset_slot;      /* their number                                   */
  int gmres_last;        /* GMRES iterations since the last one            */
  /* friction: the equations of the law per column (lac_contact_rows;
   * q = 1 + ntan components per column), NULL without */
  double *fl;            /* nslot q: lambda per component, the unknown     */
  char *ffree;           /* nslot q: the component is an unknown           */
  double *fP, *fQ;       /* nslot q q: the rows' coefficients              */
  double *fr;            /* nslot q: their right-hand sides                */
  double *dir_new;       /* nslot ntan: the slip directions of the rule    */
  int rows_its;          /* GMRES iterations of the last solve by lac_rows */
  double rows_berr;      /* and its backward error                         */
  /* the rules' own state (solve/lac_newton_rules.h) */
  lac_cycle_guard guard;
  lac_line_search ls;
  struct lac_linear_model *lin;  /* lac_newton_solve_system's model        */
};

/* The units of column i (lac_newton_units.c): |T^m cap Gamma_C|, rho_i
 * (the scale of lambda + rho d), and the scale of the terms its mean gap
 * d_i was computed from. */
double lac_newton_area (const lac_newton *s, size_t i);
double lac_newton_rho (const lac_newton *s, size_t i);
double lac_newton_gap_scale (const lac_newton *s, size_t i);

#endif /* LAC_NEWTON_INTERNAL_H */
