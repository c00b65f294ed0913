/* lac_run_mesh.c -- stage 1 of a run: the mesh (see lac_run_mesh.h)
 *                                                                  [LAC §2]
 */
#include "run/lac_run_mesh.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_status.h"
#include "io/lac_mesh_gmsh.h"
#include "io/lac_mesh_child.h"
#include "io/lac_mesh_gmsh_estimate.h"
#include "io/lac_scene_query.h"
#include "linalg/lac_petsc_env.h"
#include "run/lac_run_conflict.h"
#include "run/lac_run_scene.h"
#include "solve/lac_strategy.h"

/* ---- checks against the scene ----------------------------------------- */

static int
check_groups (const lac_scene *sc, const lac_mesh *m)
{
  int d = m->dim;
  for (size_t k = 0; k < sc->nmaterial; k++)
    if (sc->material[k].group
        && !lac_run_group (sc, m, &sc->material[k].sec, sc->material[k].group, d,
                        "a material"))
      return LAC_EINVAL;
  for (size_t k = 0; k < sc->ndirichlet; k++)
    {
      int roller = sc->dirichlet[k].kind == LAC_BC_NORMAL;
      if (!lac_run_group (sc, m, &sc->dirichlet[k].sec,
                          sc->dirichlet[k].group, roller ? d - 1 : -1,
                          "normal (the facets of a face, whose normals it "
                          "follows)"))
        return LAC_EINVAL;
    }
  for (size_t k = 0; k < sc->nload; k++)
    {
      const lac_scene_load *l = &sc->load[k];
      int vol = l->kind == LAC_LOAD_FORCE || l->kind == LAC_LOAD_EXACT_FORCE;
      int point = l->kind == LAC_LOAD_POINT;
      int want = vol ? d : point ? 0 : d - 1;
      const lac_group *g = NULL;
      if (l->group && !(g = lac_run_group (sc, m, &l->sec, l->group, want,
                                           vol ? "a volume force" : point
                                           ? "point_force (a point group)"
                                           : l->kind == LAC_LOAD_TOTAL
                                           ? "total_force (a boundary "
                                             "group; force: per unit "
                                             "volume)"
                                           : "a surface load")))
        return LAC_EINVAL;
      if (l->group && point && g && g->nnodes != 1)
        return lac_scene_error (sc, &l->sec, "group", LAC_EINVAL, "a point "
                                "group of %zu nodes; point_force acts on "
                                "one point", g->nnodes);
    }
  return LAC_SUCCESS;
}

static int
check_mesh (const lac_scene *sc, lac_model model, const lac_mesh *m)
{
  double xmax = 0;
  if (m->dim != lac_model_dim (model))
    return lac_scene_error (sc, &sc->mesh.sec, "file", LAC_EINVAL, "a %dD "
                            "mesh; model = %s needs a %dD mesh", m->dim,
                            lac_model_name (model), lac_model_dim (model));
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
  if (model == LAC_AXISYMMETRIC)
    for (size_t a = 0; a < m->nnodes; a++)
      if (m->x[a * 2] < -1e-12 * xmax)
        return lac_scene_error (sc, &sc->scene.sec, "model", LAC_EINVAL,
                                "node %zu of mesh '%s' has r = x = %g < 0",
                                m->node_tag[a], sc->mesh.file, m->x[a * 2]);
  return check_groups (sc, m);
}

/* Put the mesh of file k beside those of the files before it (one body
 * per file, nothing glued); a group name defined by two files is an
 * error naming both. */
static int
add_file (const lac_scene *sc, int k, size_t *gend, lac_mesh **mesh,
          lac_mesh *one)
{
  lac_mesh *both = NULL;
  int status;
  if (!*mesh)
    {
      *mesh = one;
      gend[0] = one->ngroups;
      return LAC_SUCCESS;
    }
  for (size_t g = 0; g < one->ngroups; g++)
    for (size_t h = 0; h < (*mesh)->ngroups; h++)
      if (!strcmp (one->group[g].name, (*mesh)->group[h].name))
        {
          int j = 0;                 /* the file that has it: groups of
                                        file j end before gend[j] */
          while (j < k - 1 && h >= gend[j])
            j++;
          status = lac_scene_error (sc, &sc->mesh.sec, "file", LAC_EINVAL,
                                    "group '%s' is defined in '%s' and in "
                                    "'%s'; the files of one scene need "
                                    "distinct group names",
                                    one->group[g].name, sc->mesh.files[j],
                                    sc->mesh.files[k]);
          lac_mesh_free (one);
          lac_mesh_free (*mesh);
          *mesh = NULL;
          return status;
        }
  status = lac_mesh_merge (*mesh, "", one, "", &both);
  lac_mesh_free (one);
  lac_mesh_free (*mesh);
  *mesh = both;
  if (both)
    gend[k] = both->ngroups;
  if (status)
    return lac_scene_error (sc, &sc->mesh.sec, "file", status, "%s: %s",
                            sc->mesh.files[k], lac_error_message ());
  return LAC_SUCCESS;
}

/* 1 if the .geo file at path sets the number of nodes of curves
 * ("Transfinite"): [mesh] size scales gmsh's element sizes, and changes
 * nothing on such curves. */
static int
geo_transfinite (const char *path)
{
  char line[256];
  size_t len = strlen (path);
  int found = 0;
  FILE *f;
  if (len < 4 || strcmp (path + len - 4, ".geo") || !(f = fopen (path, "r")))
    return 0;
  while (!found && fgets (line, sizeof line, f))
    found = strstr (line, "Transfinite") != NULL;
  fclose (f);
  return found;
}

/* lac_run_mesh_auto: see lac_run_mesh.h. */
int
lac_run_mesh_auto (const lac_scene *sc, int strategy)
{
  int scene = sc->ncontact ? sc->contact[sc->contact_loop].strategy
              : LAC_STRATEGY_AUTO;
  return !strategy && scene == LAC_STRATEGY_AUTO
         && !sc->scene.large_deformation
         && (sc->ncontact || !lac_scene_key_line (&sc->scene.sec, "solver"));
}

/* How the solve stage will solve (for the memory a .geo's mesh needs):
 * what the type of the strategy factorizes (the strategy asked for, else
 * the scene's, in small strain and large deformation alike: the
 * strategies factorize with their own solver); auto: on N > 1 MPI
 * processes petsc, else a dense factor with [scene] solver = dense, else
 * the scene's solver without contact or in large deformation, else a
 * Cholesky factor (schur or split), else_iterative petsc if lac has it. */
static lac_mesh_solve
solve_kind (const lac_scene *sc, int strategy, int *else_iterative)
{
  static const lac_mesh_solve by_factor[] = {   /* lac_strategy_factor */
    LAC_MESH_SOLVE_ITERATIVE, LAC_MESH_SOLVE_DENSE, LAC_MESH_SOLVE_LU,
    LAC_MESH_SOLVE_CHOLESKY };
  int scene = sc->ncontact ? sc->contact[sc->contact_loop].strategy
              : LAC_STRATEGY_AUTO;
  const lac_strategy_type *t = lac_strategy_type_of (strategy ? strategy
                                                     : scene);
  int solver = sc->scene.solver;
  int rank, size, autorun = lac_run_mesh_auto (sc, strategy);
  lac_petsc_rank (&rank, &size);
  *else_iterative = autorun && lac_petsc_available ();
  if (t)
    return by_factor[t->factor];
  if (autorun && size > 1)
    return LAC_MESH_SOLVE_ITERATIVE;
  if (solver == LAC_SOLVER_DENSE)
    return LAC_MESH_SOLVE_DENSE;
  if (sc->scene.large_deformation || !sc->ncontact)
    return solver == LAC_SOLVER_CHOLMOD ? LAC_MESH_SOLVE_CHOLESKY
                                        : LAC_MESH_SOLVE_LU;
  return LAC_MESH_SOLVE_CHOLESKY;
}

int
lac_run_mesh (const lac_scene *sc, lac_model model, int strategy,
              int infsup_solve, double max_memory, lac_mesh **mesh,
              char *progress, size_t size)
{
  lac_mesh_opts o;
  char msg[700];
  size_t n;
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
  o.max_memory = max_memory;
  o.element = sc->scene.element;
  o.solve = infsup_solve ? infsup_solve
            : (int) solve_kind (sc, strategy, &o.else_iterative);
  size_t gend[LAC_SCENE_MAX_MESHES];
  *mesh = NULL;
  for (int k = 0; k < sc->mesh.nfiles; k++)
    {
      lac_mesh *one = NULL;
      status = lac_mesh_read (sc->mesh.paths[k], &o, &one);
      if (status)
        {
          char quoted[600];
          lac_mesh_free (*mesh);
          *mesh = NULL;
          lac_run_inner_message (msg, sizeof msg);
          n = (size_t) snprintf (quoted, sizeof quoted, "'%s': ",
                                 sc->mesh.paths[k]);
          return lac_scene_error (sc, &sc->mesh.sec, "file", status, "%s%s%s",
                                  sc->mesh.nfiles > 1 ? sc->mesh.files[k] : "",
                                  sc->mesh.nfiles > 1 ? ": " : "",
                                  strncmp (msg, quoted, n) ? msg : msg + n);
        }
      if ((status = add_file (sc, k, gend, mesh, one)))
        return status;
    }
  if ((status = check_mesh (sc, model, *mesh))
      || (status = lac_run_conflicts (sc, model, *mesh)))
    return status;
  n = (size_t) snprintf (progress, size, "%zu nodes, %zu cells (%s), %zu "
                        "groups", (*mesh)->nnodes, (*mesh)->ncells,
                        (*mesh)->ncells ? lac_refelem_get ((*mesh)->type[0])
                        ->name : "-", (*mesh)->ngroups);
  if ((*mesh)->ndropped && n < size)
    n += (size_t) snprintf (progress + n, size - n, "; warning: %zu node%s "
                            "of the file in no cell, left out",
                            (*mesh)->ndropped,
                            (*mesh)->ndropped > 1 ? "s" : "");
  for (int k = 0; k < sc->mesh.nfiles && n < size; k++)
    if (lac_scene_key_line (&sc->mesh.sec, "size") && sc->mesh.size != 1
        && geo_transfinite (sc->mesh.paths[k]))
      n += (size_t) snprintf (progress + n, size - n, "; warning: [mesh] "
                              "size = %g does not change the transfinite "
                              "curves of %s (their number of nodes is "
                              "fixed): use level or numbers",
                              sc->mesh.size, sc->mesh.files[k]);
  return LAC_SUCCESS;
}

/* lac_run_mesh_bytes: see lac_run_mesh.h (the estimate of
 * src/io/lac_mesh_gmsh_estimate.c, for the cells of the mesh made). */
double
lac_run_mesh_bytes (const lac_scene *sc, const lac_mesh *m, int solve,
                    double extra)
{
  lac_mesh_opts o;
  memset (&o, 0, sizeof o);
  o.element = m->ncells ? (int) m->type[0] : sc->scene.element;
  o.solve = solve;
  return lac_gmsh_run_bytes ((double) m->nnodes, m->dim, &o) + extra;
}

/* lac_run_mesh_factor_fits: see lac_run_mesh.h. */
int
lac_run_mesh_factor_fits (const lac_scene *sc, const lac_mesh *m,
                          double max_memory)
{
  if (max_memory <= 0)
    max_memory = lac_mesh_default_memory ();
  return lac_run_mesh_bytes (sc, m, LAC_MESH_SOLVE_CHOLESKY, 0)
         <= max_memory;
}

/* lac_run_mesh_check_solve: see lac_run_mesh.h. */
int
lac_run_mesh_check_solve (const lac_scene *sc, const lac_mesh *m,
                          int solve, double extra, const char *what,
                          double max_memory)
{
  double bytes = lac_run_mesh_bytes (sc, m, solve, extra);
  if (max_memory <= 0)
    max_memory = lac_mesh_default_memory ();
  if (bytes <= max_memory)
    return LAC_SUCCESS;
  return lac_error_place (LAC_EINVAL, sc->path, "the mesh's %zu nodes%s%s "
                          "need about %.3g GB of memory with %s, more than "
                          "the limit of %.3g GB (--max-memory)", m->nnodes,
                          what[0] ? " " : "", what, bytes / 1e9,
                          lac_gmsh_solve_name (solve), max_memory / 1e9);
}
