/* lac_newton_internal.h -- the state of the loop of Algorithm 1, shared by
 *                          the loop (lac_newton.c) and its workspace
 *                          (lac_newton_work.c); not part of the API
 */
#ifndef LAC_NEWTON_INTERNAL_H
#define LAC_NEWTON_INTERNAL_H

#include <stddef.h>
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
  int gmres_last;        /* GMRES iterations since the last one            */
  /* the rules' own state (solve/lac_newton_rules.h) */
  lac_cycle_guard guard;
  lac_line_search ls;
  struct lac_linear_model *lin;  /* lac_newton_solve_system's model        */
};

#endif /* LAC_NEWTON_INTERNAL_H */
