/* lac_scene.h -- scene files: what one run of lac computes
 *
 * A scene is a small INI file (parsed with inih) naming the mesh, the model,
 * the materials, the boundary conditions by physical group, the exact
 * solution used to measure errors, and the outputs.  Sections and keys are
 * described by tables in lac_scene.c: adding a key is one table line plus a
 * field, adding a section one table entry plus a struct.  Every key keeps
 * the line it was read from, so that later stages (lac_run.c) can point at
 * the offending line of the scene file.
 *
 * Syntax: `[section]` or `[section NAME]` headers, `key = value` lines,
 * comments from `;` or `#` at the start of a line, or after a blank inside
 * a line.  Numbers are C numbers (1e3, -0.25); booleans yes|no, true|false,
 * on|off, 1|0; vectors are 2 or 3 numbers separated by blanks.
 *
 *   section / key          value                      default
 *   ---------------------  -------------------------  ---------------------
 *   [scene]
 *     title                free text                  scene file name
 *     model                plane_strain | axisymmetric | 3d   plane_strain
 *     element              tri3 tri6 quad4 quad8 quad9 tet4 tet10 hex8
 *                          hex20 hex27: the cells .geo meshing makes
 *                          (sets mesh order / recombine / serendipity) and
 *                          the only type a .msh may contain    any
 *     solver               dense | umfpack | cholmod  cholmod
 *     out                  output directory (relative to the current
 *                          directory)                 out/<scene basename>
 *     large_deformation    yes: total Lagrangian hyperelasticity, load
 *                          steps and one generalized Newton loop for
 *                          material, geometry and contact, re-pairing at
 *                          every iteration [LAC §4.5, Alg. 1]
 *                          (lac_nonlinear.h)          no
 *   [mesh]
 *     file                 .geo or .msh, relative to the scene file's
 *                          directory                  (required)
 *     size                 mesh size factor > 0 (.geo)            1
 *     order                1 | 2 (.geo)               from element, else 1
 *     level                refinement level 0..12, exported to the .geo as
 *                          the number `level`         0
 *     recombine            yes | no: quadrangles/hexahedra (.geo)
 *                                                     from element
 *     inverted             flip | reject: cells with det J < 0     flip
 *   [material NAME]        one per body
 *     group                volume physical group      all cells not in
 *                                                     another material
 *     E                    Young's modulus > 0        (required)
 *     nu                   Poisson's ratio in (-1, 1/2)  (required)
 *     law                  linear (Hooke; Saint Venant-Kirchhoff with
 *                          large_deformation) | neo_hookean (needs
 *                          large_deformation; lac_hyper.h)   linear
 *   [dirichlet NAME]       imposed displacements on the nodes of a group
 *     group                physical group (any dimension)  (required)
 *     ux uy uz             value of one component (3d: ux uy uz; plane
 *                          strain: ux uy)
 *     ur uz                axisymmetric: radial / axial component
 *     clamp                yes: every component zero
 *     symmetry             x | y | z | r: the normal component zero
 *     exact                yes: every component from the [exact] solution
 *     ramp                 yes | no: with [steps], the values grow with
 *                          the load factor t (yes) or are imposed whole
 *                          from the first step (no)   yes
 *   [load NAME]            exactly one of:
 *     group                boundary group (pressure, traction) or volume
 *                          group (force; all cells if absent)
 *     pressure             p: traction -p n on the group (p > 0 pushes)
 *     traction             tx ty [tz]: traction per unit area
 *     force                fx fy [fz]: force per unit volume
 *     exact                traction | tangential | force: the traction
 *                          sigma(u) n (or its tangential part, for a
 *                          contact side) or the body force -div sigma(u)
 *                          of the [exact] solution (manufactured solutions)
 *   [contact NAME]         frictionless unilateral contact by the LAC
 *                          method (at most one section in this version)
 *     slave                facet group carrying the multipliers (its cells
 *                          are refined where Hypothesis 1 needs it)
 *                                                     (required)
 *     master               facet group of the other body, or
 *     obstacle             graph: a rigid foundation v <= h(w) below the
 *                          graph h(w) = height + sum_k curvature_k
 *                          (w_k - center_k)^2 (v = y in 2D, z in 3D; w the
 *                          other coordinates)          (one of the two)
 *     height curvature center   the graph (0; 0 [0]; 0 [0])
 *     epsilon              admissibility threshold in (0, 1] [LAC Def. 1]
 *                                                     0.01
 *     method               lac | p0 (one multiplier per raw slave facet,
 *                          no macro-elements: violates Hypothesis 1) |
 *                          nts (node-to-segment / node-to-face
 *                          collocation): p0 and nts for comparisons  lac
 *   [exact]                analytic solution for errors and `exact` data
 *                          (the table of lac_exact.c)
 *     solution             thick_sphere (axisymmetric, 3d: sphere a < R < b
 *                          under inner pressure p) | thick_cylinder (plane
 *                          strain, 3d with uz = 0: cylinder a < r < b)
 *     a b p E nu           inner and outer radius, inner pressure, Young's
 *                          modulus, Poisson's ratio   (all required)
 *   [steps]                load steps of a large_deformation scene: the
 *                          load factor t goes to `start` in one step (if
 *                          start > 0), then to 1 in n equal steps; loads
 *                          and ramped Dirichlet values are t times theirs
 *     n                    number of equal steps >= 1          1
 *     start                load factor of the first step in [0, 1)   0
 *     tol                  Newton tolerance > 0 (residual, gaps)  1e-8
 *     maxit                Newton iterations per step, 1..1000    25
 *     monitor              node group (a physical point): its displacement
 *                          at every step goes to the curve CSV  (none)
 *     curve                file name of the per-step CSV    curve.csv
 *     vtu_every            K >= 0: step_NNN.vtu after every K-th step and
 *                          the last, listed in steps.pvd (0: none)   0
 *   [output]
 *     vtu                  yes | no: solution.vtu     yes
 *     csv                  yes | no: nodes.csv        yes
 *     matrix               yes | no: K.mtx (Matrix Market, stiffness before
 *                          the Dirichlet conditions)  no
 *
 * Overrides (`lac run --set KEY=VALUE`) are applied after the file is read
 * and checked like file entries; messages about them say "--set".  KEY is
 * SECTION.KEY (scene.model, mesh.level), TYPE.NAME.KEY for named sections
 * (material.steel.E), or one of the aliases element, model, solver, out,
 * level, order, size.  A named section must exist in the file; an unnamed
 * one is created if needed.
 *
 * Ownership: lac_scene_read returns a scene freed with lac_scene_free; every
 * pointer inside is owned by the scene.
 */
#ifndef LAC_SCENE_H
#define LAC_SCENE_H

#include <stddef.h>
#include "fem/lac_exact.h"
#include "fem/lac_material.h"
#include "fem/lac_spaces.h"

#define LAC_SCENE_MAX_KEYS 16

/* Where a section and each of its keys came from: line numbers in the
 * scene file, LAC_SCENE_FROM_SET for --set, 0 when not given. */
#define LAC_SCENE_FROM_SET (-1)

typedef struct lac_scene_section
{
  int kind;                             /* index in the section table     */
  char *name;                           /* owned: NAME, or NULL           */
  int line;                             /* line of the [header]           */
  int key_line[LAC_SCENE_MAX_KEYS];     /* per key of the table: its line */
  char *key_raw[LAC_SCENE_MAX_KEYS];    /* owned: the value as written    */
} lac_scene_section;

typedef struct lac_scene_main            /* [scene] */
{
  lac_scene_section sec;
  char *title;          /* owned */
  int model;            /* lac_model */
  int element;          /* lac_elem_type, LAC_ELEM_NONE if not given */
  int solver;           /* lac_solver_kind */
  char *out;            /* owned, NULL if not given */
  int large_deformation;  /* 1: the nonlinear run (lac_nonlinear.h) */
} lac_scene_main;

typedef struct lac_scene_mesh            /* [mesh] */
{
  lac_scene_section sec;
  char *file;           /* owned: as written in the scene             */
  char *path;           /* owned: resolved against the scene directory */
  double size;
  int order;            /* 0: as the file / element says */
  int level;
  int recombine;        /* -1: as the element says */
  int inverted;         /* 0 flip, 1 reject */
} lac_scene_mesh;

typedef struct lac_scene_material        /* [material NAME] */
{
  lac_scene_section sec;
  char *group;          /* owned, NULL: every cell not in another group */
  double E, nu;
  int law;              /* lac_law (lac_hyper.h): 0 linear, 1 neo_hookean */
} lac_scene_material;

typedef enum
{
  LAC_BC_COMPONENTS,    /* ux / uy / uz (ur) values */
  LAC_BC_CLAMP,
  LAC_BC_SYMMETRY,
  LAC_BC_EXACT
} lac_bc_kind;

typedef struct lac_scene_dirichlet       /* [dirichlet NAME] */
{
  lac_scene_section sec;
  char *group;          /* owned */
  lac_bc_kind kind;
  int fixed[3];         /* components fixed (model components)          */
  double value[3];      /* their values                                 */
  double ux, uy, uz, ur;            /* raw key values (table storage)  */
  int clamp, exact, symmetry;       /* raw key values (table storage)  */
  int ramp;             /* 1: values times the load factor ([steps])   */
} lac_scene_dirichlet;

typedef enum
{
  LAC_LOAD_PRESSURE, LAC_LOAD_TRACTION, LAC_LOAD_FORCE,
  LAC_LOAD_EXACT_TRACTION,    /* sigma(u) n of the [exact] solution        */
  LAC_LOAD_EXACT_TANGENTIAL,  /* its tangential part (on a contact side)   */
  LAC_LOAD_EXACT_FORCE        /* -div sigma(u) of the [exact] solution     */
} lac_load_kind;

typedef struct lac_scene_load            /* [load NAME] */
{
  lac_scene_section sec;
  char *group;          /* owned, NULL: all cells (force only) */
  lac_load_kind kind;
  double pressure;
  double vec[3];        /* traction or force, model components */
  double traction[3], force[3];     /* raw key values (table storage)  */
  int ntraction, nforce;
  int exact;                        /* 0 none, 1 traction, 2 tangential,
                                       3 force (table storage)          */
} lac_scene_load;

typedef struct lac_scene_exact           /* [exact] */
{
  lac_scene_section sec;
  int solution;         /* lac_exact_kind: index in lac_exact_table */
  double a, b, p, E, nu;
} lac_scene_exact;

typedef struct lac_scene_contact         /* [contact NAME] */
{
  lac_scene_section sec;
  char *slave;          /* owned: facet group carrying the multipliers    */
  char *master;         /* owned: facet group of the other body, or NULL  */
  int obstacle;         /* 1: a rigid obstacle below a graph (no master)  */
  double height;        /* obstacle: v <= height + sum curv_k (w_k - c_k)^2 */
  double curvature[3], center[3];    /* (room for 3: the parser's limit) */
  int ncurvature, ncenter;
  double epsilon;       /* admissibility threshold [LAC Def. 1]            */
  int method;           /* 0 lac, 1 p0 (raw trace), 2 nts (collocation)   */
} lac_scene_contact;

typedef struct lac_scene_steps           /* [steps] */
{
  lac_scene_section sec;
  int n;                /* equal load steps (after the start step)        */
  double start;         /* load factor of a first step, 0: none            */
  double tol;           /* Newton tolerance (lac_nl_opts.tol)              */
  int maxit;            /* Newton iterations per step                      */
  char *monitor;        /* owned, NULL: node group followed step by step   */
  char *curve;          /* owned, NULL: file name of the per-step CSV      */
  int vtu_every;        /* K > 0: step_NNN.vtu every K steps, 0: none      */
} lac_scene_steps;

typedef struct lac_scene_output          /* [output] */
{
  lac_scene_section sec;
  int vtu, csv, matrix;
} lac_scene_output;

typedef struct lac_scene
{
  char *path;                   /* owned: the scene file as given        */
  char *dir;                    /* owned: its directory ("." if none)    */
  char *basename;               /* owned: file name without .scene       */
  lac_scene_main scene;
  lac_scene_mesh mesh;
  lac_scene_exact exact;        /* exact.sec.line == 0: no [exact]       */
  lac_scene_output output;
  lac_scene_steps steps;        /* steps.sec.line == 0: no [steps]       */
  size_t nmaterial, ndirichlet, nload, ncontact;
  lac_scene_material *material;     /* owned, nmaterial  */
  lac_scene_dirichlet *dirichlet;   /* owned, ndirichlet */
  lac_scene_load *load;             /* owned, nload      */
  lac_scene_contact *contact;       /* owned, ncontact (0 or 1) */
} lac_scene;

/* construct / destroy */

/* Read the scene file `path`, apply the nset overrides "KEY=VALUE" and
 * check everything that can be checked without the mesh (types, ranges,
 * enums, required keys, conflicts, the mesh file exists).  Errors are one
 * line: "PATH:LINE: [section] key = 'value': what is wrong". */
int lac_scene_read (const char *path, size_t nset, const char *const *set,
                    lac_scene **out);
/* The same from a string; `path` is used for messages and relative paths. */
int lac_scene_read_string (const char *text, const char *path, size_t nset,
                           const char *const *set, lac_scene **out);
void lac_scene_free (lac_scene *sc);    /* NULL allowed */

/* query */

/* Line of `key` in section s: > 0 file line, LAC_SCENE_FROM_SET, 0 absent
 * (then the section header line is a better place to point at). */
int lac_scene_key_line (const lac_scene_section *s, const char *key);

/* Store "PATH:LINE: [section name] key = 'raw': <fmt...>" as the error
 * message (key may be NULL for the section itself) and return status. */
int lac_scene_error (const lac_scene *sc, const lac_scene_section *s,
                     const char *key, int status, const char *fmt, ...)
  __attribute__ ((format (printf, 5, 6)));

/* Names for messages and summaries. */
const char *lac_scene_element_name (int element);    /* "tri6", "any" */
const char *lac_scene_exact_name (int solution);     /* "thick_sphere" */

/* Model component index of a displacement key for the model ("ux", "ur",
 * "uz", ...), or -1 if the key does not apply to the model. */
int lac_scene_component (lac_model model, const char *key);

#endif /* LAC_SCENE_H */
