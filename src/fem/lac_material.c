/* lac_material.c -- linear elastic constitutive laws               [LAC (2)]
 *
 * Hooke's law sigma = A eps = lambda tr(eps) I + 2 mu eps  [LAC (2)] for an
 * isotropic material with Young's modulus E and Poisson's ratio nu:
 *   lambda = E nu / ((1 + nu)(1 - 2 nu)),   mu = E / (2 (1 + nu)).
 * In Voigt form with engineering shear strains (gamma = 2 eps) the matrix D
 * has lambda + 2 mu on the normal diagonal, lambda off it, and mu on the
 * shear diagonal.  The three models of lac_material.h share this D: plane
 * strain keeps the zz row (eps_zz = 0 in the strain vector, so sigma_zz =
 * lambda (eps_xx + eps_yy) = nu (sigma_xx + sigma_yy) comes out of the same
 * product), the axisymmetric model uses (rr, zz, tt, rz) in the same places.
 *
 * References: any text on linear elasticity, e.g. T. J. R. Hughes, The
 * Finite Element Method (Dover 2000), section 2.7 and 2.12 (axisymmetry).
 */
#include "fem/lac_material.h"

#include <math.h>
#include <string.h>
#include "base/lac_status.h"

/* lac_model_from_name: "plane_strain" | "axisymmetric" | "3d" -> model.
 *   Also accepts "plane-strain", "axi" and "3D".  Returns -1 if unknown. */
int
lac_model_from_name (const char *name)
{
  if (!name)
    return -1;
  if (!strcmp (name, "plane_strain") || !strcmp (name, "plane-strain"))
    return LAC_PLANE_STRAIN;
  if (!strcmp (name, "axisymmetric") || !strcmp (name, "axi"))
    return LAC_AXISYMMETRIC;
  if (!strcmp (name, "3d") || !strcmp (name, "3D"))
    return LAC_SOLID3D;
  return -1;
}

/* lac_model_name: the canonical name of a model ("?" if invalid). */
const char *
lac_model_name (lac_model m)
{
  switch (m)
    {
    case LAC_PLANE_STRAIN: return "plane_strain";
    case LAC_AXISYMMETRIC: return "axisymmetric";
    case LAC_SOLID3D: return "3d";
    }
  return "?";
}

/* lac_model_dim: space dimension of the mesh of a model (2, 2, 3; 0 if bad). */
int
lac_model_dim (lac_model m)
{
  switch (m)
    {
    case LAC_PLANE_STRAIN: return 2;
    case LAC_AXISYMMETRIC: return 2;
    case LAC_SOLID3D: return 3;
    }
  return 0;
}

/* lac_model_nstress: number of Voigt components (4, 4, 6; 0 if bad). */
int
lac_model_nstress (lac_model m)
{
  switch (m)
    {
    case LAC_PLANE_STRAIN: return 4;
    case LAC_AXISYMMETRIC: return 4;
    case LAC_SOLID3D: return 6;
    }
  return 0;
}

/* lac_material_check: 0 < E and -1 < nu < 1/2, the conditions for A to be
 * positive definite [LAC (2)].  Returns LAC_SUCCESS or LAC_EINVAL with a
 * message naming the offending value. */
int
lac_material_check (double E, double nu)
{
  if (!(E > 0.0) || !isfinite (E))
    LAC_ERROR (LAC_EINVAL, "Young's modulus E = %g must be positive and finite"
               " (nu = %g)", E, nu);
  if (!(nu > -1.0 && nu < 0.5))
    LAC_ERROR (LAC_EINVAL, "Poisson's ratio nu = %g must satisfy -1 < nu < 1/2"
               " (E = %g); nu = 1/2 is incompressible, not supported", nu, E);
  return LAC_SUCCESS;
}

/* lac_material_D: D (ns x ns, row-major) with sigma = D eps  [LAC (2)].
 *   [in]  m, E, nu   model and material (checked)
 *   [out] D          lac_model_nstress(m)^2 values
 *   returns LAC_SUCCESS, LAC_EINVAL (bad model or material) */
int
lac_material_D (lac_model m, double E, double nu, double *D)
{
  int status = lac_material_check (E, nu);
  if (status)
    return status;
  int ns = lac_model_nstress (m);
  if (ns == 0)
    LAC_ERROR (LAC_EINVAL, "unknown model %d", (int) m);
  double lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));  /* Lame lambda */
  double mu = E / (2.0 * (1.0 + nu));                     /* shear modulus */
  for (int k = 0; k < ns * ns; k++)
    D[k] = 0.0;
  /* Three normal components in every model: (xx,yy,zz) or (rr,zz,tt). */
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      D[i * ns + j] = lam + (i == j ? 2.0 * mu : 0.0); /* lam + 2mu delta_ij */
  for (int k = 3; k < ns; k++)
    D[k * ns + k] = mu;                   /* tau = mu gamma (engineering) */
  return LAC_SUCCESS;
}

/* lac_von_mises: sqrt(3/2 s':s') of a Voigt stress vector, s' the deviator.
 *   = sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2)/2 + 3 (shears^2)).
 *   Plane strain and axisymmetric vectors carry the out-of-plane normal
 *   stress (zz, resp. tt) in s[2] and one shear in s[3]. */
double
lac_von_mises (lac_model m, const double *s)
{
  double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  double q = 0.5 * (a * a + b * b + c * c);
  int ns = lac_model_nstress (m);
  for (int k = 3; k < ns; k++)
    q += 3.0 * s[k] * s[k];
  return sqrt (q);
}

double
lac_model_weight (lac_model m, const double *x)
{
  return m == LAC_AXISYMMETRIC ? 6.283185307179586476925286766559 * x[0]
                               : 1.0;                        /* 2 pi r */
}
