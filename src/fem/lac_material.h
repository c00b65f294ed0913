/* lac_material.h -- linear elastic constitutive laws              [LAC (2)]
 *
 * sigma = A eps  [LAC (2)] in Voigt form, for the three models:
 *   plane strain   components (xx, yy, zz, xy)       ns = 4
 *   axisymmetric   components (rr, zz, tt, rz)       ns = 4   (x = r, y = z;
 *                  tt is the hoop component u_r / r)
 *   3D             components (xx, yy, zz, xy, yz, zx) ns = 6
 * Shear strains are engineering strains (gamma = 2 eps).  In plane strain
 * eps_zz = 0 and sigma_zz = nu (sigma_xx + sigma_yy) is kept for post-processing.
 */
#ifndef LAC_MATERIAL_H
#define LAC_MATERIAL_H

typedef enum
{
  LAC_PLANE_STRAIN, LAC_AXISYMMETRIC, LAC_SOLID3D
} lac_model;

/* "plane_strain" | "axisymmetric" | "3d" -> model; -1 if unknown */
int lac_model_from_name (const char *name);
const char *lac_model_name (lac_model m);
int lac_model_dim (lac_model m);      /* 2, 2, 3 */
int lac_model_nstress (lac_model m);  /* 4, 4, 6 */

/* Check 0 < E and -1 < nu < 1/2 (message names the values). */
int lac_material_check (double E, double nu);

/* D (ns x ns, row-major) with sigma = D eps. */
int lac_material_D (lac_model m, double E, double nu, double *D);

/* The weight of the model's measure at x: 2 pi r (r = x[0]) for the
 * axisymmetric model, whose integrals are over the solid of revolution,
 * 1 otherwise.  Every volume and surface integral of lac uses it. */
double lac_model_weight (lac_model m, const double *x);

/* von Mises stress of a Voigt stress vector of the model. */
double lac_von_mises (lac_model m, const double *s);

#endif /* LAC_MATERIAL_H */
