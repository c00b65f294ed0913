/* lac_mesh_geo_check.h -- the counts a .geo script writes as numbers,
 * checked before gmsh sees them                                  [LAC §2]
 *
 * gmsh 4.8 takes the number of nodes of a transfinite curve
 * (Transfinite Curve {...} = N) as (N > 2) ? (int) N : 2: a count above
 * 2^31 - 1 (3e9), nan, a fraction or one below 2 becomes another count
 * without a word, and a mesh of 4 nodes is solved as if it were the
 * one asked for.  lac_geo_check reads the script as text (comments and
 * strings skipped) and checks each such count that is written as a
 * number: an integer from 2 to 2147483647.  A count computed by the
 * script (2 * n + 1) is not evaluated here; the numbers it comes from
 * are checked by lac_mesh_opts.h when they come from the scene.
 *
 * Errors: "'FILE': line 12: Transfinite Curve = 3e9: ..." (LAC_EINVAL).
 */
#ifndef LAC_MESH_GEO_CHECK_H
#define LAC_MESH_GEO_CHECK_H

#include <stddef.h>

/* LAC_SUCCESS or LAC_EINVAL with a message naming the line. */
int lac_geo_check_text (const char *path, const char *text, size_t len);

/* The same on the file (read whole, at most max_bytes: base/lac_input.h). */
int lac_geo_check (const char *path, double max_bytes);

#endif /* LAC_MESH_GEO_CHECK_H */
