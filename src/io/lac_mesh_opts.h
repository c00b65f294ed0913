/* lac_mesh_opts.h -- the options of a mesh read                  [LAC §2]
 *
 * What lac_mesh_read (lac_mesh_gmsh.h) is asked to do with a .msh or .geo
 * file, in a header of its own so that the parts of the reader that run in
 * the child process (lac_mesh_gmsh_session.h, lac_mesh_gmsh_reader.h) see
 * the options without seeing the driver; lac_mesh_opts.c checks the
 * numbers a .geo receives, for the scene (which names its line) and for
 * the session (which passes them to gmsh).
 */
#ifndef LAC_MESH_OPTS_H
#define LAC_MESH_OPTS_H

#include <stddef.h>

#define LAC_MESH_MAX_NUMBERS 16
/* The longest NAME of a number (gmsh 4.8 aborts on a name of 1,100
 * letters, chapter 01, bad-input.md). */
#define LAC_MESH_NUMBER_NAME 63
/* The largest magnitude of a number: gmsh converts the counts a .geo
 * computes (Transfinite Curve {...} = n) to 32-bit integers, and a count
 * beyond them (or nan) silently becomes 2. */
#define LAC_MESH_NUMBER_MAX 2147483647.0

/* Bytes a run of lac needs before any mesh (its libraries, buffers): the
 * constant term of the estimate (lac_mesh_gmsh_estimate.h), and the
 * smallest --max-memory (below it gmsh cannot even start). */
#define LAC_MESH_RUN_BYTES_MIN 1e8

/* The largest memory limit (--max-memory): 1e18 bytes, above the address
 * space of any machine lac runs on (x86-64 maps at most 2^57 bytes) and
 * within the 64 bits of the kernel's limits (setrlimit): a larger value,
 * cast to them, became a limit of a few bytes, and gmsh "failed to
 * initialize". */
#define LAC_MESH_MEMORY_MAX 1e18

/* How the run will solve, for the memory part of a .geo's size estimate
 * (lac_mesh_gmsh_estimate.h): a sparse Cholesky factor (cholmod, and the
 * strategies schur, augmented, split), a sparse LU (umfpack, saddle),
 * a dense LU, or no factorization (petsc: a sparse matrix, a multigrid
 * hierarchy and a few vectors); or what `lac infsup` does instead of a
 * solve (contact/lac_infsup.h): the Cholesky factor of its norm matrix A
 * (the H1 Gram matrix, or K with --norm energy) and A^-1 C by blocks,
 * the dense path; with the sparse path also the LU factor of the
 * saddle-point matrix [A C; C^T 0]. */
typedef enum
{
  LAC_MESH_SOLVE_CHOLESKY, LAC_MESH_SOLVE_LU, LAC_MESH_SOLVE_DENSE,
  LAC_MESH_SOLVE_ITERATIVE,
  LAC_MESH_SOLVE_INFSUP, LAC_MESH_SOLVE_INFSUP_SPARSE,
  LAC_MESH_SOLVE_INFSUP_ENERGY, LAC_MESH_SOLVE_INFSUP_ENERGY_SPARSE,
  LAC_MESH_NSOLVES
} lac_mesh_solve;

/* Options for reading or meshing (.geo) through gmsh. */
typedef struct lac_mesh_opts
{
  double size;         /* characteristic length factor (.geo); 0: as is  */
  int order;           /* 1 or 2 (.geo); 0: as in the file               */
  int serendipity;     /* quad8/hex20 instead of quad9/hex27             */
  int recombine;       /* quadrangles / hexahedra from .geo              */
  int level;           /* exported to the .geo as the number `level`     */
  const char *numbers; /* borrowed, NULL: more numbers for the .geo,
                          "NAME=VALUE" pairs separated by blanks or
                          commas (at most LAC_MESH_MAX_NUMBERS)          */
  int flip_inverted;   /* 1: flip cells with det J < 0; 0: reject them   */
  double max_memory;   /* bytes gmsh may use, and a .geo's estimated run
                          may need; 0: lac_mesh_default_memory ()        */
  double max_seconds;  /* wall-clock and CPU seconds for gmsh; 0:
                          LAC_MESH_CHILD_SECONDS                         */
  int element;         /* the scene's cells (lac_elem_type of a 2D or 3D
                          cell) for the estimate; anything else: from
                          recombine, order and serendipity             */
  int solve;           /* lac_mesh_solve, for the estimate             */
  int else_iterative;  /* 1: a mesh that does not fit with `solve` is
                          made if it fits with an iterative solve (the
                          strategy auto then takes petsc, chapter 13)  */
} lac_mesh_opts;

/* One NAME=VALUE of lac_mesh_opts.numbers. */
typedef struct lac_mesh_number
{
  char name[LAC_MESH_NUMBER_NAME + 1];
  double value;
} lac_mesh_number;

/* Split numbers ("n=28, m=3": pairs separated by blanks or commas) into
 * out[0 .. LAC_MESH_MAX_NUMBERS-1]: each NAME a .geo identifier (a letter
 * or _, then letters, digits, _; at most LAC_MESH_NUMBER_NAME; not
 * `level`, which the option level sets; not twice), each VALUE a number
 * (base/lac_number.h) of magnitude at most LAC_MESH_NUMBER_MAX.  Returns
 * the count (0 for NULL or blanks), or -1 with the reason in why (naming
 * the pair). */
int lac_mesh_numbers_split (const char *numbers, lac_mesh_number *out,
                            char *why, size_t size);

#endif /* LAC_MESH_OPTS_H */
