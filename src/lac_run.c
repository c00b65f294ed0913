/* lac_run.c -- the pipeline of one scene (see lac_run.h)            [LAC §2]
 *
 * Each stage is a function stage_<name> of the run; lac_run_iterate calls
 * the next one and times it.  Errors about the scene point at the scene
 * line (lac_scene_error); errors of the modules keep their message, with
 * the scene line prepended where one is responsible.
 *
 * Exact solutions known to the code (the [exact] section):
 *   thick_sphere    hollow sphere a <= R <= b under inner pressure p, outer
 *                   surface free (Lame; Timoshenko & Goodier, Theory of
 *                   Elasticity, 3rd ed., §137):
 *                     u_R = p a^3 / (E (b^3 - a^3))
 *                           ((1 - 2 nu) R + (1 + nu) b^3 / (2 R^2))
 *   thick_cylinder  hollow cylinder a <= r <= b in plane strain (ibid.,
 *                   §28):
 *                     u_r = (1 + nu) p a^2 / (E (b^2 - a^2))
 *                           ((1 - 2 nu) r + b^2 / r)
 * Both are u = g(R) x with g = C1 + C2 / R^k (k = 3, 2), so their
 * gradient is g I + g'(R) x x^T / R.
 */
#include "lac_run.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <gsl/gsl_eigen.h>
#include "lac_mem.h"
#include "lac_output.h"
#include "lac_post.h"
#include "lac_status.h"

static const char *const stage_names[LAC_NSTAGES] =
  { "mesh", "material", "assemble", "solve", "post", "output" };

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

typedef struct exact_ctx
{
  int dim;        /* components of u                                     */
  int nr;         /* coordinates in the radius: 3 sphere in 3D, else 2   */
  int k;          /* g = C1 + C2 / R^k                                   */
  double C1, C2;
} exact_ctx;

static double
radius (const exact_ctx *e, const double *x)
{
  double R2 = 0;
  for (int i = 0; i < e->nr; i++)
    R2 += x[i] * x[i];
  return sqrt (R2);
}

static void
exact_u (const double *x, void *ctx, double *out)
{
  const exact_ctx *e = ctx;
  double R = radius (e, x), g = e->C1 + e->C2 / pow (R, e->k);
  for (int i = 0; i < e->dim; i++)
    out[i] = i < e->nr ? g * x[i] : 0.0;              /* u = g(R) x */
}

static void
exact_grad (const double *x, void *ctx, double *out)
{
  const exact_ctx *e = ctx;
  double R = radius (e, x), g = e->C1 + e->C2 / pow (R, e->k);
  double gp = -e->k * e->C2 / pow (R, e->k + 1);      /* g'(R) */
  for (int i = 0; i < e->dim; i++)
    for (int j = 0; j < e->dim; j++)
      out[i * e->dim + j] = (i < e->nr && j < e->nr)
        ? (i == j ? g : 0.0) + gp * x[i] * x[j] / R : 0.0;
}

static void
exact_setup (const lac_run *r, exact_ctx *e)
{
  const lac_scene_exact *x = &r->scene->exact;
  double a = x->a, b = x->b, p = x->p, E = x->E, nu = x->nu;
  e->dim = r->dim;
  if (x->solution == LAC_EXACT_THICK_SPHERE)
    {
      double c = p * a * a * a / (E * (b * b * b - a * a * a));
      e->nr = r->dim;
      e->k = 3;
      e->C1 = c * (1 - 2 * nu);
      e->C2 = c * (1 + nu) * b * b * b / 2;
    }
  else
    {
      double c = (1 + nu) * p * a * a / (E * (b * b - a * a));
      e->nr = 2;
      e->k = 2;
      e->C1 = c * (1 - 2 * nu);
      e->C2 = c * b * b;
    }
}

/* ---- helpers ---------------------------------------------------------- */

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

static int
summary_add (lac_run *r, const char *key, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));

static int
summary_add (lac_run *r, const char *key, const char *fmt, ...)
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
      int want = l->kind == LAC_LOAD_FORCE ? d : d - 1;
      if (l->group && !find_group (r, &l->sec, l->group, want,
                                   l->kind == LAC_LOAD_FORCE ? "a volume "
                                   "force" : "a surface load"))
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

static int
stage_material (lac_run *r)
{
  const lac_scene *sc = r->scene;
  const lac_mesh *m = r->mesh;
  const lac_scene_material *dflt = NULL;
  int *owner;
  r->E = lac_malloc (m->ncells * sizeof *r->E);
  r->nu = lac_malloc (m->ncells * sizeof *r->nu);
  owner = lac_malloc (m->ncells * sizeof *owner);
  if (!r->E || !r->nu || !owner)
    {
      lac_free (owner);
      LAC_ERROR (LAC_ENOMEM, "material arrays for %zu cells", m->ncells);
    }
  for (size_t c = 0; c < m->ncells; c++)
    owner[c] = -1;
  for (size_t k = 0; k < sc->nmaterial; k++)
    {
      const lac_scene_material *mt = &sc->material[k];
      const lac_group *g;
      if (!mt->group)
        {
          dflt = mt;
          continue;
        }
      g = lac_mesh_group (m, mt->group);
      for (size_t j = 0; j < g->n; j++)
        {
          size_t c = g->cell[j];
          if (owner[c] >= 0)
            {
              lac_free (owner);
              return lac_scene_error (sc, &mt->sec, "group", LAC_EINVAL,
                                      "cell %zu is also in [material %s]",
                                      m->cell_tag[c],
                                      sc->material[owner[c]].sec.name);
            }
          owner[c] = (int) k;
          r->E[c] = mt->E;
          r->nu[c] = mt->nu;
        }
    }
  for (size_t c = 0; c < m->ncells; c++)
    if (owner[c] < 0 && dflt)
      {
        owner[c] = (int) (dflt - sc->material);
        r->E[c] = dflt->E;
        r->nu[c] = dflt->nu;
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
  snprintf (r->progress, sizeof r->progress, "%zu material%s, %s",
            sc->nmaterial, sc->nmaterial > 1 ? "s" : "",
            "linear elastic");
  return LAC_SUCCESS;
}

/* ---- stage 3: assemble ------------------------------------------------ */

/* Rigid motions of the model at component i of a node at x (relative to
 * the body's centre, divided by its size):  plane strain t_x, t_y, r_z;
 * axisymmetric t_z (the only one: u_r = const strains the hoops); 3D t_x,
 * t_y, t_z, r_x, r_y, r_z with r_w = w x x. */
static int
rigid_modes (lac_model model, int i, const double *x, double *v)
{
  if (model == LAC_AXISYMMETRIC)
    return v[0] = (i == 1), 1;
  if (model == LAC_PLANE_STRAIN)
    {
      v[0] = (i == 0), v[1] = (i == 1);
      v[2] = i == 0 ? -x[1] : x[0];                   /* e_z x x */
      return 3;
    }
  for (int k = 0; k < 3; k++)
    v[k] = (i == k);
  v[3] = i == 0 ? 0 : i == 1 ? -x[2] : x[1];          /* e_x x x */
  v[4] = i == 0 ? x[2] : i == 1 ? 0 : -x[0];          /* e_y x x */
  v[5] = i == 0 ? -x[1] : i == 1 ? x[0] : 0;          /* e_z x x */
  return 6;
}

static const char *
mode_name (lac_model model, int k)
{
  static const char *const n2[] = { "translation along x",
    "translation along y", "rotation about z" };
  static const char *const n3[] = { "translation along x",
    "translation along y", "translation along z", "rotation about x",
    "rotation about y", "rotation about z" };
  if (model == LAC_AXISYMMETRIC)
    return "translation along z (the axis)";
  return model == LAC_PLANE_STRAIN ? n2[k] : n3[k];
}

static size_t
uf_find (size_t *p, size_t a)
{
  while (p[a] != a)
    a = p[a] = p[p[a]];
  return a;
}

/* Describe the rigid motion with mode coefficients v (relative to the
 * body's centre ctr and size L): in 2D a translation or the rotation about
 * its fixed point, in 3D the modes that take part. */
static int
describe_mode (lac_model model, int nm, const double *v, const double *ctr,
               double L, char *buf, size_t size)
{
  if (model == LAC_PLANE_STRAIN && fabs (v[2]) > 1e-6)
    /* u = (v0 - v2 y, v1 + v2 x) vanishes at x = -v1/v2, y = v0/v2 */
    {
      double x = ctr[0] - L * v[1] / v[2], y = ctr[1] + L * v[0] / v[2];
      return snprintf (buf, size, "rotation about (%.3g, %.3g)",
                       fabs (x) < 1e-9 * L ? 0.0 : x,     /* no -2e-16 */
                       fabs (y) < 1e-9 * L ? 0.0 : y);
    }
  if (model == LAC_PLANE_STRAIN && fabs (v[0]) > 1e-6 && fabs (v[1]) > 1e-6)
    return snprintf (buf, size, "translation along (%.3g, %.3g)", v[0], v[1]);
  {
    int len = 0;
    buf[0] = '\0';
    for (int j = 0; j < nm; j++)
      if (fabs (v[j]) > 0.1 && len >= 0 && (size_t) len < size)
        len += snprintf (buf + len, size - (size_t) len, "%s%s",
                         len ? " + " : "", mode_name (model, j));
    return len;
  }
}

/* The free rigid motions of a body from the Gram matrix G of the modes
 * restricted to its fixed dofs: eigenvalues <= 1e-10 * max are free.
 * Describes them in buf; returns their number (-1: GSL failed). */
static int
free_modes (lac_model model, int nm, double *G, const double *ctr, double L,
            char *buf, size_t size)
{
  gsl_matrix_view A = gsl_matrix_view_array (G, (size_t) nm, (size_t) nm);
  gsl_vector *ev = gsl_vector_alloc ((size_t) nm);
  gsl_matrix *V = gsl_matrix_alloc ((size_t) nm, (size_t) nm);
  gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc ((size_t) nm);
  int nfree = 0;
  size_t len = 0;
  double lmax;
  buf[0] = '\0';
  if (!ev || !V || !w || gsl_eigen_symmv (&A.matrix, ev, V, w))
    nfree = -1;
  lmax = nfree ? 0 : gsl_vector_max (ev);
  for (int k = 0; nfree >= 0 && k < nm; k++)
    {
      double v[6];
      if (lmax > 0 && gsl_vector_get (ev, (size_t) k) > 1e-10 * lmax)
        continue;
      for (int j = 0; j < nm; j++)
        v[j] = gsl_matrix_get (V, (size_t) j, (size_t) k);
      if (len + 8 < size)
        len += (size_t) snprintf (buf + len, size - len, nfree ? "; "
                                  : "free: ");
      if (len < size)
        len += (size_t) describe_mode (model, nm, v, ctr, L, buf + len,
                                       size - len);
      nfree++;
    }
  if (nfree > 0 && lmax == 0)
    snprintf (buf, size, "no Dirichlet condition acts on it");
  gsl_eigen_symmv_free (w);
  gsl_matrix_free (V);
  gsl_vector_free (ev);
  return nfree;
}

/* Bodies: the connected components of the mesh (nodes joined through
 * cells, union-find in p).  comp[a] = body of node a (SIZE_MAX: in no
 * cell), cell0[b] = a cell of body b; returns the number of bodies. */
static size_t
find_bodies (const lac_mesh *m, size_t *p, size_t *comp, size_t *cell0)
{
  size_t nb = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    p[a] = a, comp[a] = SIZE_MAX;
  for (size_t c = 0; c < m->ncells; c++)
    for (size_t k = m->ptr[c] + 1; k < m->ptr[c + 1]; k++)
      p[uf_find (p, (size_t) m->conn[k])] = uf_find (p, (size_t)
                                                     m->conn[m->ptr[c]]);
  for (size_t c = 0; c < m->ncells; c++)
    {
      size_t root = uf_find (p, (size_t) m->conn[m->ptr[c]]);
      if (comp[root] == SIZE_MAX)
        cell0[nb] = c, comp[root] = nb++;
    }
  for (size_t a = 0; a < m->nnodes; a++)
    comp[a] = comp[uf_find (p, a)];
  return nb;
}

/* Centre ctr[4b .. 4b+2] and size ctr[4b+3] (largest distance of a node
 * to the centre along an axis, 1 if zero) of each body; ctr zeroed. */
static void
body_frames (const lac_mesh *m, const size_t *comp, size_t nb, double *ctr)
{
  int dim = m->dim;
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; comp[a] != SIZE_MAX && i <= dim; i++)
      ctr[4 * comp[a] + (size_t) (i < dim ? i : 3)]
        += i < dim ? m->x[a * (size_t) dim + (size_t) i] : 1.0;
  for (size_t b = 0; b < nb; b++)
    {
      for (int i = 0; i < 3; i++)
        ctr[4 * b + (size_t) i] /= ctr[4 * b + 3];     /* mean of x */
      ctr[4 * b + 3] = 0;
    }
  for (size_t a = 0; a < m->nnodes; a++)
    for (int i = 0; comp[a] != SIZE_MAX && i < dim; i++)
      ctr[4 * comp[a] + 3] = fmax (ctr[4 * comp[a] + 3],
                                   fabs (m->x[a * (size_t) dim + (size_t) i]
                                         - ctr[4 * comp[a] + (size_t) i]));
  for (size_t b = 0; b < nb; b++)
    if (!(ctr[4 * b + 3] > 0))
      ctr[4 * b + 3] = 1;
}

/* G_b += v v^T over the fixed dofs q of body b, v = the rigid modes at q
 * (36 entries per body, nm x nm used). */
static void
mode_gram (const lac_run *r, const char *fixed, const size_t *comp,
           const double *ctr, int nm, double *G)
{
  const lac_mesh *m = r->mesh;
  int dim = m->dim;
  for (size_t q = 0; q < r->ndof; q++)
    {
      size_t a = q / (size_t) dim, b = comp[a];
      double x[3] = { 0, 0, 0 }, v[6];
      if (!fixed[q] || b == SIZE_MAX)
        continue;
      for (int i = 0; i < dim; i++)
        x[i] = (m->x[a * (size_t) dim + (size_t) i] - ctr[4 * b + (size_t) i])
               / ctr[4 * b + 3];
      rigid_modes (r->model, (int) (q % (size_t) dim), x, v);
      for (int i = 0; i < nm; i++)
        for (int j = 0; j < nm; j++)
          G[36 * b + (size_t) (i * nm + j)] += v[i] * v[j];
    }
}

/* Every connected body must be fixed against rigid motions by the fixed
 * dofs; otherwise K is singular.  Checking it here names the body and the
 * free motion, which a solver's pivot message cannot:  the rigid modes
 * restricted to the fixed dofs of a body must be linearly independent,
 * i.e. their Gram matrix G_b must be non-singular. */
static int
check_rigid (lac_run *r, const lac_dirichlet *d)
{
  const lac_mesh *m = r->mesh;
  int nm = r->model == LAC_PLANE_STRAIN ? 3
           : r->model == LAC_AXISYMMETRIC ? 1 : 6;
  size_t n = m->nnodes, nb, *p = lac_malloc (n * sizeof *p);
  size_t *comp = lac_malloc (n * sizeof *comp);
  size_t *cell0 = lac_malloc (n * sizeof *cell0);
  double *ctr = NULL, *G = NULL;
  char *fixed = lac_calloc (r->ndof, 1), desc[400];
  int status = LAC_SUCCESS;
  if (!p || !comp || !cell0 || !fixed)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "rigid-motion check");
      goto done;
    }
  nb = find_bodies (m, p, comp, cell0);
  ctr = lac_calloc (4 * nb, sizeof *ctr);
  G = lac_calloc (36 * nb, sizeof *G);
  if (!ctr || !G)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "rigid-motion check");
      goto done;
    }
  body_frames (m, comp, nb, ctr);
  for (size_t k = 0; k < d->n; k++)
    fixed[d->dof[k]] = 1;
  mode_gram (r, fixed, comp, ctr, nm, G);
  for (size_t b = 0; b < nb && !status; b++)
    {
      int nfree = free_modes (r->model, nm, G + 36 * b, ctr + 4 * b,
                              ctr[4 * b + 3], desc, sizeof desc);
      size_t c = cell0[b];
      if (nfree < 0)
        status = LAC_ERRMSG (LAC_ENOMEM, "rigid-motion check (GSL)");
      else if (nfree > 0 && m->body[c] >= 0)
        status = lac_error_set (LAC_ESING, r->scene->path, "stiffness is "
                                "singular: body '%s' is not fixed against "
                                "rigid motion (%s); add [dirichlet] "
                                "conditions that prevent it",
                                m->group[m->body[c]].name, desc);
      else if (nfree > 0)
        status = lac_error_set (LAC_ESING, r->scene->path, "stiffness is "
                                "singular: the cells around cell %zu are not "
                                "fixed against rigid motion (%s); add "
                                "[dirichlet] conditions that prevent it",
                                m->cell_tag[c], desc);
    }
done:
  lac_free (G);
  lac_free (fixed);
  lac_free (ctr);
  lac_free (cell0);
  lac_free (comp);
  lac_free (p);
  return status;
}

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
      if (l->kind == LAC_LOAD_PRESSURE)
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
  exact_ctx e;
  exact_setup (r, &e);
  for (size_t k = 0; k < sc->ndirichlet && !status; k++)
    {
      const lac_scene_dirichlet *bc = &sc->dirichlet[k];
      const lac_group *g = lac_mesh_group (r->mesh, bc->group);
      if (bc->kind == LAC_BC_EXACT)
        status = lac_dirichlet_add_field (d, r->mesh, g, exact_u, &e);
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
      || (status = check_rigid (r, d)))
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

/* ---- stage 5: post ---------------------------------------------------- */

/* Distinct cell types of the mesh, "tri6" or "tri6+quad8". */
static void
cell_types (const lac_mesh *m, char *buf, size_t size)
{
  int seen[LAC_NELEM_TYPES] = { 0 };
  size_t len = 0;
  buf[0] = '\0';
  for (size_t c = 0; c < m->ncells; c++)
    seen[m->type[c]] = 1;
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    if (seen[t] && len < size)
      len += (size_t) snprintf (buf + len, size - len, "%s%s", len ? "+" : "",
                                lac_refelem_get ((lac_elem_type) t)->name);
}

/* Mean radial displacement u.x/R (and its exact value) over the nodes at
 * radius R0; returns the number of such nodes. */
static size_t
radial_mean (const lac_run *r, const exact_ctx *e, double R0, double *uh,
             double *ue)
{
  const lac_mesh *m = r->mesh;
  size_t n = 0;
  *uh = *ue = 0;
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *x = m->x + a * (size_t) r->dim;
      double R = radius (e, x);
      if (fabs (R - R0) > 1e-8 * R0)
        continue;
      for (int i = 0; i < e->nr; i++)
        {
          *uh += r->u[a * (size_t) r->dim + (size_t) i] * x[i] / R;
          *ue += r->u_exact[a * (size_t) r->dim + (size_t) i] * x[i] / R;
        }
      n++;
    }
  if (n)
    *uh /= (double) n, *ue /= (double) n;
  return n;
}

static int
summary_exact (lac_run *r, const exact_ctx *e)
{
  const lac_scene_exact *x = &r->scene->exact;
  const char *side[2] = { "inner", "outer" };
  const double R0[2] = { x->a, x->b };
  int status = summary_add (r, "exact", "%s",
                            lac_scene_exact_name (x->solution));
  if (!status)
    status = summary_add (r, "err_l2", "%.10e", r->err_l2);
  if (!status)
    status = summary_add (r, "err_h1", "%.10e", r->err_h1);
  if (!status)
    status = summary_add (r, "rel_err_l2", "%.10e", r->norm_l2 > 0
                          ? r->err_l2 / r->norm_l2 : 0.0);
  if (!status)
    status = summary_add (r, "rel_err_h1", "%.10e", r->norm_h1 > 0
                          ? r->err_h1 / r->norm_h1 : 0.0);
  for (int k = 0; k < 2 && !status; k++)
    {
      double uh, ue;
      char key[64];
      if (!radial_mean (r, e, R0[k], &uh, &ue))
        continue;
      snprintf (key, sizeof key, "u_r_%s", side[k]);
      status = summary_add (r, key, "%.10e", uh);
      snprintf (key, sizeof key, "u_r_%s_exact", side[k]);
      if (!status)
        status = summary_add (r, key, "%.10e", ue);
      snprintf (key, sizeof key, "rel_err_u_r_%s", side[k]);
      if (!status)
        status = summary_add (r, key, "%.10e", ue != 0 ? fabs (uh - ue)
                              / fabs (ue) : fabs (uh));
    }
  return status;
}

static int
make_summary (lac_run *r, const exact_ctx *e)
{
  const lac_mesh *m = r->mesh;
  double work = 0, umax = 0, vmax = 0;
  char types[128], effects[256] = "";
  int status;
  for (size_t k = 0; k < r->ndof; k++)
    work += r->F[k] * r->u[k];                   /* l(u_h) = F . u */
  for (size_t a = 0; a < m->nnodes; a++)
    {
      double s = 0;
      for (int i = 0; i < r->dim; i++)
        s += r->u[a * (size_t) r->dim + (size_t) i]
             * r->u[a * (size_t) r->dim + (size_t) i];
      umax = fmax (umax, sqrt (s));
      vmax = fmax (vmax, r->vm[a]);
    }
  cell_types (m, types, sizeof types);
  for (size_t k = 0; k < r->neffects; k++)
    snprintf (effects + strlen (effects), sizeof effects - strlen (effects),
              "%s%s", k ? ", " : "", r->effects[k]);
  if ((status = summary_add (r, "title", "%s", r->scene->scene.title))
      || (status = summary_add (r, "model", "%s", lac_model_name (r->model)))
      || (status = summary_add (r, "element", "%s", types))
      || (status = summary_add (r, "effects", "%s", effects))
      || (status = summary_add (r, "nodes", "%zu", m->nnodes))
      || (status = summary_add (r, "cells", "%zu", m->ncells))
      || (status = summary_add (r, "dofs", "%zu", r->ndof))
      || (status = summary_add (r, "fixed_dofs", "%zu", r->nfixed))
      || (status = summary_add (r, "nnz_K", "%zu", r->nnz))
      || (status = summary_add (r, "load_work", "%.10e", work))
      || (status = summary_add (r, "max_u", "%.10e", umax))
      || (status = summary_add (r, "max_von_mises", "%.10e", vmax)))
    return status;
  return r->u_exact ? summary_exact (r, e) : LAC_SUCCESS;
}

static int
stage_post (lac_run *r)
{
  const lac_mesh *m = r->mesh;
  exact_ctx e;
  int status;
  r->sigma = lac_malloc (m->nnodes * (size_t) r->ns * sizeof *r->sigma);
  r->vm = lac_malloc (m->nnodes * sizeof *r->vm);
  if (!r->sigma || !r->vm)
    LAC_ERROR (LAC_ENOMEM, "nodal stresses of %zu nodes", m->nnodes);
  status = lac_post_stress_nodal (m, &r->mat, r->u, NULL, r->sigma, r->vm);
  if (status)
    return status;
  exact_setup (r, &e);
  if (r->scene->exact.sec.line != 0)
    {
      if (!(r->u_exact = lac_malloc (r->ndof * sizeof *r->u_exact)))
        LAC_ERROR (LAC_ENOMEM, "exact displacement");
      for (size_t a = 0; a < m->nnodes; a++)
        exact_u (m->x + a * (size_t) r->dim, &e,
                 r->u_exact + a * (size_t) r->dim);
      status = lac_post_errors (m, r->model, r->u, exact_u, exact_grad, &e,
                                &r->err_l2, &r->err_h1, &r->norm_l2,
                                &r->norm_h1);
      if (status)
        return status;
    }
  if ((status = make_summary (r, &e)))
    return status;
  if (r->u_exact)
    snprintf (r->progress, sizeof r->progress, "stresses, errors vs %s: "
              "L2 %.3e, H1 %.3e", lac_scene_exact_name
              (r->scene->exact.solution), r->err_l2, r->err_h1);
  else
    snprintf (r->progress, sizeof r->progress, "stresses, von Mises");
  return LAC_SUCCESS;
}

/* ---- stage 6: output -------------------------------------------------- */

static int
stage_output (lac_run *r)
{
  const lac_scene_output *o = &r->scene->output;
  lac_output_fields f = { r->mesh, r->model, r->u, r->u_exact, r->sigma,
                          r->vm };
  lac_output_batch *b;
  const char *path;
  int status = LAC_SUCCESS;
  if (r->opts.timings)
    for (int s = 0; s < LAC_STAGE_OUTPUT && !status; s++)
      {
        char key[32];
        snprintf (key, sizeof key, "time_%s", stage_names[s]);
        status = summary_add (r, key, "%.3f", r->time[s]);
      }
  if (status || r->opts.no_output)
    {
      snprintf (r->progress, sizeof r->progress, "no files written");
      return status;
    }
  if (!(b = lac_output_batch_alloc (r->out_dir)))
    return LAC_EIO;
  if (o->vtu && (!(path = lac_output_batch_add (b, "solution.vtu"))
                 || (status = lac_output_vtu (path, &f))))
    goto done;
  if (o->csv && (!(path = lac_output_batch_add (b, "nodes.csv"))
                 || (status = lac_output_csv (path, &f))))
    goto done;
  if (o->matrix && (!(path = lac_output_batch_add (b, "K.mtx"))
                    || (status = lac_csc_write_mm (r->K0, path))))
    goto done;
  if (!(path = lac_output_batch_add (b, "summary.txt"))
      || (status = lac_output_summary (path, r->nsummary,
                                       (const char *const *) r->key,
                                       (const char *const *) r->val)))
    goto done;
  status = lac_output_commit (b);
  snprintf (r->progress, sizeof r->progress, "%s/: %s%s%ssummary.txt",
            r->out_dir, o->vtu ? "solution.vtu, " : "",
            o->csv ? "nodes.csv, " : "", o->matrix ? "K.mtx, " : "");
done:
  if (!status && !path)
    status = LAC_ENOMEM;
  lac_output_batch_free (b);
  return status;
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
  lac_free (r->vm);
  lac_free (r->sigma);
  lac_free (r->u);
  lac_free (r->b);
  lac_free (r->F);
  lac_csc_free (r->K0);
  lac_csc_free (r->K);
  lac_free (r->nu);
  lac_free (r->E);
  lac_mesh_free (r->mesh);
  lac_free (r->out_dir);
  lac_free (r);
}

int
lac_run_iterate (lac_run *r)
{
  static int (*const stage[LAC_NSTAGES]) (lac_run *) = {
    stage_mesh, stage_material, stage_assemble, stage_solve, stage_post,
    stage_output };
  double t0 = now ();
  int status;
  if (r->stage >= LAC_NSTAGES)
    return LAC_SUCCESS;
  r->progress[0] = '\0';
  status = stage[r->stage] (r);
  r->time[r->stage] = now () - t0;
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
