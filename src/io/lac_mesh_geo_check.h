/* lac_mesh_geo_check.h -- the counts a .geo script writes as numbers,
 * checked before gmsh sees them                                  [LAC §2]
 *
 * gmsh 4.8 takes the number of nodes of a transfinite curve
 * (Transfinite Curve {...} = N) as (N > 2) ? (int) N : 2: a count above
 * 2^31 - 1 (3e9), nan, a fraction or one below 2 becomes another count
 * without a word, and a mesh of 4 nodes is solved as if it were the
 * one asked for.  lac_geo_check reads the script as text (comments and
 * strings skipped) and checks each such count that is written as a
 * number: an integer from 2 to 2147483647.  A count the script computes
 * (2 * n + 1) is evaluated where lac can tell its value
 * (lac_mesh_geo_expr.h: arithmetic on numbers, on the scene's numbers
 * and on the script's assignments outside If, For and Macro blocks), and
 * refused when it is not finite or beyond 2147483647 in magnitude
 * (a fraction is gmsh's to truncate, as documented); one lac cannot
 * evaluate is gmsh's alone.
 *
 * Errors: "'FILE': line 12: Transfinite Curve {...} = 3e9: ..." (LAC_EINVAL).
 */
#ifndef LAC_MESH_GEO_CHECK_H
#define LAC_MESH_GEO_CHECK_H

#include <stddef.h>
#include "io/lac_mesh_opts.h"

/* LAC_SUCCESS or LAC_EINVAL with a message naming the line; o (may be
 * NULL: none) gives the numbers the scene passes to the script, `level`
 * and `numbers`. */
int lac_geo_check_text (const char *path, const char *text, size_t len,
                        const lac_mesh_opts *o);

/* The same on the file (read whole, at most o->max_memory bytes:
 * base/lac_input.h). */
int lac_geo_check (const char *path, const lac_mesh_opts *o);

#endif /* LAC_MESH_GEO_CHECK_H */
