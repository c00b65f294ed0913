/* lac_run_system.c -- stage 4 of a run: the system to solve
 *                     (see lac_run_system.h)    [LAC (8), (16)-(18); §4.3]
 */
#include "run/lac_run_system.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "run/lac_run_roller.h"
#include "run/lac_run_scene.h"

void
lac_run_system_clear (lac_run_system *sys)
{
  lac_csc_free (sys->K);
  lac_csc_free (sys->K0);
  lac_run_curves_free (sys->curves);
  lac_linear_lift_clear (&sys->lift);
  lac_free (sys->F);
  lac_free (sys->b);
  lac_dirichlet_free (sys->dir);
  lac_bodies_free (sys->bodies);
  lac_run_plate_clear (&sys->ties);
  lac_free (sys->N);
  lac_free (sys->fixed);
  for (size_t j = 0; sys->N_what && j < sys->nfree; j++)
    lac_free (sys->N_what[j]);
  lac_free (sys->N_what);
  memset (sys, 0, sizeof *sys);
}

/* ---- loads and Dirichlet data given by the scene ---------------------- */

typedef struct const_ctx
{
  int dim;
  double v[3];
} const_ctx;

static void
const_field (const double *x, void *ctx, double *out)
{
  const const_ctx *c = ctx;
  (void) x;
  for (int i = 0; i < c->dim; i++)
    out[i] = c->v[i];
}

/* A total force F on a boundary group, spread uniformly: the traction
 * F / |g|, |g| = sum of the x entries of the load of a unit traction
 * (the shape functions sum to one; axisymmetric: 2 pi r dGamma). */
static int
total_force (const lac_mesh *m, lac_model model, const lac_group *g,
             const double *force, double *F)
{
  size_t ndof = (size_t) m->dim * m->nnodes;
  double *one = lac_calloc (ndof, sizeof *one), area = 0;
  const_ctx c = { m->dim, { 1, 0, 0 } };
  int status = one ? lac_assembly_traction (m, model, g, const_field, &c, one)
                   : LAC_ERRMSG (LAC_ENOMEM, "area of group '%s'", g->name);
  for (size_t a = 0; !status && a < m->nnodes; a++)
    area += one[a * (size_t) m->dim];
  lac_free (one);
  if (status)
    return status;
  if (!(area > 0))
    LAC_ERROR (LAC_EINVAL, "group '%s' has no area to spread a force on",
               g->name);
  for (int i = 0; i < m->dim; i++)
    c.v[i] = force[i] / area;
  return lac_assembly_traction (m, model, g, const_field, &c, F);
}

/* F += the load of section k. */
static int
add_load (const lac_scene *sc, size_t k, lac_model model, const lac_mesh *m,
          double *F)
{
  const lac_scene_load *l = &sc->load[k];
  const lac_group *g = l->group ? lac_mesh_group (m, l->group) : NULL;
  const_ctx c = { m->dim, { l->vec[0], l->vec[1], l->vec[2] } };
  int status = LAC_SUCCESS;
  lac_exact e;
  lac_run_exact (sc, model, &e);
  if (l->kind == LAC_LOAD_EXACT_TRACTION)
    status = lac_assembly_traction_n (m, model, g, lac_exact_traction, &e,
                                      F);
  else if (l->kind == LAC_LOAD_EXACT_TANGENTIAL)
    status = lac_assembly_traction_n (m, model, g,
                                      lac_exact_traction_tangential, &e, F);
  else if (l->kind == LAC_LOAD_EXACT_FORCE)
    status = lac_assembly_volume_force (m, model, g, lac_exact_force, &e,
                                        F);
  else if (l->kind == LAC_LOAD_TOTAL)
    status = total_force (m, model, g, l->vec, F);
  else if (l->kind == LAC_LOAD_POINT)
    for (int i = 0; i < m->dim; i++)                   /* one node */
      F[g->node[0] * (size_t) m->dim + (size_t) i] += l->vec[i];
  else if (l->kind == LAC_LOAD_PRESSURE)
    status = lac_assembly_pressure (m, model, g, l->pressure, F);
  else if (l->kind == LAC_LOAD_TRACTION)
    status = lac_assembly_traction (m, model, g, const_field, &c, F);
  else
    status = lac_assembly_volume_force (m, model, g, const_field, &c, F);
  if (status)
    {
      char msg[600];
      lac_run_inner_message (msg, sizeof msg);
      return lac_scene_error (sc, &l->sec, NULL, status, "%s", msg);
    }
  return LAC_SUCCESS;
}

static int
add_loads (const lac_scene *sc, lac_model model, const lac_mesh *m,
           double *F)
{
  int status = LAC_SUCCESS;
  for (size_t k = 0; k < sc->nload && !status; k++)
    status = add_load (sc, k, model, m, F);
  return status;
}

/* ---- load steps of a small-strain scene ------------------------------- */

/* [steps] in a small-strain scene: the loads by curve
 * (run/lac_run_curves.h). */
static int
small_steps (const lac_scene *sc)
{
  return !sc->scene.large_deformation && sc->steps.sec.line != 0;
}

/* The curves, F_c of each, the curve of each Dirichlet entry. */
static int
curves_build (const lac_scene *sc, lac_model model, const lac_mesh *m,
              lac_run_system *sys)
{
  lac_run_curves *cv = lac_run_curves_alloc (sc, sys->ndof);
  int status = cv ? LAC_SUCCESS : LAC_ENOMEM;
  sys->curves = cv;
  for (size_t k = 0; k < sc->nload && !status; k++)
    status = add_load (sc, k, model, m, cv->F + cv->of_load[k] * cv->ndof);
  return status ? status : lac_run_curves_entries (sc, model, m, sys->dir,
                                                   cv);
}

static int
add_dirichlet (const lac_scene *sc, lac_model model, const lac_mesh *m,
               lac_dirichlet *d)
{
  int status = LAC_SUCCESS;
  lac_exact e;
  lac_run_exact (sc, model, &e);
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      const lac_scene_dirichlet *bc = &sc->dirichlet[k];
      const lac_group *g = lac_mesh_group (m, bc->group);
      if (bc->kind == LAC_BC_EXACT)
        status = lac_dirichlet_add_field (d, m, g, lac_exact_u, &e);
      for (int c = 0; c < m->dim && bc->kind != LAC_BC_EXACT && !status; c++)
        if (bc->fixed[c])
          status = lac_dirichlet_add_group (d, m, g, c, bc->value[c]);
    }
  /* normal = g: the nodes of those groups in frames (run/lac_run_roller.h) */
  return status ? status : lac_run_rollers (sc, model, m, d);
}

/* ---- bodies: fixed, or held by contact ------------------------------- */

/* Does body b touch a contact surface?  Such a body may be held by the
 * contact constraints alone (the upper block of a patch test). */
static int
body_on_contact (const lac_bodies *B, const lac_run_setup *setup,
                 size_t nnodes, size_t b)
{
  if (!setup->on_contact)
    return 0;
  for (size_t a = 0; a < nnodes; a++)
    if (B->node_body[a] == b && setup->on_contact[a])
      return 1;
  return 0;
}

/* Why rollers do not hold body b, if they are on a curved face. */
static const char *
slide_hint (const lac_bodies *B, size_t b)
{
  return B->body[b].slide ? ": a roller lets a curved face slide along "
                            "itself" : "";
}

/* Every body that touches no contact surface must be fixed against rigid
 * motion (else K is singular, and a pivot message could not say why); the
 * free motions of those that touch one are N. */
static int
check_bodies (const lac_scene *sc, const lac_mesh *m,
              const lac_run_setup *setup, lac_run_system *sys)
{
  const lac_bodies *B = sys->bodies;
  char *held_by_contact = lac_calloc (B->n + 1, 1);
  int status = held_by_contact ? LAC_SUCCESS
               : lac_error_set (LAC_ENOMEM, sc->path, "checking the bodies");
  if (!status && !sc->scene.large_deformation)     /* rigid plates */
    status = lac_run_plate_motions (sc, m, sys->bodies);
  for (size_t b = 0; !status && b < B->n; b++)
    {
      const char *name = lac_bodies_name (B, m, b);
      if (B->body[b].nfree == 0)
        continue;
      if (body_on_contact (B, setup, m->nnodes, b))
        held_by_contact[b] = 1;
      else if (name)
        status = lac_error_set (LAC_ESING, sc->path, "stiffness is singular:"
                                " body '%s' is not fixed against rigid "
                                "motion (%s%s); add [dirichlet] conditions "
                                "that prevent it", name, B->body[b].desc,
                                slide_hint (B, b));
      else
        status = lac_error_set (LAC_ESING, sc->path, "stiffness is singular:"
                                " the cells around cell %zu are not fixed "
                                "against rigid motion (%s%s); add "
                                "[dirichlet] conditions that prevent it",
                                m->cell_tag[B->body[b].cell0],
                                B->body[b].desc, slide_hint (B, b));
    }
  if (!status)
    status = lac_bodies_free_motions (B, m, held_by_contact, &sys->nfree,
                                      &sys->N, &sys->N_what);
  for (size_t j = 0; !status && j < sys->nfree; j++)     /* N~ = T^T N */
    lac_frames_to_local (sys->dir->frames, sys->N + j * sys->ndof);
  lac_free (held_by_contact);
  return status;
}

static int
find_bodies (const lac_scene *sc, lac_model model, const lac_mesh *m,
             const lac_run_setup *setup, lac_run_system *sys)
{
  char *fixed = lac_calloc (sys->ndof, 1);
  int status;
  if (!fixed)
    LAC_ERROR (LAC_ENOMEM, "rigid-motion check");
  for (size_t k = 0; k < sys->dir->n; k++)
    fixed[sys->dir->dof[k]] = 1;
  status = lac_bodies_find (m, model, fixed, sys->dir->frames,
                            &sys->bodies);
  lac_free (fixed);
  return status ? status : check_bodies (sc, m, setup, sys);
}

/* ---- contact: admissibility, C, G ------------------------------------- */

/* The contact data of every pair (admissibility, C, G; each pair's
 * interference in its gaps) into the set-up's; C of all pairs side by
 * side turned to the nodal frames of rollers (T^T C), the Dirichlet
 * values moved into G. */
static int
contact_matrices (const lac_scene *sc, lac_run_setup *setup,
                  lac_run_system *sys)
{
  int status = lac_contact_set_assemble (&setup->set, NULL, &setup->data);
  if (status)
    return lac_run_setup_error (sc, setup, status == LAC_EADMISS
                                ? "epsilon" : NULL, status);
  lac_contact *all = setup->data.all;    /* each pair's gaps g0 - delta */
  sys->contact = all;
  if ((status = lac_run_interference_check (sc, &setup->set, &setup->data,
                                            &sys->fit)))
    return status;                 /* before the Dirichlet values move in */
  if (all && (status = lac_contact_to_frames (all, sys->dir->frames)))
                                                             /* T^T C */
    return status;
  if (sys->curves)           /* load steps: G0 and C_D kept for the steps */
    return lac_linear_lift_record (sys->dir, all, &sys->lift);
  return lac_contact_apply_dirichlet (all, sys->dir->n, sys->dir->dof,
                                      sys->dir->val);
}

/* Large deformation: the fits measured on contact data of the reference
 * shape made for it alone (the loop makes its own at every iteration,
 * where nothing in reach is no error: here neither). */
static int
fits_large (const lac_scene *sc, lac_run_setup *setup, lac_run_system *sys)
{
  lac_contact_set_data d = { 0 };
  int status, any = 0;
  for (size_t p = 0; p < sc->ncontact; p++)
    any |= sc->contact[p].interference > 0;
  if (!any)
    return LAC_SUCCESS;
  for (size_t p = 0; p < setup->npairs; p++)
    setup->pair[p].popts.allow_empty = 1;
  status = lac_contact_set_build (&setup->set, NULL, &d);
  for (size_t p = 0; p < setup->npairs; p++)
    setup->pair[p].popts.allow_empty = 0;
  if (status)
    status = lac_scene_error (sc, &sc->contact[d.failed < sc->ncontact
                                               ? d.failed : 0].sec,
                              NULL, status, "%s", lac_error_message ());
  else
    status = lac_run_interference_check (sc, &setup->set, &d, &sys->fit);
  lac_contact_set_data_clear (&d);
  return status;
}

/* ---- the stage -------------------------------------------------------- */

/* The fixed dofs and their number. */
static int
count_fixed (lac_run_system *sys)
{
  char *seen = sys->fixed = lac_calloc (sys->ndof, 1);
  if (!seen)
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  for (size_t k = 0; k < sys->dir->n; k++)
    if (!seen[sys->dir->dof[k]])
      seen[sys->dir->dof[k]] = 1, sys->nfixed++;
  return LAC_SUCCESS;
}

/* K after the Dirichlet elimination, and b; with rollers, in the nodal
 * frames first (T^T K T, T^T F: fem/lac_frames.h). */
static int
eliminate (const lac_scene *sc, lac_run_system *sys)
{
  int status;
  sys->nnz = (size_t) sys->K->p[sys->ndof];
  if (sc->output.matrix && !(sys->K0 = lac_csc_copy (sys->K)))
    LAC_ERROR (LAC_ENOMEM, "copy of K");
  memcpy (sys->b, sys->F, sys->ndof * sizeof *sys->b);
  if ((status = lac_frames_rotate_matrix (sys->dir->frames, sys->K))
      || (sys->curves                     /* load steps: b of each curve */
          && (status = lac_run_curves_lift (sys->curves, sys->K,
                                            sys->dir))))
    return status;
  lac_frames_to_local (sys->dir->frames, sys->b);
  return lac_dirichlet_apply (sys->dir, sys->K, sys->b);
}

/* The stiffness triplets' list, sized for every cell block (the rigid
 * plates' condensation works on it). */
static lac_triplet *
alloc_triplets (const lac_mesh *m, size_t ndof)
{
  size_t cap = 0;
  for (size_t c = 0; c < m->ncells; c++)
    {
      size_t nc = (m->ptr[c + 1] - m->ptr[c]) * (size_t) m->dim;
      cap += nc * nc;                          /* entries of K_e */
    }
  return lac_triplet_alloc (ndof, ndof, cap ? cap : 1);
}

int
lac_run_system_build (const lac_scene *sc, lac_model model,
                      const lac_mesh *m, const lac_run_material *mat,
                      lac_run_setup *setup, lac_run_system *sys,
                      char *progress, size_t size)
{
  lac_triplet *T = NULL;
  int status = LAC_SUCCESS, large = sc->scene.large_deformation, plates = 0;
  memset (sys, 0, sizeof *sys);
  sys->ndof = (size_t) m->dim * m->nnodes;
  sys->coord_dim = m->dim;
  sys->x = model == LAC_AXISYMMETRIC ? NULL : m->x;
  for (size_t k = 0; !large && k < sc->nload; k++)
    plates |= sc->load[k].plate != 0;
  sys->F = lac_calloc (sys->ndof, sizeof *sys->F);
  sys->b = lac_malloc (sys->ndof * sizeof *sys->b);
  sys->dir = lac_dirichlet_alloc ();
  if (plates)
    T = alloc_triplets (m, sys->ndof);
  if (!sys->F || !sys->b || !sys->dir || (plates && !T))
    LAC_ERROR (LAC_ENOMEM, "system of %zu dofs", sys->ndof);
  /* With rigid plates K through triplets here, which their condensation
   * works on; else K after the rest (lac_run_system_stiffness); the
   * Newton loop of large deformation assembles K_T itself. */
  if ((plates && (status = lac_assembly_stiffness (m, &mat->elastic, T)))
      || (status = add_loads (sc, model, m, sys->F))          /* F = l(v)    */
      || (status = add_dirichlet (sc, model, m, sys->dir))
      || (status = find_bodies (sc, model, m, setup, sys))
      || (status = count_fixed (sys))
      || (small_steps (sc) && (status = curves_build (sc, model, m, sys)))
      || (sc->ncontact && !large                           /* C, G (else: */
          && (status = contact_matrices (sc, setup, sys))))
    goto done;                                       /* per Newton it.) */
  if (large)                              /* the Newton loop's affair */
    {
      memcpy (sys->b, sys->F, sys->ndof * sizeof *sys->b);
      snprintf (progress, size, "%zu dofs, loads and Dirichlet data (K_T: "
                "at every Newton iteration)", sys->ndof);
      status = fits_large (sc, setup, sys);
      lac_run_interference_warning (sc, &sys->fit, progress, size);
      goto done;
    }
  if (plates
      && (status = lac_run_plate_tie (sc, m, setup, T, sys->F, sys->dir,
                                      &sys->ties)))
    goto done;
  if (plates && sys->curves)
    lac_run_curves_tie (sys->curves, &sys->ties);       /* P^T F_c */
  if (plates
      && ((!(sys->K = lac_csc_from_triplet (T)) && (status = LAC_ENOMEM))
          || (status = eliminate (sc, sys))))
    goto done;
done:
  lac_triplet_free (T);
  return status;
}

/* The progress line of stage 4. */
static void
system_progress (const lac_run_system *sys, char *progress, size_t size)
{
  if (sys->ties.n)
    snprintf (progress, size, "%zu dofs (%zu fixed, %zu tied to %zu rigid "
              "plates), %zu nonzeros in K", sys->ndof, sys->nfixed,
              sys->ties.n, sys->ties.nplates, sys->nnz);
  else
    snprintf (progress, size, "%zu dofs (%zu fixed), %zu nonzeros in K%s",
              sys->ndof, sys->nfixed, sys->nnz, sys->k_by_solver
              ? " (not made: the solver assembles it from the cells)" : "");
}

int
lac_run_system_stiffness (const lac_scene *sc, const lac_mesh *m,
                          const lac_run_material *mat, int from_cells,
                          lac_run_system *sys, char *progress, size_t size)
{
  int status;
  if (sc->scene.large_deformation)
    return LAC_SUCCESS;                 /* K_T: the Newton loop's affair */
  if (sys->ties.n || sys->K)
    {
      system_progress (sys, progress, size);  /* made with the plates */
      lac_run_interference_warning (sc, &sys->fit, progress, size);
      return LAC_SUCCESS;
    }
  if (from_cells && !sys->dir->frames && !sc->output.matrix)
    {                                   /* b and the entries: no K */
      memcpy (sys->b, sys->F, sys->ndof * sizeof *sys->b);
      if ((status = lac_assembly_digest (m, &mat->elastic, sys->dir, sys->b,
                                         &sys->nnz))
          || (sys->curves                 /* load steps: b of each curve */
              && (status = lac_run_curves_digest (sys->curves, m,
                                                  &mat->elastic, sys->dir))))
        return status;
      sys->k_by_solver = 1;
    }
  /* K in its compressed columns straight away (no triplet list: the peak
   * of the assembly is K and the map of the cells). */
  else if ((status = lac_assembly_stiffness_csc (m, &mat->elastic, &sys->K))
           || (status = eliminate (sc, sys)))
    return status;
  if (!sys->dir->frames)   /* K is the cells' (and Dirichlet's): not turned
                              to rollers' frames */
    sys->cells = (lac_dist_source) { m, &mat->elastic, sys->fixed };
  system_progress (sys, progress, size);
  lac_run_interference_warning (sc, &sys->fit, progress, size);
  return LAC_SUCCESS;
}
