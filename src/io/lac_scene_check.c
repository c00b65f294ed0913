/* lac_scene_check.c -- step 4 of reading a scene (see lac_scene.h)
 *
 * After the typed values are stored (lac_scene_ini.c): defaults that
 * depend on other keys (title, order and recombine from the element),
 * required keys, conflicting keys, keys that depend on the model
 * (displacement components, symmetry axes, vector sizes, the exact
 * solution), that the mesh file exists, and the keys of the
 * large-deformation run.  The first error stops with a one-line message
 * naming the scene line.
 */
#include "io/lac_scene_check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>
#include "fem/lac_exact.h"
#include "io/lac_mesh_opts.h"
#include "io/lac_output_batch.h"
#include "io/lac_scene_keys.h"
#include "io/lac_scene_query.h"
#include "solve/lac_newton_rules.h"
#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

static int
given (const lac_scene_section *s, const char *key)
{
  return lac_scene_key_line (s, key) != 0;
}

static int
require (const lac_scene *sc, const lac_scene_section *s, const char *key,
         const char *what)
{
  if (given (s, key))
    return LAC_SUCCESS;
  return lac_scene_error (sc, s, NULL, LAC_EINVAL, "missing key '%s' (%s)",
                          key, what);
}

static int
finish_scene (lac_scene *sc)
{
  const lac_scene_element_spec *info = lac_scene_elements;
  lac_scene_main *m = &sc->scene;
  int dim = lac_model_dim ((lac_model) m->model);
  if (!m->title && !(m->title = lac_strdup (sc->basename)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  if (m->element != LAC_ELEM_NONE && info[m->element].dim != dim)
    return lac_scene_error (sc, &m->sec, "element", LAC_EINVAL,
                            "a %dD element; model = %s needs %s",
                            info[m->element].dim,
                            lac_scene_model_names[m->model], dim == 2
                            ? "tri3, tri6, quad4, quad8 or quad9"
                            : "tet4, tet10, hex8, hex20 or hex27");
  /* Store the element as an lac_elem_type from here on. */
  if (m->element != LAC_ELEM_NONE)
    m->element = info[m->element].type;
  return LAC_SUCCESS;
}


/* One name of [mesh] file: its path, relative to the scene's directory,
 * checked to be a regular file that opens (a named pipe would block the
 * run, a device feed it without end: base/lac_input.h; its size is
 * checked against --max-memory when it is read). */
static int
mesh_path (lac_scene *sc, lac_scene_mesh *m, const char *name, char **path)
{
  size_t len = strlen (sc->dir) + strlen (name) + 2;
  int status;
  if (!(*path = lac_malloc (len)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  if (name[0] == '/')
    snprintf (*path, len, "%s", name);
  else
    snprintf (*path, len, "%s/%s", sc->dir, name);
  if ((status = lac_input_check (*path, HUGE_VAL, "", NULL)))
    return lac_scene_error (sc, &m->sec, "file", status, "%s",
                            lac_error_message ());
  return LAC_SUCCESS;
}

/* [mesh] file: one name, or several separated by blanks (one mesh per
 * body, read one after the other and put side by side). */
static int
mesh_files (lac_scene *sc, lac_scene_mesh *m)
{
  const char *p = m->file;
  int status = LAC_SUCCESS;
  for (int k = 0; k < m->nfiles; k++)
    lac_free (m->files[k]), lac_free (m->paths[k]);
  m->nfiles = 0;
  lac_free (m->path);
  m->path = NULL;
  while (!status && *(p += strspn (p, " \t")))
    {
      size_t n = strcspn (p, " \t");
      if (m->nfiles == LAC_SCENE_MAX_MESHES)
        return lac_scene_error (sc, &m->sec, "file", LAC_EINVAL, "more than "
                                "%d mesh files", LAC_SCENE_MAX_MESHES);
      if (!(m->files[m->nfiles] = lac_malloc (n + 1)))
        LAC_ERROR (LAC_ENOMEM, "out of memory");
      memcpy (m->files[m->nfiles], p, n);
      m->files[m->nfiles][n] = '\0';
      status = mesh_path (sc, m, m->files[m->nfiles], &m->paths[m->nfiles]);
      m->nfiles++;
      p += n;
    }
  if (!status && m->nfiles == 0)
    return lac_scene_error (sc, &m->sec, "file", LAC_EINVAL, "no file name");
  if (!status && !(m->path = lac_strdup (m->paths[0])))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  return status;
}

static int
finish_mesh (lac_scene *sc)
{
  const lac_scene_element_spec *info = lac_scene_elements;
  const char *const *names = lac_scene_element_names;
  lac_scene_mesh *m = &sc->mesh;
  lac_mesh_number num[LAC_MESH_MAX_NUMBERS];
  char why[400];
  int el = -1, status;
  if (m->sec.line == 0)
    return lac_scene_where_error (sc->path, 0, LAC_EINVAL, "no [mesh] "
                                  "section (a scene needs [mesh] file = "
                                  "NAME.geo or NAME.msh)");
  if ((status = require (sc, &m->sec, "file", ".geo or .msh file")))
    return status;
  for (int k = 0; k < LAC_SCENE_NELEMENTS; k++)
    if ((int) info[k].type == sc->scene.element)
      el = k;
  if (el >= 0 && given (&m->sec, "order") && m->order != info[el].order)
    return lac_scene_error (sc, &m->sec, "order", LAC_EINVAL, "contradicts "
                            "[scene] element = %s (order %d)", names[el],
                            info[el].order);
  if (el >= 0 && given (&m->sec, "recombine")
      && m->recombine != info[el].recombine)
    return lac_scene_error (sc, &m->sec, "recombine", LAC_EINVAL,
                            "contradicts [scene] element = %s", names[el]);
  if (el >= 0)
    {
      m->order = info[el].order;
      m->recombine = info[el].recombine;
    }
  if (m->numbers && lac_mesh_numbers_split (m->numbers, num, why,
                                            sizeof why) < 0)
    return lac_scene_error (sc, &m->sec, "numbers", LAC_EINVAL, "%s", why);

  /* The files, relative to the scene's directory. */
  return mesh_files (sc, m);
}

/* nu in (LAC_SCENE_NU_MAX, 0.5): incompressible to rounding. */
static int
check_nu (lac_scene *sc, lac_scene_section *sec, double nu)
{
  if (nu <= LAC_SCENE_NU_MAX)
    return LAC_SUCCESS;
  return lac_scene_error (sc, sec, "nu", LAC_EINVAL, "too close to 0.5: "
                          "lambda / mu = 2 nu / (1 - 2 nu) = %.3g, the "
                          "material is incompressible to rounding and its "
                          "stiffness singular in double precision; lac "
                          "takes nu <= %.9g (lambda / mu <= 1e8)",
                          2 * nu / (1 - 2 * nu), LAC_SCENE_NU_MAX);
}

/* Sections in the order of their group, then of their position. */
typedef struct by_group
{
  const char *group;
  size_t k;
} by_group;

static int
group_order (const void *a, const void *b)
{
  const by_group *x = a, *y = b;
  int c = strcmp (x->group, y->group);
  return c ? c : (x->k > y->k) - (x->k < y->k);
}

/* No group in two [material] sections: the sections sorted by group (a
 * pairwise comparison was quadratic in the number of sections). */
static int
materials_distinct (lac_scene *sc)
{
  by_group *g = lac_malloc ((sc->nmaterial + 1) * sizeof *g);
  size_t n = 0;
  int status = LAC_SUCCESS;
  if (!g)
    LAC_ERROR (LAC_ENOMEM, "%zu materials", sc->nmaterial);
  for (size_t k = 0; k < sc->nmaterial; k++)
    if (sc->material[k].group)
      g[n++] = (by_group) { sc->material[k].group, k };
  qsort (g, n, sizeof *g, group_order);
  for (size_t i = 1; i < n && !status; i++)
    if (strcmp (g[i - 1].group, g[i].group) == 0)
      status = lac_scene_error (sc, &sc->material[g[i].k].sec, "group",
                                LAC_EINVAL, "group already used by "
                                "[material %s]",
                                sc->material[g[i - 1].k].sec.name);
  lac_free (g);
  return status;
}

static int
finish_materials (lac_scene *sc)
{
  int status;
  const lac_scene_material *nogroup = NULL;
  if (sc->nmaterial == 0)
    return lac_scene_where_error (sc->path, 0, LAC_EINVAL, "no [material "
                                  "NAME] section (one per body: group, E, "
                                  "nu)");
  for (size_t k = 0; k < sc->nmaterial; k++)
    {
      const lac_scene_material *m = &sc->material[k];
      if ((status = require (sc, &m->sec, "E", "Young's modulus > 0"))
          || (status = require (sc, &m->sec, "nu", "Poisson's ratio in "
                                "(-1, 0.5)"))
          || (status = check_nu (sc, &sc->material[k].sec, m->nu)))
        return status;
      if (!m->group && nogroup)
        return lac_scene_error (sc, &m->sec, NULL, LAC_EINVAL, "no group, "
                                "like [material %s]: give each a group",
                                nogroup->sec.name);
      if (!m->group)
        nogroup = m;
    }
  return materials_distinct (sc);
}

/* The components ux, uy, uz, ur given: fixed[] and value[], their number
 * in *ncomp. */
static int
dirichlet_components (lac_scene *sc, lac_scene_dirichlet *d, int *ncomp)
{
  static const char *const comp[] = { "ux", "uy", "uz", "ur" };
  const double *val[] = { &d->ux, &d->uy, &d->uz, &d->ur };
  lac_model model = (lac_model) sc->scene.model;
  int c;
  *ncomp = 0;
  for (int k = 0; k < 4; k++)
    if (given (&d->sec, comp[k]))
      {
        if ((c = lac_scene_component (model, comp[k])) < 0)
          return lac_scene_error (sc, &d->sec, comp[k], LAC_EINVAL,
                                  "not a component of model = %s (use %s)",
                                  lac_scene_model_names[model],
                                  model == LAC_AXISYMMETRIC ? "ur, uz"
                                  : model == LAC_SOLID3D ? "ux, uy, uz"
                                  : "ux, uy");
        d->fixed[c] = 1;
        d->value[c] = *val[k];
        (*ncomp)++;
      }
  return LAC_SUCCESS;
}

/* normal = g: u.n = g along the outward normal of a facet group (a
 * roller for g = 0; run/lac_run_roller.h). */
static int
dirichlet_normal (lac_scene *sc, lac_scene_dirichlet *d)
{
  if (!given (&d->sec, "normal"))
    return LAC_SUCCESS;
  if (d->kind != LAC_BC_COMPONENTS)
    return lac_scene_error (sc, &d->sec, "normal", LAC_EINVAL, "give only "
                            "one of clamp, symmetry, exact, normal");
  d->kind = LAC_BC_NORMAL;
  return LAC_SUCCESS;
}

/* d->kind from clamp, symmetry (with its component), exact and normal. */
static int
dirichlet_kind (lac_scene *sc, lac_scene_dirichlet *d)
{
  lac_model model = (lac_model) sc->scene.model;
  int c;
  d->kind = LAC_BC_COMPONENTS;
  if (given (&d->sec, "clamp") && d->clamp)
    d->kind = LAC_BC_CLAMP;
  if (given (&d->sec, "symmetry"))
    {
      static const int axis[3][4] = {   /* x y z r -> component or -1 */
        { 0, 1, -1, -1 }, { -1, -1, 1, 0 }, { 0, 1, 2, -1 } };
      if ((c = axis[model][d->symmetry]) < 0)
        return lac_scene_error (sc, &d->sec, "symmetry", LAC_EINVAL,
                                "not an axis of model = %s (use %s)",
                                lac_scene_model_names[model],
                                model == LAC_AXISYMMETRIC ? "r or z"
                                : model == LAC_SOLID3D ? "x, y or z"
                                : "x or y");
      if (d->kind != LAC_BC_COMPONENTS)
        return lac_scene_error (sc, &d->sec, "symmetry", LAC_EINVAL,
                                "give only one of clamp, symmetry, exact, "
                                "normal");
      d->kind = LAC_BC_SYMMETRY;
      d->fixed[c] = 1;
      d->value[c] = 0;
    }
  if (given (&d->sec, "exact") && d->exact)
    {
      if (d->kind != LAC_BC_COMPONENTS)
        return lac_scene_error (sc, &d->sec, "exact", LAC_EINVAL,
                                "give only one of clamp, symmetry, exact, "
                                "normal");
      if (sc->exact.sec.line == 0)
        return lac_scene_error (sc, &d->sec, "exact", LAC_EINVAL,
                                "needs an [exact] section");
      d->kind = LAC_BC_EXACT;
    }
  return dirichlet_normal (sc, d);
}

static int
finish_dirichlet (lac_scene *sc, lac_scene_dirichlet *d)
{
  int dim = lac_model_dim ((lac_model) sc->scene.model), ncomp, status;
  if ((status = require (sc, &d->sec, "group", "physical group"))
      || (status = dirichlet_components (sc, d, &ncomp))
      || (status = dirichlet_kind (sc, d)))
    return status;
  if (d->kind != LAC_BC_COMPONENTS && d->kind != LAC_BC_SYMMETRY
      && d->kind != LAC_BC_NORMAL && ncomp)
    return lac_scene_error (sc, &d->sec, NULL, LAC_EINVAL, "give either "
                            "components (ux, ...) or clamp/exact, not both");
  if (d->kind == LAC_BC_SYMMETRY && ncomp)
    return lac_scene_error (sc, &d->sec, "symmetry", LAC_EINVAL,
                            "give either components (ux, ...) or symmetry, "
                            "not both");
  if (d->kind == LAC_BC_NORMAL && ncomp)
    return lac_scene_error (sc, &d->sec, "normal", LAC_EINVAL,
                            "give either components (ux, ...) or normal, "
                            "not both");
  if (d->kind == LAC_BC_CLAMP)
    for (int c = 0; c < 3; c++)
      d->fixed[c] = c < dim, d->value[c] = 0;
  if (d->kind == LAC_BC_COMPONENTS && ncomp == 0)
    return lac_scene_error (sc, &d->sec, NULL, LAC_EINVAL, "nothing to "
                            "impose: give ux/uy/uz (ur/uz), clamp = yes, "
                            "symmetry = AXIS, exact = yes or normal = "
                            "VALUE");
  return LAC_SUCCESS;
}

/* total_force (on a boundary group, or a rigid plate) or point_force (on
 * a point group); the group's dimension is checked with the mesh. */
static int
finish_total (lac_scene *sc, lac_scene_load *l, int dim)
{
  int point = given (&l->sec, "point_force");
  const char *key = point ? "point_force" : "total_force";
  if ((point ? l->npoint_force : l->ntotal_force) != dim)
    return lac_scene_error (sc, &l->sec, key, LAC_EINVAL, "expected %d "
                            "numbers for model = %s", dim,
                            lac_scene_model_names[sc->scene.model]);
  if (l->plate && sc->scene.large_deformation)
    return lac_scene_error (sc, &l->sec, "plate", LAC_EINVAL, "a rigid "
                            "plate needs a linear scene (large_deformation "
                            "= no)");
  l->kind = point ? LAC_LOAD_POINT : LAC_LOAD_TOTAL;
  memcpy (l->vec, point ? l->point_force : l->total_force, sizeof l->vec);
  return require (sc, &l->sec, "group", point ? "point physical group"
                  : "boundary physical group");
}

static int
finish_load (lac_scene *sc, lac_scene_load *l)
{
  int dim = lac_model_dim ((lac_model) sc->scene.model), nkind = 0;
  nkind += given (&l->sec, "pressure");
  nkind += given (&l->sec, "traction");
  nkind += given (&l->sec, "force");
  nkind += given (&l->sec, "exact");
  nkind += given (&l->sec, "total_force");
  nkind += given (&l->sec, "point_force");
  if (nkind != 1)
    return lac_scene_error (sc, &l->sec, NULL, LAC_EINVAL, "give exactly "
                            "one of pressure, traction, force, exact, "
                            "total_force, point_force");
  if (given (&l->sec, "plate") && !given (&l->sec, "total_force"))
    return lac_scene_error (sc, &l->sec, "plate", LAC_EINVAL, "a plate "
                            "carries a total_force: give total_force");
  if (given (&l->sec, "total_force") || given (&l->sec, "point_force"))
    return finish_total (sc, l, dim);
  if (given (&l->sec, "exact"))
    {
      if (sc->exact.sec.line == 0)
        return lac_scene_error (sc, &l->sec, "exact", LAC_EINVAL,
                                "needs an [exact] section");
      if (l->exact == 0)
        return lac_scene_error (sc, &l->sec, "exact", LAC_EINVAL,
                                "expected traction, tangential or force");
      l->kind = l->exact == 1 ? LAC_LOAD_EXACT_TRACTION
                : l->exact == 2 ? LAC_LOAD_EXACT_TANGENTIAL
                : LAC_LOAD_EXACT_FORCE;
      return l->kind == LAC_LOAD_EXACT_FORCE
             ? LAC_SUCCESS
             : require (sc, &l->sec, "group", "boundary physical group");
    }
  if (given (&l->sec, "pressure"))
    l->kind = LAC_LOAD_PRESSURE;
  else if (given (&l->sec, "traction"))
    {
      l->kind = LAC_LOAD_TRACTION;
      if (l->ntraction != dim)
        return lac_scene_error (sc, &l->sec, "traction", LAC_EINVAL,
                                "expected %d numbers for model = %s", dim,
                                lac_scene_model_names[sc->scene.model]);
      memcpy (l->vec, l->traction, sizeof l->vec);
    }
  else
    {
      l->kind = LAC_LOAD_FORCE;
      if (l->nforce != dim)
        return lac_scene_error (sc, &l->sec, "force", LAC_EINVAL,
                                "expected %d numbers for model = %s", dim,
                                lac_scene_model_names[sc->scene.model]);
      memcpy (l->vec, l->force, sizeof l->vec);
    }
  if (l->kind != LAC_LOAD_FORCE)
    return require (sc, &l->sec, "group", "boundary physical group");
  return LAC_SUCCESS;
}

/* "a, b or c" from the names of the exact solutions (which = 0) or of the
 * models in the bit mask `models` (which = 1). */
static void
or_list (char *buf, size_t size, int which, unsigned models)
{
  const char *name[8];
  int n = 0;
  size_t len = 0;
  for (int k = 0; which == 0 && k < lac_exact_count () && n < 8; k++)
    name[n++] = lac_exact_name (k);
  for (int m = 0; which == 1 && m < 3; m++)
    if (models & (1u << m))
      name[n++] = lac_scene_model_names[m];
  buf[0] = '\0';
  for (int k = 0; k < n && len < size; k++)
    len += (size_t) snprintf (buf + len, size - len, "%s%s",
                              k == 0 ? "" : k == n - 1 ? " or " : ", ",
                              name[k]);
}

/* Is `key` one of the blank-separated words of `need`? */
static int
exact_needs (const char *need, const char *key)
{
  size_t n = strlen (key);
  for (const char *p = need; (p = strstr (p, key)); p += n)
    if ((p == need || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
      return 1;
  return 0;
}

static int
finish_exact (lac_scene *sc)
{
  static const char *const keys[] = { "a", "b", "p", "E", "nu" };
  lac_scene_exact *x = &sc->exact;
  lac_model model = (lac_model) sc->scene.model;
  char list[256];
  int status;
  if (x->sec.line == 0)
    return LAC_SUCCESS;
  or_list (list, sizeof list, 0, 0);
  if ((status = require (sc, &x->sec, "solution", list)))
    return status;
  const char *need = lac_exact_table[x->solution].params;
  for (int k = 0; k < 5; k++)
    if (exact_needs (need, keys[k])
        && (status = require (sc, &x->sec, keys[k], "a number")))
      return status;
  if (exact_needs (need, "nu") && (status = check_nu (sc, &x->sec, x->nu)))
    return status;
  if (exact_needs (need, "a") && x->a >= x->b)
    return lac_scene_error (sc, &x->sec, "b", LAC_EINVAL, "expected b > a "
                            "= %g", x->a);
  if (!lac_exact_applies (x->solution, model))
    {
      or_list (list, sizeof list, 1, lac_exact_table[x->solution].models);
      return lac_scene_error (sc, &x->sec, "solution", LAC_EINVAL, "needs "
                              "model = %s", list);
    }
  return LAC_SUCCESS;
}

static int
finish_contact (lac_scene *sc, lac_scene_contact *c)
{
  int status;
  int dim = lac_model_dim ((lac_model) sc->scene.model);
  if ((status = require (sc, &c->sec, "slave", "facet physical group")))
    return status;
  if ((c->master != NULL) == (c->obstacle != 0))
    return lac_scene_error (sc, &c->sec, NULL, LAC_EINVAL, "give exactly "
                            "one of master = GROUP and obstacle = graph");
  if (c->obstacle && c->ncurvature && c->ncurvature != dim - 1)
    return lac_scene_error (sc, &c->sec, "curvature", LAC_EINVAL, "expected "
                            "%d number%s for model = %s", dim - 1,
                            dim == 3 ? "s" : "",
                            lac_scene_model_names[sc->scene.model]);
  if (c->obstacle && c->ncenter && c->ncenter != dim - 1)
    return lac_scene_error (sc, &c->sec, "center", LAC_EINVAL, "expected "
                            "%d number%s for model = %s", dim - 1,
                            dim == 3 ? "s" : "",
                            lac_scene_model_names[sc->scene.model]);
  if (c->method == 2 && sc->ncontact > 1)
    return lac_scene_error (sc, &c->sec, "method", LAC_EINVAL, "nts (for "
                            "comparison) takes a scene of one [contact] "
                            "section; this one has %zu", sc->ncontact);
  for (const lac_scene_contact *b = sc->contact; b < c; b++)
    if (strcmp (b->slave, c->slave) == 0)
      return lac_scene_error (sc, &c->sec, "slave", LAC_EINVAL, "already the "
                              "slave group of [contact %s]: a facet carries "
                              "the multipliers of one pair", b->sec.name);
  if (c->normal == 1 && c->master)
    return lac_scene_error (sc, &c->sec, "normal", LAC_EINVAL, "applies to "
                            "an obstacle only (two bodies meet along the "
                            "slave normal)");
  if (c->method == 2 && !c->master)
    return lac_scene_error (sc, &c->sec, "method", LAC_EINVAL, "nts needs a "
                            "master group (not an obstacle)");
  if (c->master && strcmp (c->slave, c->master) == 0)
    return lac_scene_error (sc, &c->sec, "master", LAC_EINVAL, "the master "
                            "group must differ from the slave group");
  return LAC_SUCCESS;
}

/* The key q of the loop (0 strategy, 1 max_iterations, 2 rules) of c:
 * its value, and the value given to every section (*set). */
static int *
loop_value (lac_scene_contact *c, int q)
{
  return q == 0 ? &c->strategy : q == 1 ? &c->max_iterations
         : &c->rules_off;
}

/* [contact] rules: the names into the bits switched off. */
static int
parse_rules (lac_scene *sc, lac_scene_contact *c)
{
  int on;
  if (!c->rules)
    return LAC_SUCCESS;
  if (lac_rule_parse (c->rules, &on))
    return lac_scene_error (sc, &c->sec, "rules", LAC_EINVAL, "%s",
                            lac_error_message ());
  c->rules_off = LAC_RULES_ALL & ~on;
  return LAC_SUCCESS;
}

/* The keys of the one loop of all pairs (strategy, max_iterations,
 * rules): in one [contact] section, or the same in several.  Every
 * section gets the value given; sc->contact_loop is the first section
 * that gives strategy, else max_iterations (0 if none does). */
static int
finish_contact_loop (lac_scene *sc)
{
  static const char *const keys[] = { "strategy", "max_iterations",
                                      "rules" };
  size_t from[3] = { SIZE_MAX, SIZE_MAX, SIZE_MAX };
  int status;
  for (size_t k = 0; k < sc->ncontact; k++)
    if ((status = parse_rules (sc, &sc->contact[k])))
      return status;
  for (int q = 0; q < 3; q++)
    {
      for (size_t k = 0; k < sc->ncontact; k++)
        {
          lac_scene_contact *c = &sc->contact[k];
          if (!given (&c->sec, keys[q]))
            continue;
          if (from[q] == SIZE_MAX)
            from[q] = k;
          else if (*loop_value (c, q)
                   != *loop_value (&sc->contact[from[q]], q))
            return lac_scene_error (sc, &c->sec, keys[q], LAC_EINVAL, "the "
                                    "pairs are solved by one loop: %s "
                                    "differs from [contact %s]", keys[q],
                                    sc->contact[from[q]].sec.name);
        }
      for (size_t k = 0; from[q] != SIZE_MAX && k < sc->ncontact; k++)
        *loop_value (&sc->contact[k], q)
          = *loop_value (&sc->contact[from[q]], q);
    }
  sc->contact_loop = from[0] != SIZE_MAX ? from[0]
                     : from[1] != SIZE_MAX ? from[1] : 0;
  return LAC_SUCCESS;
}

/* [steps] curve: a file of the output directory that no other output of
 * the run has (curve = solution.vtu overwrote the solution), named
 * without a directory (it is written into the output directory). */
static int
check_curve (lac_scene *sc)
{
  const char *c = sc->steps.curve;
  if (!c)
    return LAC_SUCCESS;
  if (strchr (c, '/') || c[0] == '.')
    return lac_scene_error (sc, &sc->steps.sec, "curve", LAC_EINVAL,
                            "expected a file name of the output directory, "
                            "without '/' and not starting with '.'");
  if (strcmp (c, "curve.csv") && lac_output_batch_ours (c))
    return lac_scene_error (sc, &sc->steps.sec, "curve", LAC_EINVAL,
                            "the run writes another output under this name "
                            "(solution.vtu, nodes.csv, contact.csv, "
                            "contact_steps.csv, contact.vtu, K.mtx, "
                            "summary.txt, steps.pvd, step_NNN.vtu): give the "
                            "curve a name of its own");
  return LAC_SUCCESS;
}

/* The keys of the large-deformation run (lac_nonlinear.h) and the keys
 * that need it: law = neo_hookean and [steps]; [exact] (small-strain
 * solutions) and the comparison contact methods do not go with it. */
static int
finish_nonlinear (lac_scene *sc)
{
  const lac_scene_main *m = &sc->scene;
  for (size_t k = 0; k < sc->nmaterial && !m->large_deformation; k++)
    if (sc->material[k].law != 0)
      return lac_scene_error (sc, &sc->material[k].sec, "law", LAC_EINVAL,
                              "needs [scene] large_deformation = yes (a "
                              "finite-strain law)");
  if (!m->large_deformation && sc->steps.sec.line != 0)
    return lac_scene_error (sc, &sc->steps.sec, NULL, LAC_EINVAL, "load "
                            "steps need [scene] large_deformation = yes");
  if (!m->large_deformation)
    return LAC_SUCCESS;
  if (check_curve (sc))
    return LAC_EINVAL;
  if (sc->exact.sec.line != 0)
    return lac_scene_error (sc, &sc->exact.sec, NULL, LAC_EINVAL, "the "
                            "exact solutions are small-strain solutions; "
                            "not with large_deformation = yes");
  for (size_t k = 0; k < sc->ncontact; k++)
    if (sc->contact[k].method != 0)
      return lac_scene_error (sc, &sc->contact[k].sec, "method", LAC_EINVAL,
                              "large_deformation = yes runs the LAC method "
                              "only (method = lac)");
  return LAC_SUCCESS;
}

int
lac_scene_finish (lac_scene *sc)
{
  int status;
  if ((status = finish_scene (sc)) || (status = finish_mesh (sc))
      || (status = finish_exact (sc)) || (status = finish_materials (sc)))
    return status;
  for (size_t k = 0; k < sc->ndirichlet; k++)
    if ((status = finish_dirichlet (sc, &sc->dirichlet[k])))
      return status;
  for (size_t k = 0; k < sc->nload; k++)
    if ((status = finish_load (sc, &sc->load[k])))
      return status;
  for (size_t k = 0; k < sc->ncontact; k++)
    if ((status = finish_contact (sc, &sc->contact[k])))
      return status;
  if (sc->ncontact && (status = finish_contact_loop (sc)))
    return status;
  return finish_nonlinear (sc);
}
