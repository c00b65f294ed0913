/* lac_scene_keys.c -- the section and key tables of a scene, its sections
 *
 * The tables below describe every section and key a scene file may hold
 * (lac_scene.h lists them with their meaning and defaults): each key's
 * type, the field that stores it, its allowed range.  The steps of
 * reading a scene (lac_scene.c) read them; so do the messages
 * (lac_scene_query.c).  Also here: the defaults of a new section, and the
 * lookup and creation of the sections of a scene.
 */
#include "io/lac_scene_keys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "fem/lac_exact.h"
#include "fem/lac_material.h"
#include "linalg/lac_linalg.h"
#include "solve/lac_newton.h"
#include "solve/lac_nonlinear.h"
#include "solve/lac_strategy.h"
#include "base/lac_mem.h"

/* ---- tables ----------------------------------------------------------- */

const char *const lac_scene_model_names[] =
  { "plane_strain", "axisymmetric", "3d", NULL };      /* lac_model order */
static const char *const solver_names[] =
  { "dense", "umfpack", "cholmod", NULL };   /* lac_solver_kind order */
const char *const lac_scene_element_names[] =
  { "tri3", "tri6", "quad4", "quad8", "quad9",
    "tet4", "tet10", "hex8", "hex20", "hex27", NULL };
static const char *const inverted_names[] = { "flip", "reject", NULL };
static const char *const symmetry_names[] = { "x", "y", "z", "r", NULL };
static const char *const law_names[] = { "linear", "neo_hookean", NULL };

/* element name -> type, dimension, order, recombine, serendipity */
const lac_scene_element_spec lac_scene_elements[LAC_SCENE_NELEMENTS] = {
  { LAC_TRI3, 2, 1, 0, 0 }, { LAC_TRI6, 2, 2, 0, 0 },
  { LAC_QUAD4, 2, 1, 1, 0 }, { LAC_QUAD8, 2, 2, 1, 1 },
  { LAC_QUAD9, 2, 2, 1, 0 }, { LAC_TET4, 3, 1, 0, 0 },
  { LAC_TET10, 3, 2, 0, 0 }, { LAC_HEX8, 3, 1, 1, 0 },
  { LAC_HEX20, 3, 2, 1, 1 }, { LAC_HEX27, 3, 2, 1, 0 },
};

#define F(T, f) offsetof (T, f)
#define STR(T, f) { #f, K_STR, F (T, f), 0, NULL, 0, 0, 0, 0, "text" }
#define NUM(T, f, lo, hi, open, ex) \
  { #f, K_NUM, F (T, f), 0, NULL, 0, lo, hi, open, ex }
#define INT(T, f, lo, hi, ex) \
  { #f, K_INT, F (T, f), 0, NULL, 0, lo, hi, 0, ex }
#define BOOL(T, f) { #f, K_BOOL, F (T, f), 0, NULL, 0, 0, 0, 0, "yes or no" }
#define ENUM(T, f, names) \
  { #f, K_ENUM, F (T, f), 0, names, sizeof names[0], 0, 0, 0, NULL }
#define VEC(T, f, n) { #f, K_VEC, F (T, f), F (T, n), NULL, 0, 0, 0, 0, \
                       "2 or 3 numbers" }
#define VEC12(T, f, n) { #f, K_VEC, F (T, f), F (T, n), NULL, 0, 0, 0, 0, \
                         "1 or 2 numbers" }

static const key_spec scene_keys[] = {
  STR (lac_scene_main, title),
  ENUM (lac_scene_main, model, lac_scene_model_names),
  ENUM (lac_scene_main, element, lac_scene_element_names),
  ENUM (lac_scene_main, solver, solver_names),
  STR (lac_scene_main, out),
  BOOL (lac_scene_main, large_deformation),
};
static const key_spec mesh_keys[] = {
  STR (lac_scene_mesh, file),
  NUM (lac_scene_mesh, size, 0, HUGE_VAL, 1, "a number > 0"),
  INT (lac_scene_mesh, order, 1, 2, "1 or 2"),
  INT (lac_scene_mesh, level, 0, 12, "an integer in 0..12"),
  STR (lac_scene_mesh, numbers),
  BOOL (lac_scene_mesh, recombine),
  ENUM (lac_scene_mesh, inverted, inverted_names),
};
static const key_spec material_keys[] = {
  STR (lac_scene_material, group),
  NUM (lac_scene_material, E, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_material, nu, -1, 0.5, 3, "a number in (-1, 0.5)"),
  ENUM (lac_scene_material, law, law_names),
};
static const key_spec dirichlet_keys[] = {
  STR (lac_scene_dirichlet, group),
  NUM (lac_scene_dirichlet, ux, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_dirichlet, uy, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_dirichlet, uz, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_dirichlet, ur, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  BOOL (lac_scene_dirichlet, clamp),
  ENUM (lac_scene_dirichlet, symmetry, symmetry_names),
  BOOL (lac_scene_dirichlet, exact),
  NUM (lac_scene_dirichlet, normal, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  BOOL (lac_scene_dirichlet, ramp),
};
static const char *const load_exact_names[] =
  { "none", "traction", "tangential", "force", NULL };
static const key_spec load_keys[] = {
  STR (lac_scene_load, group),
  NUM (lac_scene_load, pressure, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  VEC (lac_scene_load, traction, ntraction),
  VEC (lac_scene_load, force, nforce),
  ENUM (lac_scene_load, exact, load_exact_names),
  VEC (lac_scene_load, total_force, ntotal_force),
  BOOL (lac_scene_load, plate),
  VEC (lac_scene_load, point_force, npoint_force),
};
static const key_spec exact_keys[] = {
  { "solution", K_ENUM, F (lac_scene_exact, solution), 0,    /* lac_exact.h */
    &lac_exact_table[0].name, sizeof lac_exact_table[0], 0, 0, 0, NULL },
  NUM (lac_scene_exact, a, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_exact, b, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_exact, p, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  NUM (lac_scene_exact, E, 0, HUGE_VAL, 1, "a number > 0"),
  NUM (lac_scene_exact, nu, -1, 0.5, 3, "a number in (-1, 0.5)"),
};
static const char *const obstacle_names[] = { "none", "graph", NULL };
static const char *const normal_names[] = { "obstacle", "slave", NULL };
static const char *const method_names[] = { "lac", "p0", "nts", NULL };
static const char *const hex_cut_names[] =      /* LAC_MACRO_HEX_* */
  { "auto", "pyramids", "six", NULL };
static const key_spec contact_keys[] = {
  STR (lac_scene_contact, slave),
  STR (lac_scene_contact, master),
  ENUM (lac_scene_contact, obstacle, obstacle_names),
  NUM (lac_scene_contact, height, -HUGE_VAL, HUGE_VAL, 0, "a number"),
  VEC12 (lac_scene_contact, curvature, ncurvature),
  VEC12 (lac_scene_contact, center, ncenter),
  ENUM (lac_scene_contact, normal, normal_names),
  NUM (lac_scene_contact, epsilon, 0, 1, 1, "a number in (0, 1]"),
  ENUM (lac_scene_contact, method, method_names),
  { "strategy", K_ENUM, F (lac_scene_contact, strategy), 0,  /* the table */
    &lac_strategy_table[0].name, sizeof lac_strategy_table[0], 0, 0, 0,
    NULL },
  INT (lac_scene_contact, max_iterations, 1, 100000,
       "an integer in 1..100000"),
  STR (lac_scene_contact, rules),
  NUM (lac_scene_contact, gap_bound, 0, HUGE_VAL, 0, "a length >= 0"),
  NUM (lac_scene_contact, interference, 0, HUGE_VAL, 0, "a length >= 0"),
  ENUM (lac_scene_contact, hex_cut, hex_cut_names),
};
static const char *const tangent_names[] =            /* lac_nonlinear.h */
  { "consistent", "frozen", NULL };
static const key_spec steps_keys[] = {
  INT (lac_scene_steps, n, 1, 100000, "an integer in 1..100000"),
  NUM (lac_scene_steps, start, 0, 1, 2, "a number in [0, 1)"),
  NUM (lac_scene_steps, tol, 0, HUGE_VAL, 1, "a number > 0"),
  INT (lac_scene_steps, maxit, 1, 1000, "an integer in 1..1000"),
  STR (lac_scene_steps, monitor),
  STR (lac_scene_steps, curve),
  INT (lac_scene_steps, vtu_every, 0, 100000, "an integer in 0..100000"),
  ENUM (lac_scene_steps, tangent, tangent_names),
};
static const char *const vtu_format_names[] = { "binary", "ascii", NULL };
static const key_spec output_keys[] = {
  BOOL (lac_scene_output, vtu),
  BOOL (lac_scene_output, csv),
  BOOL (lac_scene_output, matrix),
  ENUM (lac_scene_output, vtu_format, vtu_format_names),
  BOOL (lac_scene_output, reactions),
};

#define NK(a) ((int) (sizeof a / sizeof a[0]))
const section_spec lac_scene_sections[NSEC] = {
  { "scene", 0, scene_keys, NK (scene_keys) },
  { "mesh", 0, mesh_keys, NK (mesh_keys) },
  { "material", 1, material_keys, NK (material_keys) },
  { "dirichlet", 1, dirichlet_keys, NK (dirichlet_keys) },
  { "load", 1, load_keys, NK (load_keys) },
  { "exact", 0, exact_keys, NK (exact_keys) },
  { "output", 0, output_keys, NK (output_keys) },
  { "contact", 1, contact_keys, NK (contact_keys) },
  { "steps", 0, steps_keys, NK (steps_keys) },
};

/* ---- sections: lookup and creation ------------------------------------ */

int
lac_scene_section_kind (const char *type)
{
  for (int k = 0; k < NSEC; k++)
    if (strcmp (lac_scene_sections[k].name, type) == 0)
      return k;
  return -1;
}

int
lac_scene_split_section (const char *sec, char *buf, size_t size,
                         const char **name)
{
  char *sp;
  snprintf (buf, size, "%s", sec);
  sp = strchr (buf, ' ');
  *name = "";
  if (sp)
    {
      *sp = '\0';
      *name = sp + 1;
    }
  return lac_scene_section_kind (buf);
}

void
lac_scene_section_defaults (int kind, lac_scene_section *s)
{
  switch (kind)
    {
    case SEC_SCENE:
      {
        lac_scene_main *m = (lac_scene_main *) s;
        m->model = LAC_PLANE_STRAIN;
        m->element = LAC_ELEM_NONE;
        m->solver = LAC_SOLVER_CHOLMOD;
        break;
      }
    case SEC_MESH:
      {
        lac_scene_mesh *m = (lac_scene_mesh *) s;
        m->size = 1;
        m->recombine = -1;
        break;
      }
    case SEC_MATERIAL:
      ((lac_scene_material *) s)->E = ((lac_scene_material *) s)->nu = NAN;
      break;
    case SEC_EXACT:
      ((lac_scene_exact *) s)->solution = LAC_EXACT_NONE;
      break;
    case SEC_OUTPUT:
      ((lac_scene_output *) s)->vtu = ((lac_scene_output *) s)->csv = 1;
      break;
    case SEC_CONTACT:
      ((lac_scene_contact *) s)->strategy = LAC_STRATEGY_AUTO;
      ((lac_scene_contact *) s)->max_iterations = LAC_NEWTON_MAXIT;
      break;
    case SEC_DIRICHLET:
      ((lac_scene_dirichlet *) s)->ramp = 1;
      break;
    case SEC_STEPS:
      {
        lac_scene_steps *t = (lac_scene_steps *) s;
        t->n = 1;
        t->tol = LAC_NL_TOL;
        t->maxit = LAC_NL_MAXIT;
        break;
      }
    default:
      break;
    }
  s->kind = kind;
}

static lac_scene_section *
singleton (lac_scene *sc, int kind)
{
  switch (kind)
    {
    case SEC_SCENE: return &sc->scene.sec;
    case SEC_MESH: return &sc->mesh.sec;
    case SEC_EXACT: return &sc->exact.sec;
    case SEC_OUTPUT: return &sc->output.sec;
    case SEC_STEPS: return &sc->steps.sec;
    default: return NULL;
    }
}

/* Named sections: count, k-th, and one more (zeroed) at the end. */
static size_t
named_count (const lac_scene *sc, int kind)
{
  return kind == SEC_MATERIAL ? sc->nmaterial
         : kind == SEC_DIRICHLET ? sc->ndirichlet
         : kind == SEC_CONTACT ? sc->ncontact : sc->nload;
}

static lac_scene_section *
named_at (lac_scene *sc, int kind, size_t k)
{
  return kind == SEC_MATERIAL ? &sc->material[k].sec
         : kind == SEC_DIRICHLET ? &sc->dirichlet[k].sec
         : kind == SEC_CONTACT ? &sc->contact[k].sec : &sc->load[k].sec;
}

/* One more section at the end of a named kind's array, zeroed; the
 * arrays double as they grow (lac_grow), so that a scene of n sections
 * is read in time linear in n. */
#define GROW(arr, n, cap)                                               \
  do {                                                                  \
    if (lac_grow (&(arr), (n) + 1, &(cap), sizeof *(arr), 4))           \
      return NULL;                                                      \
    memset (&(arr)[(n)], 0, sizeof *(arr));                             \
    s = &(arr)[(n)++].sec;                                              \
  } while (0)

static lac_scene_section *
named_grow (lac_scene *sc, int kind)
{
  lac_scene_section *s;
  if (kind == SEC_MATERIAL)
    GROW (sc->material, sc->nmaterial, sc->cap[0]);
  else if (kind == SEC_DIRICHLET)
    GROW (sc->dirichlet, sc->ndirichlet, sc->cap[1]);
  else if (kind == SEC_CONTACT)
    GROW (sc->contact, sc->ncontact, sc->cap[2]);
  else
    GROW (sc->load, sc->nload, sc->cap[3]);
  return s;
}

lac_scene_section *
lac_scene_section_get (lac_scene *sc, int kind, size_t k)
{
  if (!lac_scene_sections[kind].named)
    return singleton (sc, kind);
  return k < named_count (sc, kind) ? named_at (sc, kind, k) : NULL;
}

size_t
lac_scene_section_count (const lac_scene *sc, int kind)
{
  return lac_scene_sections[kind].named ? named_count (sc, kind) : 1;
}

lac_scene_section *
lac_scene_section_find (lac_scene *sc, int kind, const char *name)
{
  if (!lac_scene_sections[kind].named)
    {
      lac_scene_section *s = singleton (sc, kind);
      return s->line ? s : NULL;
    }
  for (size_t k = 0; k < named_count (sc, kind); k++)
    if (strcmp (named_at (sc, kind, k)->name, name) == 0)
      return named_at (sc, kind, k);
  return NULL;
}

lac_scene_section *
lac_scene_section_new (lac_scene *sc, int kind, const char *name, int line)
{
  lac_scene_section *s;
  if (!lac_scene_sections[kind].named)
    {
      s = singleton (sc, kind);
      s->line = line;
      return s;
    }
  if (!(s = named_grow (sc, kind)))
    return NULL;
  lac_scene_section_defaults (kind, s);
  s->line = line;
  s->name = lac_strdup (name);   /* freed with the scene even if NULL */
  return s->name ? s : NULL;
}

int
lac_scene_key_index (int kind, const char *key)
{
  for (int k = 0; k < lac_scene_sections[kind].nkeys; k++)
    if (strcmp (lac_scene_sections[kind].keys[k].name, key) == 0)
      return k;
  return -1;
}

void
lac_scene_join_names (char *buf, size_t size, const char *const *names,
                      size_t n, size_t stride)
{
  size_t len = 0;
  buf[0] = '\0';
  for (size_t k = 0; k < n; k++)
    {
      const char *s = *(const char *const *) ((const char *) names
                                              + k * stride);
      int w = snprintf (buf + len, size - len, "%s%s", k ? ", " : "", s);
      if (w < 0 || (size_t) w >= size - len)
        break;
      len += (size_t) w;
    }
}

void
lac_scene_section_list (char *buf, size_t size)
{
  size_t len = 0;
  for (int k = 0; k < NSEC && len < size; k++)
    {
      const section_spec *sp = &lac_scene_sections[k];
      int w = snprintf (buf + len, size - len, "%s%s%s", k ? ", " : "",
                        sp->name, sp->named ? " NAME" : "");
      if (w < 0)
        break;
      len += (size_t) w;
    }
}
