/* lac_petsc_mg_internal.h -- shared by the contact multigrid's two levels
 *                            (lac_petsc_mg.c), its graph and aggregates
 *                            (lac_petsc_mg_aggregate.c) and its
 *                            prolongator (lac_petsc_mg_prolong.c); not
 *                            part of the library's interface
 */
#ifndef LAC_PETSC_MG_INTERNAL_H
#define LAC_PETSC_MG_INTERNAL_H

#ifdef LAC_HAVE_PETSC

#include <petscksp.h>
#include "linalg/lac_petsc_env.h"
#include "linalg/lac_petsc_mg.h"

#define TRY(call) do { PetscErrorCode e_ = (call); \
    if (e_) return lac_petsc_fail ((int) e_, __func__, #call); } while (0)

#define MAX_NULL 16          /* near-null vectors at most                 */

/* K's near-null vectors: m of them, the constant first if has_const;
 * a: the local arrays of the others (without a near-null space: the
 * constants of the bs components). */
typedef struct
{
  int m, has_const, given;
  PetscInt bs;
  const Vec *vec;            /* borrowed from K's near-null space        */
  const PetscScalar *a[MAX_NULL];
} near_null;

/* K's near-null vectors into *z (its arrays read until _close). */
int lac_petsc_mg_near_null_open (Mat K, near_null *z);
int lac_petsc_mg_near_null_close (near_null *z);

/* first[a] .. first[a + 1] - 1 (first: nagg + 2): the nodes of aggregate
 * a in node[] (n); the size of the largest aggregate. */
int lac_petsc_mg_members (const int *agg, int n, int nagg, int *first,
                          int *node);

/* Step 5: *lambda, the largest eigenvalue of D^-1 K (estimated); *P =
 * (I - w D^-1 K) *P, w = 4 / (3 lambda).  Collective. */
int lac_petsc_mg_largest_eigenvalue (Mat K, double *lambda);
int lac_petsc_mg_smooth (Mat K, double lambda, Mat *P);

#endif /* LAC_HAVE_PETSC */

#endif /* LAC_PETSC_MG_INTERNAL_H */
