/* lac_scene.h -- scene files: what one run of lac computes
 *
 * A scene is a small INI file (parsed with inih) naming the mesh, the model,
 * the materials, the boundary conditions by physical group, the exact
 * solution used to measure errors, and the outputs.  Sections and keys are
 * described by tables in lac_scene_keys.c: adding a key is one table line
 * plus a field, adding a section one table entry plus a struct (in
 * lac_scene_types.h).  Every key keeps the line it was read from, so that
 * later stages (lac_run.c) can point at the offending line of the scene
 * file (lac_scene_query.h).
 *
 * Syntax: `[section]` or `[section NAME]` headers, `key = value` lines,
 * comments from `;` or `#` at the start of a line, or after a blank inside
 * a line.  Numbers are decimal C numbers (1e3, -0.25), finite doubles,
 * through the one checked parser of base/lac_number.h; booleans yes|no, true|false,
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
 *                          directory; or several separated by blanks (at
 *                          most LAC_SCENE_MAX_MESHES, one per body, put
 *                          side by side; no group name in two files)
 *                                                     (required)
 *     size                 mesh size factor > 0 (.geo)            1
 *     order                1 | 2 (.geo)               from element, else 1
 *     level                refinement level 0..12, exported to the .geo as
 *                          the number `level`         0
 *     numbers              "NAME=VALUE ..." more numbers for the .geo,
 *                          each finite, |VALUE| <= 2^31 - 1
 *                          (lac_mesh_opts.h)             none
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
 *     normal               g: u.n = g along the outward unit normal n of
 *                          a facet group at each node (a roller for g =
 *                          0, on any face, plane or curved:
 *                          run/lac_run_roller.h)
 *     ramp                 yes | no: with [steps], the values grow with
 *                          the load factor t (yes) or are imposed whole
 *                          from the first step (no)   yes
 *     curve                t0 f0 t1 f1 ...: with [steps], small strain:
 *                          the values times f(t), linear between the
 *                          pairs (t increasing), constant beyond the ends
 *                          (lac_scene_factor)          f = t or 1 (ramp)
 *   [load NAME]            exactly one of pressure, traction, force,
 *                          exact, total_force, point_force:
 *     group                boundary group (pressure, traction,
 *                          total_force), volume group (force; all cells
 *                          if absent) or point group (point_force)
 *     pressure             p: traction -p n on the group (p > 0 pushes)
 *     traction             tx ty [tz]: traction per unit area
 *     force                fx fy [fz]: force per unit volume
 *     total_force          Fx Fy [Fz]: a total force on a boundary group,
 *                          spread uniformly (traction F / |group|)
 *     plate                yes: with total_force, the group moves as one
 *                          rigid plate (translation) carrying the force
 *                          (run/lac_run_plate.h)             no
 *     point_force          Fx Fy [Fz]: a force at the node of a point
 *                          group (a gmsh Physical Point of one point)
 *     exact                traction | tangential | force: the traction
 *                          sigma(u) n (or its tangential part, for a
 *                          contact side) or the body force -div sigma(u)
 *                          of the [exact] solution (manufactured solutions)
 *     curve                as for [dirichlet]: the load times f(t)  f = t
 *   [contact NAME]         frictionless unilateral contact by the LAC
 *                          method: one section per contact pair
 *                          (contact/lac_contact_set.h)
 *     slave                facet group carrying the multipliers (its cells
 *                          are refined where Hypothesis 1 needs it)
 *                                                     (required)
 *     master               facet group of the other body, or
 *     obstacle             graph: a rigid foundation v <= h(w) below the
 *                          graph h(w) = height + sum_k curvature_k
 *                          (w_k - center_k)^2 (v = y in 2D, z in 3D; w the
 *                          other coordinates)          (one of the two)
 *     height curvature center   the graph (0; 0 [0]; 0 [0])
 *     normal               obstacle | slave: the gap and the constraint
 *                          against the obstacle along its normal at the
 *                          closest point, or along the slave normal (the
 *                          paper's manufactured solutions)   obstacle
 *     epsilon              admissibility threshold in (0, 1] [LAC Def. 1]
 *                          (0 in the struct when not given: the
 *                          method's default LAC_EPSILON_DEFAULT)   0.01
 *     method               lac | p0 (one multiplier per raw slave facet,
 *                          no macro-elements: violates Hypothesis 1) |
 *                          nts (node-to-segment / node-to-face
 *                          collocation): p0 and nts for comparisons  lac
 *     strategy             auto | dense | schur | augmented | split |
 *                          saddle | petsc: how each active set's
 *                          system is solved (solve/lac_strategy.h) auto
 *     max_iterations       active-set iterations at most          50
 *     gap_bound            length added to the pairing distance (one
 *                          facet size) for curved bodies           0
 *     interference         delta >= 0: a shrink fit drawn with matching
 *                          surfaces, every gap of the pair is g0 - delta
 *                          (contact/lac_contact.h)               0
 *     hex_cut              auto | pyramids | six: the cut of a hexahedron
 *                          under a slave face (contact/lac_refine.h)  auto
 *   [exact]                analytic solution for errors and `exact` data
 *                          (the table of lac_exact.c)
 *     solution             thick_sphere (axisymmetric, 3d: sphere a < R < b
 *                          under inner pressure p) | thick_cylinder (plane
 *                          strain, 3d with uz = 0: cylinder a < r < b)
 *     a b p E nu           inner and outer radius, inner pressure, Young's
 *                          modulus, Poisson's ratio   (all required)
 *   [steps]                load steps: the load factor t goes to `start`
 *                          in one step (if start > 0), then to `end` in n
 *                          equal steps; loads and ramped Dirichlet values
 *                          are t times theirs (large deformation), or each
 *                          section's value times its f(t) (small strain,
 *                          with [contact]: one loop of Algorithm 1 per
 *                          step, run/lac_run_steps.h)
 *     n                    number of equal steps >= 1          1
 *     start                load factor of the first step, in [0, end)   0
 *     end                  load factor of the last step > 0 (large
 *                          deformation: 1)                     1
 *     tol                  Newton tolerance > 0 (residual, gaps; large
 *                          deformation only)                   1e-8
 *     maxit                Newton iterations per step, 1..1000 (large
 *                          deformation only)                   25
 *     monitor              node group (a physical point): its displacement
 *                          at every step goes to the curve CSV  (none)
 *     curve                file name of the per-step CSV    curve.csv
 *     vtu_every            K >= 0: step_NNN.vtu after every K-th step and
 *                          the last, listed in steps.pvd (0: none)   0
 *     tangent              consistent | frozen: the Newton step with the
 *                          derivatives of the contact terms, or without
 *                          (frozen geometry; large deformation only)
 *                                                             consistent
 *   [output]
 *     vtu                  yes | no: solution.vtu (and contact.vtu)  yes
 *     csv                  yes | no: nodes.csv        yes
 *     matrix               yes | no: K.mtx (Matrix Market, stiffness before
 *                          the Dirichlet conditions)  no
 *     vtu_format           binary | ascii: VTU arrays as appended raw
 *                          bytes or as text (io/lac_vtu.h)   binary
 *     reactions            yes | no: reaction.NAME = Rx Ry [Rz] in the
 *                          summary, the force of the supports of every
 *                          [dirichlet] section (run/lac_run_reaction.h)  no
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
#include "io/lac_scene_query.h"
#include "io/lac_scene_types.h"

/* Read the scene file `path`, apply the nset overrides "KEY=VALUE" and
 * check everything that can be checked without the mesh (types, ranges,
 * enums, required keys, conflicts, the mesh file exists).  Errors are one
 * line: "PATH:LINE: [section] key = 'value': what is wrong". */
int lac_scene_read (const char *path, size_t nset, const char *const *set,
                    lac_scene **out);
/* The same from a string; `path` is used for messages and relative paths. */
int lac_scene_read_string (const char *text, const char *path, size_t nset,
                           const char *const *set, lac_scene **out);
/* The same from the len bytes of text, which may hold anything (a NUL
 * byte is an error with its line, as in a file). */
int lac_scene_read_buffer (const char *text, size_t len, const char *path,
                           size_t nset, const char *const *set,
                           lac_scene **out);
void lac_scene_free (lac_scene *sc);    /* NULL allowed */

#endif /* LAC_SCENE_H */
