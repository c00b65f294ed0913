/* lac_scene_types.h -- what a scene holds once read
 *
 * One typed struct per section of a scene file (the format, the keys and
 * their defaults are described in lac_scene.h), and the scene itself.
 * Every section remembers the lines its header and its keys came from, so
 * that later stages can point at the offending line (lac_scene_query.h).
 * The section and key tables that fill these structs are in
 * lac_scene_keys.c.
 *
 * Ownership: every pointer inside a lac_scene is owned by it
 * (lac_scene_free, lac_scene.h).
 */
#ifndef LAC_SCENE_TYPES_H
#define LAC_SCENE_TYPES_H

#include <stddef.h>
#include "fem/lac_exact.h"        /* solution: a lac_exact_kind */
#include "fem/lac_material.h"     /* model: a lac_model */
#include "fem/lac_spaces.h"       /* element: a lac_elem_type */

#define LAC_SCENE_MAX_KEYS 16

/* The largest scene file read: a scene is a few kilobytes of text (the
 * largest of lac's is 3 kB); a path to anything larger, or to what is not
 * a regular file (/dev/zero, a named pipe), is refused before it is read
 * (base/lac_input.h). */
#define LAC_SCENE_MAX_BYTES 4e6

/* Every real value of a scene is at most LAC_SCENE_NUM_MAX in magnitude,
 * and a value that must be > 0 at least 1 / LAC_SCENE_NUM_MAX: products
 * of moduli, loads, lengths and displacements then stay far from the
 * overflow of a double (1.8e308) and from its underflow. */
#define LAC_SCENE_NUM_MAX 1e30

/* nu may come this close to 0.5: lambda / mu = 2 nu / (1 - 2 nu) stays
 * below 1e8, where the stiffness of displacement elements is still
 * solved to some digits (it is singular to rounding at 1e12-1e15). */
#define LAC_SCENE_NU_MAX 0.499999995

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

#define LAC_SCENE_MAX_MESHES 8     /* files of one [mesh] file = ...  */

typedef struct lac_scene_mesh            /* [mesh] */
{
  lac_scene_section sec;
  char *file;           /* owned: as written in the scene             */
  char *path;           /* owned: resolved against the scene directory
                           (the first file)                            */
  int nfiles;           /* files named (separated by blanks), >= 1      */
  char *files[LAC_SCENE_MAX_MESHES];   /* owned: each name as written  */
  char *paths[LAC_SCENE_MAX_MESHES];   /* owned: each resolved         */
  double size;
  int order;            /* 0: as the file / element says */
  int level;
  char *numbers;        /* owned, NULL: "NAME=VALUE ..." for the .geo      */
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
  LAC_BC_EXACT,
  LAC_BC_NORMAL         /* u.n = value along the face's outward normal n
                           (a roller: fem/lac_frames.h)                  */
} lac_bc_kind;

typedef struct lac_scene_dirichlet       /* [dirichlet NAME] */
{
  lac_scene_section sec;
  char *group;          /* owned */
  lac_bc_kind kind;
  int fixed[3];         /* components fixed (model components)          */
  double value[3];      /* their values                                 */
  double ux, uy, uz, ur;            /* raw key values (table storage)  */
  double normal;                    /* LAC_BC_NORMAL: the value of u.n   */
  int clamp, exact, symmetry;       /* raw key values (table storage)  */
  int ramp;             /* 1: values times the load factor ([steps])   */
} lac_scene_dirichlet;

typedef enum
{
  LAC_LOAD_PRESSURE, LAC_LOAD_TRACTION, LAC_LOAD_FORCE,
  LAC_LOAD_EXACT_TRACTION,    /* sigma(u) n of the [exact] solution        */
  LAC_LOAD_EXACT_TANGENTIAL,  /* its tangential part (on a contact side)   */
  LAC_LOAD_EXACT_FORCE,       /* -div sigma(u) of the [exact] solution     */
  LAC_LOAD_TOTAL,             /* a total force on a boundary group: spread
                                 uniformly (traction F / |group|) or, with
                                 plate, through a rigid plate              */
  LAC_LOAD_POINT              /* a force on the node of a point group      */
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
  double total_force[3], point_force[3];   /* raw key values            */
  int ntotal_force, npoint_force;
  int plate;            /* total_force: 1: the group moves as one rigid
                           plate (translation), the force on the plate   */
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
  int normal;           /* obstacle: gap and constraint along 0 the
                           obstacle's normal, 1 the slave's (lac_obstacle.h) */
  double epsilon;       /* admissibility threshold [LAC Def. 1]; 0: not
                           given (the method's default)                    */
  int method;           /* 0 lac, 1 p0 (raw trace), 2 nts (collocation)   */
  int strategy;         /* lac_strategy_kind, LAC_STRATEGY_AUTO default   */
  int max_iterations;   /* active-set iterations at most
                           (LAC_NEWTON_MAXIT, solve/lac_newton.h)         */
  char *rules;          /* the rules of the loop switched on: all (the
                           default), none, or a list of their names
                           (solve/lac_newton_rules.h)                      */
  int rules_off;        /* and the LAC_RULE_* bits switched off           */
  double gap_bound;     /* pairs up to this normal gap more (length, 0)   */
  double interference;  /* delta >= 0 taken from every gap: a shrink fit
                           drawn with matching surfaces (length, 0)       */
  int hex_cut;          /* the cut of a hexahedron under a slave face:
                           0 auto (hex8 pyramids, hex20 six), 1 pyramids,
                           2 six (LAC_MACRO_HEX_*, contact/lac_refine.h)  */
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
  int tangent;          /* 0 consistent, 1 frozen (lac_nl_opts.frozen)     */
} lac_scene_steps;

typedef struct lac_scene_output          /* [output] */
{
  lac_scene_section sec;
  int vtu, csv, matrix;
  int vtu_format;       /* 0 binary (appended raw), 1 ascii               */
  int reactions;        /* 1: reaction.NAME lines in the summary
                           (run/lac_run_reaction.h)                      */
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
  size_t cap[4];                /* allocated: material, dirichlet,
                                   contact, load (they grow by doubling) */
  lac_scene_material *material;     /* owned, nmaterial  */
  lac_scene_dirichlet *dirichlet;   /* owned, ndirichlet */
  lac_scene_load *load;             /* owned, nload      */
  lac_scene_contact *contact;       /* owned, ncontact: the contact pairs */
  size_t contact_loop;          /* the [contact] section that gives the
                                   keys of the one loop of all pairs
                                   (strategy, max_iterations), 0 if none */
} lac_scene;

#endif /* LAC_SCENE_TYPES_H */
