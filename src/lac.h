/* lac.h -- lac as a library: the headers of its API, in one include
 *                                                          [LAC §2-§5]
 *
 * A program of one's own (an exercise outside the tree, a new element, a
 * study in C) includes this header and builds against the installed
 * library (README.md, "Using lac as a library"):
 *
 *   #include "lac.h"
 *   cc prog.c $(pkg-config --cflags --libs lac)
 *
 * The headers below are the API: the modules of the paper, each one the
 * contract of its module and explained by a chapter; their functions keep
 * their meaning from one version of lac to the next (a change that breaks
 * a program that uses them raises the number of liblac.so.N).  Every
 * other header of src/ is installed too, so that these compile and so
 * that a reader can go one level down; those may change with the code.
 * In the tree, with -Isrc, the same #include "lac.h" works.
 */
#ifndef LAC_H
#define LAC_H

/* status codes and the message of the last error; allocation
 * (lac_malloc, lac_free) (chapter 01) */
#include "base/lac_status.h"
#include "base/lac_mem.h"

/* triplets, CSC matrices and the direct solvers (chapter 07) */
#include "linalg/lac_linalg.h"

/* reference elements, quadrature, meshes, materials, assembly, stresses,
 * errors and exact solutions, hyperelasticity (chapters 01, 02, 10) */
#include "fem/lac_spaces.h"
#include "fem/lac_quadrature.h"
#include "fem/lac_mesh.h"
#include "fem/lac_material.h"
#include "fem/lac_assembly.h"
#include "fem/lac_post.h"
#include "fem/lac_exact.h"
#include "fem/lac_hyper.h"

/* the macro-mesh, pairing, admissibility, the LAC matrices, several
 * pairs, a rigid obstacle, the inf-sup constant (chapters 03-06, 11) */
#include "contact/lac_macromesh.h"
#include "contact/lac_refine.h"
#include "contact/lac_pairing.h"
#include "contact/lac_admissibility.h"
#include "contact/lac_contact.h"
#include "contact/lac_assembly_lac.h"
#include "contact/lac_contact_set.h"
#include "contact/lac_obstacle.h"
#include "contact/lac_infsup.h"

/* Algorithm 1: the strategies of one active set, the contact model it
 * asks for, its models of small and of large deformations (07, 10) */
#include "solve/lac_strategy.h"
#include "solve/lac_contact_model.h"
#include "solve/lac_newton.h"
#include "solve/lac_linear_model.h"
#include "solve/lac_nonlinear.h"

/* scene files, gmsh meshes, result files (chapter 01) */
#include "io/lac_scene.h"
#include "io/lac_mesh_gmsh.h"
#include "io/lac_output.h"
#include "io/lac_vtu.h"

/* pictures of a result (chapter 08) */
#include "render/lac_render.h"

/* one run of a scene, stage by stage, as lac run does it (chapter 01) */
#include "run/lac_run.h"
#include "run/lac_run_scene.h"

#endif /* LAC_H */
