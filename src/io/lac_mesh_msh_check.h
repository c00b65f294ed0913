/* lac_mesh_msh_check.h -- an ASCII .msh file read line by line before
 * gmsh reads it                                                   [LAC §2]
 *
 * gmsh reads the numbers of a .msh file as a stream: an element line of
 * MSH 2.2 with one node too few takes the first number of the next line
 * as its last node, and the mesh is silently wrong (a tri3 with two nodes
 * gave 33 % more displacement); a count of 10^12 nodes in a 57-byte file
 * makes it reserve gigabytes.  lac_msh_check reads the file as lines and
 * checks the structure gmsh relies on:
 *
 *   - a $MeshFormat header first, version 2.x or 4.1 (binary files: the
 *     header only, the rest is left to gmsh in its child process);
 *   - every section closed by its $End line;
 *   - $Nodes and $Elements (2.2: one line per node or element; 4.1: entity
 *     blocks): each count matches the lines that follow, each line has
 *     exactly the numbers it must have -- an element line the node count
 *     of its type, for the types of gmsh 1 to 31 -- and the numbers are
 *     numbers;
 *   - no NUL byte, no line without a line feed before the end.
 *
 * Errors: "'FILE': not a valid mesh file: line N: element 7 (type 2,
 * tri3) has 4 numbers after its tags, expected 3".
 */
#ifndef LAC_MESH_MSH_CHECK_H
#define LAC_MESH_MSH_CHECK_H

#include <stddef.h>

/* The elements of a file by gmsh type (1..31) and by the dimension of
 * their type: what gmsh must give back (gmsh 4.8 drops a tri6 element
 * from a surface of tri3 elements without a word; lac_mesh_read compares
 * the counts).  All zero for a binary file. */
#define LAC_MSH_NTYPES 32
typedef struct lac_msh_counts
{
  size_t by_type[LAC_MSH_NTYPES];
  size_t by_dim[4];
} lac_msh_counts;

/* LAC_SUCCESS, LAC_EIO (cannot read, not a regular file or larger than
 * max_bytes, or not a valid mesh file: the message names the line) or
 * LAC_ENOMEM.  The file is read whole (base/lac_input.h), so max_bytes
 * (--max-memory) bounds what lac's own process takes for it.  counts
 * (may be NULL) receives the elements of the file. */
int lac_msh_check (const char *path, double max_bytes,
                   lac_msh_counts *counts);

/* The dimension of gmsh element type t (0..3), -1 if lac does not know
 * it; its name ("tri6"), "?" if none. */
int lac_msh_type_dim (int t);
const char *lac_msh_type_name (int t);

/* The same on the len bytes of text (for tests and fuzzing). */
int lac_msh_check_text (const char *path, const char *text, size_t len);

#endif /* LAC_MESH_MSH_CHECK_H */
