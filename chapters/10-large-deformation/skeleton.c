/* skeleton.c -- chapter 10, exercises 2 and 3: a start for your program
 *
 * Copy it with
 *   make exercise NAME=law FROM=chapters/10-large-deformation/skeleton.c
 * edit exercises/law/main.c, then
 *   make build/exercises/law && build/exercises/law
 * As given, it prints the first Piola-Kirchhoff stress P of the
 * neo-Hookean law at one deformation gradient F; the TODO lines are yours.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"
#include "fem/lac_hyper.h"

/* Stop on a failed library call with its stored one-line message. */
static void
check_status (int status, const char *what)
{
  if (status == LAC_SUCCESS)
    return;
  fprintf (stderr, "exercise: %s failed: %s (%s)\n", what,
           lac_error_message (), lac_strerror (status));
  exit (1);
}

int
main (void)
{
  const double E = 1000, nu = 0.3;
  double lam, mu;
  check_status (lac_hyper_lame (E, nu, &lam, &mu), "lac_hyper_lame");
  printf ("lambda = %g, mu = %g\n", lam, mu);

  /* F, row-major F[i*3+J]; TODO: a rotation, a stretch, their product */
  double e = 0.1;
  double F[9] = { 1 + e, 0, 0, 0, 1, 0, 0, 0, 1 };
  double P[9], A[81];                 /* A[((i*3+J)*3+k)*3+L] = dP_iJ/dF_kL */
  check_status (lac_hyper_stress (LAC_LAW_NEO_HOOKEAN, E, nu, F, P, A),
                "lac_hyper_stress");
  for (int i = 0; i < 3; i++)
    printf ("P[%d] = %12.6f %12.6f %12.6f\n", i, P[3 * i], P[3 * i + 1],
            P[3 * i + 2]);
  /* TODO: compare A at F = I with Hooke's tensor */
  return 0;
}
