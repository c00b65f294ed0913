/* lac_run.c -- the pipeline of one scene (see lac_run.h)            [LAC §2]
 *
 * Each stage is a function stage_<name> of the run; lac_run_iterate calls
 * the next one and times it.  Errors about the scene point at the scene
 * line (lac_scene_error); errors of the modules keep their message, with
 * the scene line prepended where one is responsible.
 *
 * This file holds the run itself (alloc / iterate / free, the summary
 * lines) and the stages mesh, material, assemble and solve; the
 * rigid-motion check of the assemble stage is in lac_run_rigid.c, the
 * stages post and output in lac_run_post.c, the exact solutions in
 * lac_exact.c.
 */
#include "run/lac_run_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "base/lac_mem.h"
#include "io/lac_mesh_gmsh.h"
#include "base/lac_status.h"

static const char *const stage_names[LAC_NSTAGES] =
  { "mesh", "contact", "material", "assemble", "solve", "post", "output" };

const char *
lac_run_stage_name (int stage)
{
  return stage >= 0 && stage < LAC_NSTAGES ? stage_names[stage] : "done";
}

/* ---- fields given by the scene ---------------------------------------- */

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

/* ---- the exact solution ----------------------------------------------- */

void
lac_run_exact (const lac_run *r, lac_exact *e)
{
  const lac_scene_exact *x = &r->scene->exact;
  lac_exact_params p = { x->a, x->b, x->p, x->E, x->nu };
  lac_exact_init (e, x->solution, r->model, &p);
}

/* ---- helpers ---------------------------------------------------------- */

double
lac_run_now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

int
lac_run_summary_add (lac_run *r, const char *key, const char *fmt, ...)
{
  char buf[512];
  va_list ap;
  if (r->nsummary == r->capsummary)
    {
      size_t cap = r->capsummary ? 2 * r->capsummary : 32;
      char **k = lac_realloc (r->key, cap * sizeof *k);
      char **v = k ? lac_realloc (r->val, cap * sizeof *v) : NULL;
      if (k)
        r->key = k;
      if (!v)
        LAC_ERROR (LAC_ENOMEM, "out of memory");
      r->val = v;
      r->capsummary = cap;
    }
  va_start (ap, fmt);
  vsnprintf (buf, sizeof buf, fmt, ap);
  va_end (ap);
  r->key[r->nsummary] = lac_strdup (key);
  r->val[r->nsummary] = lac_strdup (buf);
  if (!r->key[r->nsummary] || !r->val[r->nsummary])
    {
      lac_free (r->key[r->nsummary]);
      lac_free (r->val[r->nsummary]);
      LAC_ERROR (LAC_ENOMEM, "out of memory");
    }
  r->nsummary++;
  return LAC_SUCCESS;
}

const char *
lac_run_summary_get (const lac_run *r, const char *key)
{
  for (size_t k = 0; k < r->nsummary; k++)
    if (strcmp (r->key[k], key) == 0)
      return r->val[k];
  return NULL;
}

/* The current message without its "lac_function: " prefix. */
static void
inner_message (char *buf, size_t size)
{
  const char *m = lac_error_message (), *colon = strstr (m, ": ");
  if (strncmp (m, "lac_", 4) == 0 && colon && !memchr (m, ' ', (size_t)
                                                       (colon - m)))
    m = colon + 2;
  snprintf (buf, size, "%s", m);
}

/* "body, left, right" */
static void
group_list (const lac_mesh *m, char *buf, size_t size)
{
  size_t len = 0;
  buf[0] = '\0';
  for (size_t g = 0; g < m->ngroups && len + 8 < size; g++)
    {
      int w = snprintf (buf + len, size - len, "%s%s", g ? ", " : "",
                        m->group[g].name);
      if (w < 0 || (size_t) w >= size - len)
        {
          snprintf (buf + len, size - len, ", ...");
          break;
        }
      len += (size_t) w;
    }
  if (m->ngroups == 0)
    snprintf (buf, size, "none");
}

/* The group named by key `group` of section s, checked for its dimension
 * (dim_want < 0: any).  NULL with a message naming the scene line. */
static const lac_group *
find_group (const lac_run *r, const lac_scene_section *s, const char *name,
            int dim_want, const char *what)
{
  const lac_group *g = lac_mesh_group (r->mesh, name);
  char list[400];
  if (!g)
    {
      group_list (r->mesh, list, sizeof list);
      lac_scene_error (r->scene, s, "group", LAC_EINVAL, "no physical group "
                       "of that name in mesh '%s' (groups: %s)",
                       r->scene->mesh.file, list);
      return NULL;
    }
  if (dim_want >= 0 && g->dim != dim_want)
    {
      lac_scene_error (r->scene, s, "group", LAC_EINVAL, "group of dimension"
                       " %d; %s needs a group of dimension %d", g->dim, what,
                       dim_want);
      return NULL;
    }
  return g;
}

/* ---- stage 1: mesh ---------------------------------------------------- */

static int
check_groups (lac_run *r)
{
  const lac_scene *sc = r->scene;
  int d = r->dim;
  for (size_t k = 0; k < sc->nmaterial; k++)
    if (sc->material[k].group
        && !find_group (r, &sc->material[k].sec, sc->material[k].group, d,
                        "a material"))
      return LAC_EINVAL;
  for (size_t k = 0; k < sc->ndirichlet; k++)
    if (!find_group (r, &sc->dirichlet[k].sec, sc->dirichlet[k].group, -1,
                     NULL))
      return LAC_EINVAL;
  for (size_t k = 0; k < sc->nload; k++)
    {
      const lac_scene_load *l = &sc->load[k];
      int vol = l->kind == LAC_LOAD_FORCE || l->kind == LAC_LOAD_EXACT_FORCE;
      int want = vol ? d : d - 1;
      if (l->group && !find_group (r, &l->sec, l->group, want,
                                   vol ? "a volume force" : "a surface load"))
        return LAC_EINVAL;
    }
  return LAC_SUCCESS;
}

static int
check_mesh (lac_run *r)
{
  const lac_scene *sc = r->scene;
  const lac_mesh *m = r->mesh;
  double xmax = 0;
  if (m->dim != r->dim)
    return lac_scene_error (sc, &sc->mesh.sec, "file", LAC_EINVAL, "a %dD "
                            "mesh; model = %s needs a %dD mesh", m->dim,
                            lac_model_name (r->model), r->dim);
  if (sc->scene.element != LAC_ELEM_NONE)
    for (size_t c = 0; c < m->ncells; c++)
      if ((int) m->type[c] != sc->scene.element)
        return lac_scene_error (sc, &sc->scene.sec, "element", LAC_EINVAL,
                                "mesh '%s' has %s cells (cell %zu)",
                                sc->mesh.file,
                                lac_refelem_get (m->type[c])->name,
                                m->cell_tag[c]);
  for (size_t a = 0; a < m->nnodes * (size_t) m->dim; a++)
    xmax = fmax (xmax, fabs (m->x[a]));
  if (r->model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      if (m->x[a * 2] < -1e-12 * xmax)
        return lac_scene_error (sc, &sc->scene.sec, "model", LAC_EINVAL,
                                "node %zu of mesh '%s' has r = x = %g < 0",
                                m->node_tag[a], sc->mesh.file, m->x[a * 2]);
  return check_groups (r);
}

static int
stage_mesh (lac_run *r)
{
  const lac_scene *sc = r->scene;
  lac_mesh_opts o;
  char msg[700];
  int status;
  memset (&o, 0, sizeof o);
  o.size = sc->mesh.size;
  o.order = sc->mesh.order;
  o.serendipity = sc->scene.element == LAC_QUAD8
                  || sc->scene.element == LAC_HEX20;
  o.recombine = sc->mesh.recombine > 0;
  o.level = sc->mesh.level;
  o.numbers = sc->mesh.numbers;
  o.flip_inverted = sc->mesh.inverted == 0;
  status = lac_mesh_read (sc->mesh.path, &o, &r->mesh);
  if (status)
    {
      char quoted[600];
      size_t n;
      inner_message (msg, sizeof msg);
      n = (size_t) snprintf (quoted, sizeof quoted, "'%s': ", sc->mesh.path);
      return lac_scene_error (sc, &sc->mesh.sec, "file", status, "%s",
                              strncmp (msg, quoted, n) ? msg : msg + n);
    }
  if ((status = check_mesh (r)))
    return status;
  r->ndof = (size_t) r->dim * r->mesh->nnodes;
  snprintf (r->progress, sizeof r->progress, "%zu nodes, %zu cells (%s), "
            "%zu groups", r->mesh->nnodes, r->mesh->ncells,
            r->mesh->ncells ? lac_refelem_get (r->mesh->type[0])->name : "-",
            r->mesh->ngroups);
  return LAC_SUCCESS;
}

/* ---- stage 2: material ------------------------------------------------ */

/* E, nu of the cells of the materials with a group; owner[c] = the
 * material of cell c (-1: none yet), *dflt = the material without group
 * (NULL if none). */
static int
material_groups (lac_run *r, int *owner, const lac_scene_material **dflt)
{
  const lac_scene *sc = r->scene;
  const lac_mesh *m = r->mesh;
  *dflt = NULL;
  for (size_t c = 0; c < m->ncells; c++)
    owner[c] = -1;
  for (size_t k = 0; k < sc->nmaterial; k++)
    {
      const lac_scene_material *mt = &sc->material[k];
      const lac_group *g;
      if (!mt->group)
        {
          *dflt = mt;
          continue;
        }
      g = lac_mesh_group (m, mt->group);
      for (size_t j = 0; j < g->n; j++)
        {
          size_t c = g->cell[j];
          if (owner[c] >= 0)
            return lac_scene_error (sc, &mt->sec, "group", LAC_EINVAL,
                                    "cell %zu is also in [material %s]",
                                    m->cell_tag[c],
                                    sc->material[owner[c]].sec.name);
          owner[c] = (int) k;
          r->E[c] = mt->E;
          r->nu[c] = mt->nu;
          r->law[c] = (char) mt->law;
        }
    }
  return LAC_SUCCESS;
}

static int
stage_material (lac_run *r)
{
  const lac_scene *sc = r->scene;
  const lac_mesh *m = r->mesh;
  const lac_scene_material *dflt = NULL;
  int *owner, status;
  r->E = lac_malloc (m->ncells * sizeof *r->E);
  r->nu = lac_malloc (m->ncells * sizeof *r->nu);
  r->law = lac_calloc (m->ncells, 1);
  owner = lac_malloc (m->ncells * sizeof *owner);
  if (!r->E || !r->nu || !r->law || !owner)
    {
      lac_free (owner);
      LAC_ERROR (LAC_ENOMEM, "material arrays for %zu cells", m->ncells);
    }
  if ((status = material_groups (r, owner, &dflt)))
    {
      lac_free (owner);
      return status;
    }
  for (size_t c = 0; c < m->ncells; c++)
    if (owner[c] < 0 && dflt)
      {
        owner[c] = (int) (dflt - sc->material);
        r->E[c] = dflt->E;
        r->nu[c] = dflt->nu;
        r->law[c] = (char) dflt->law;
      }
    else if (owner[c] < 0)
      {
        const char *body = m->body[c] >= 0 ? m->group[m->body[c]].name : NULL;
        lac_free (owner);
        if (body)
          return lac_error_set (LAC_EINVAL, sc->path, "cell %zu of mesh '%s'"
                                " (group '%s') has no material: add a "
                                "[material NAME] with group = %s",
                                m->cell_tag[c], sc->mesh.file, body, body);
        return lac_error_set (LAC_EINVAL, sc->path, "cell %zu of mesh '%s' "
                              "is in no volume physical group and has no "
                              "material: add a [material NAME] without group",
                              m->cell_tag[c], sc->mesh.file);
      }
  lac_free (owner);
  r->mat.model = r->model;
  r->mat.E = r->E;
  r->mat.nu = r->nu;
  int nh = 0;
  for (size_t k = 0; k < sc->nmaterial; k++)
    nh += sc->material[k].law != 0;
  snprintf (r->progress, sizeof r->progress, "%zu material%s, %s",
            sc->nmaterial, sc->nmaterial > 1 ? "s" : "",
            nh == (int) sc->nmaterial ? "neo-Hookean"
            : nh ? "neo-Hookean and linear elastic"
            : sc->scene.large_deformation ? "linear elastic (Saint "
              "Venant-Kirchhoff)" : "linear elastic");
  return LAC_SUCCESS;
}

/* ---- stage 3: assemble ------------------------------------------------ */

static int
add_loads (lac_run *r)
{
  const lac_scene *sc = r->scene;
  int status = LAC_SUCCESS;
  for (size_t k = 0; k < sc->nload && !status; k++)
    {
      const lac_scene_load *l = &sc->load[k];
      const lac_group *g = l->group ? lac_mesh_group (r->mesh, l->group)
                           : NULL;
      const_ctx c = { r->dim, { l->vec[0], l->vec[1], l->vec[2] } };
      lac_exact e;
      lac_run_exact (r, &e);
      if (l->kind == LAC_LOAD_EXACT_TRACTION)
        status = lac_assembly_traction_n (r->mesh, r->model, g,
                                          lac_exact_traction, &e, r->F);
      else if (l->kind == LAC_LOAD_EXACT_TANGENTIAL)
        status = lac_assembly_traction_n (r->mesh, r->model, g,
                                          lac_exact_traction_tangential, &e,
                                          r->F);
      else if (l->kind == LAC_LOAD_EXACT_FORCE)
        status = lac_assembly_volume_force (r->mesh, r->model, g,
                                            lac_exact_force, &e, r->F);
      else if (l->kind == LAC_LOAD_PRESSURE)
        status = lac_assembly_pressure (r->mesh, r->model, g, l->pressure,
                                        r->F);
      else if (l->kind == LAC_LOAD_TRACTION)
        status = lac_assembly_traction (r->mesh, r->model, g, const_field, &c,
                                        r->F);
      else
        status = lac_assembly_volume_force (r->mesh, r->model, g,
                                            const_field, &c, r->F);
      if (status)
        {
          char msg[600];
          inner_message (msg, sizeof msg);
          return lac_scene_error (sc, &l->sec, NULL, status, "%s", msg);
        }
    }
  return status;
}

static int
add_dirichlet (lac_run *r, lac_dirichlet *d)
{
  const lac_scene *sc = r->scene;
  int status = LAC_SUCCESS;
  lac_exact e;
  lac_run_exact (r, &e);
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      const lac_scene_dirichlet *bc = &sc->dirichlet[k];
      const lac_group *g = lac_mesh_group (r->mesh, bc->group);
      if (bc->kind == LAC_BC_EXACT)
        status = lac_dirichlet_add_field (d, r->mesh, g, lac_exact_u, &e);
      for (int c = 0; c < r->dim && bc->kind != LAC_BC_EXACT && !status; c++)
        if (bc->fixed[c])
          status = lac_dirichlet_add_group (d, r->mesh, g, c, bc->value[c]);
    }
  return status;
}

static lac_csc *
csc_copy (const lac_csc *A)
{
  lac_csc *B = lac_csc_alloc (A->nrow, A->ncol, (size_t) A->p[A->ncol]);
  if (!B)
    return NULL;
  memcpy (B->p, A->p, (A->ncol + 1) * sizeof *B->p);
  memcpy (B->i, A->i, (size_t) A->p[A->ncol] * sizeof *B->i);
  memcpy (B->x, A->x, (size_t) A->p[A->ncol] * sizeof *B->x);
  return B;
}

static int
stage_assemble (lac_run *r)
{
  const lac_mesh *m = r->mesh;
  lac_triplet *T = NULL;
  lac_dirichlet *d = NULL;
  char *seen = NULL;
  size_t cap = 0;
  int status = LAC_SUCCESS;
  for (size_t c = 0; c < m->ncells; c++)
    {
      size_t nc = (m->ptr[c + 1] - m->ptr[c]) * (size_t) r->dim;
      cap += nc * nc;                          /* entries of K_e */
    }
  T = lac_triplet_alloc (r->ndof, r->ndof, cap);
  r->F = lac_calloc (r->ndof, sizeof *r->F);
  r->b = lac_malloc (r->ndof * sizeof *r->b);
  d = lac_dirichlet_alloc ();
  if (!T || !r->F || !r->b || !d)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "system of %zu dofs", r->ndof);
      goto done;
    }
  if ((status = lac_assembly_stiffness (m, &r->mat, T))   /* K = sum K_e */
      || (status = add_loads (r))                           /* F = l(v)    */
      || (status = add_dirichlet (r, d))
      || (status = lac_run_check_rigid (r, d))
      || (!r->scene->scene.large_deformation          /* C, G (else: */
          && (status = lac_run_contact_assemble (r, d)))) /* per Newton it.) */
    goto done;
  if (!(r->K = lac_csc_from_triplet (T)))
    {
      status = LAC_ENOMEM;
      goto done;
    }
  r->nnz = (size_t) r->K->p[r->ndof];
  if (r->scene->output.matrix && !(r->K0 = csc_copy (r->K)))
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "copy of K");
      goto done;
    }
  memcpy (r->b, r->F, r->ndof * sizeof *r->b);
  if ((status = lac_dirichlet_apply (d, r->K, r->b)))
    goto done;
  if (!(seen = lac_calloc (r->ndof, 1)))
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "out of memory");
      goto done;
    }
  for (size_t k = 0; k < d->n; k++)
    if (!seen[d->dof[k]])
      seen[d->dof[k]] = 1, r->nfixed++;
  snprintf (r->progress, sizeof r->progress, "%zu dofs (%zu fixed), "
            "%zu nonzeros in K", r->ndof, r->nfixed, r->nnz);
done:
  lac_free (seen);
  lac_dirichlet_free (d);
  lac_triplet_free (T);
  return status;
}

/* ---- stage 4: solve --------------------------------------------------- */

static int
stage_solve (lac_run *r)
{
  lac_solver *s = lac_solver_alloc ((lac_solver_kind) r->scene->scene.solver);
  lac_solver_info info;
  int status;
  if (r->contact)
    {
      lac_solver_free (s);
      return lac_run_contact_solve (r);              /* [LAC Alg. 1] */
    }
  if (!s)
    return LAC_ENOMEM;
  if (!(r->u = lac_malloc (r->ndof * sizeof *r->u)))
    {
      lac_solver_free (s);
      LAC_ERROR (LAC_ENOMEM, "displacement of %zu dofs", r->ndof);
    }
  status = lac_solver_factor (s, r->K);                  /* K = L U, L L^T */
  if (status == LAC_ESING)
    {
      char msg[600];
      inner_message (msg, sizeof msg);
      status = lac_error_set (status, r->scene->path, "stiffness is singular"
                              " (%s solver): %s", r->solver_name, msg);
    }
  if (!status)
    status = lac_solver_solve (s, r->b, r->u);          /* u = K^-1 b */
  if (!status && lac_solver_get_info (s, &info) == LAC_SUCCESS)
    r->rcond = info.rcond;
  lac_solver_free (s);
  if (status)
    return status;
  lac_csc_free (r->K);
  r->K = NULL;
  snprintf (r->progress, sizeof r->progress, "%s, rcond %.1e",
            r->solver_name, r->rcond);
  return LAC_SUCCESS;
}

/* ---- the run ---------------------------------------------------------- */

lac_run *
lac_run_alloc (const lac_scene *sc, const lac_run_opts *opts)
{
  lac_run *r;
  const char *out;
  size_t len;
  if (!sc)
    LAC_ERROR_NULL (LAC_EINVAL, "no scene");
  if (!(r = lac_calloc (1, sizeof *r)))
    LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
  if (opts)
    r->opts = *opts;
  r->scene = sc;
  r->model = (lac_model) sc->scene.model;
  r->dim = lac_model_dim (r->model);
  r->ns = lac_model_nstress (r->model);
  r->solver_name = lac_solver_kind_name ((lac_solver_kind) sc->scene.solver);
  out = r->opts.out_dir ? r->opts.out_dir : sc->scene.out;
  len = out ? strlen (out) + 1 : strlen (sc->basename) + 5;
  if (!(r->out_dir = lac_malloc (len)))
    {
      lac_free (r);
      LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
    }
  if (out)
    snprintf (r->out_dir, len, "%s", out);
  else
    snprintf (r->out_dir, len, "out/%s", sc->basename);
  r->opts.out_dir = r->out_dir;
  r->effects[r->neffects++] = r->model == LAC_PLANE_STRAIN ? "plane strain"
    : r->model == LAC_AXISYMMETRIC ? "axisymmetric" : "3D solid";
  if (sc->ncontact)
    r->effects[r->neffects++] = "frictionless contact (LAC)";
  if (sc->scene.large_deformation)
    {
      int nh = 0;
      for (size_t k = 0; k < sc->nmaterial; k++)
        nh += sc->material[k].law != 0;
      r->effects[r->neffects++] = "large deformation";
      if (nh)
        r->effects[r->neffects++] = "neo-Hookean material";
      if (nh < (int) sc->nmaterial)
        r->effects[r->neffects++] = "Saint Venant-Kirchhoff material";
      if (sc->ncontact)
        r->effects[r->neffects++] = "re-pairing every iteration";
      if (sc->steps.n > 1 || sc->steps.start > 0)
        r->effects[r->neffects++] = "load steps";
      return r;
    }
  r->effects[r->neffects++] = "small strain";
  r->effects[r->neffects++] = "linear elastic material";
  return r;
}

void
lac_run_free (lac_run *r)
{
  if (!r)
    return;
  for (size_t k = 0; k < r->nsummary; k++)
    lac_free (r->key[k]), lac_free (r->val[k]);
  lac_free (r->key);
  lac_free (r->val);
  lac_free (r->u_exact);
  lac_free (r->lam_x);
  lac_free (r->lam_exact);
  lac_free (r->on_contact);
  lac_newton_free (r->newton);
  lac_contact_free (r->contact);
  lac_pairing_free (r->pairing);
  lac_macromesh_free (r->macro);
  lac_free (r->vm);
  lac_free (r->sigma);
  lac_free (r->u);
  lac_free (r->b);
  lac_free (r->F);
  lac_csc_free (r->K0);
  lac_csc_free (r->K);
  lac_free (r->nu);
  lac_free (r->E);
  lac_free (r->law);
  lac_run_nl_free (r->nl);
  lac_mesh_free (r->mesh);
  lac_free (r->out_dir);
  lac_free (r);
}

int
lac_run_iterate (lac_run *r)
{
  static int (*const stage[LAC_NSTAGES]) (lac_run *) = {
    stage_mesh, lac_run_stage_contact, stage_material, stage_assemble, stage_solve,
    lac_run_stage_post, lac_run_stage_output };
  static int (*const stage_nl[LAC_NSTAGES]) (lac_run *) = {  /* large def. */
    stage_mesh, lac_run_nl_contact, stage_material, stage_assemble,
    lac_run_nl_solve, lac_run_nl_post, lac_run_nl_output };
  double t0 = lac_run_now ();
  int status;
  if (r->stage >= LAC_NSTAGES)
    return LAC_SUCCESS;
  r->progress[0] = '\0';
  status = (r->scene->scene.large_deformation ? stage_nl : stage)[r->stage] (r);
  r->time[r->stage] += lac_run_now () - t0;   /* solve: all load steps */
  if (status == LAC_CONTINUE)                 /* a load step: same stage */
    return LAC_CONTINUE;
  if (status)
    return status;
  r->stage++;
  return r->stage < LAC_NSTAGES ? LAC_CONTINUE : LAC_SUCCESS;
}

int
lac_run_all (lac_run *r)
{
  int status;
  while ((status = lac_run_iterate (r)) == LAC_CONTINUE)
    ;
  return status;
}
