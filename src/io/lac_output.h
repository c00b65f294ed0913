/* lac_output.h -- result files: VTU for ParaView, CSV tables, summaries
 *
 * VTU: one XML UnstructuredGrid piece in ASCII; points always have three
 * coordinates; quadratic cells are written as VTK quadratic cells (cell
 * type and node order from lac_refelem's vtk_type and vtk_perm).  Point
 * data: displacement (3 components), the exact displacement when there is
 * one, the stress components (one array each) and von Mises; cell data: the
 * body index.  CSV: one row per node (coordinates, displacement, stress,
 * von Mises).  Summary: "name = value" lines.
 *
 * Files of one run are written as a batch: each under a temporary name in
 * the output directory, renamed to the final names only by
 * lac_output_commit, so a run that fails leaves the files of an earlier
 * run untouched.  Renaming follows the order the files were added, so the
 * summary, added last, is the last to appear.
 *
 * Ownership: the fields are borrowed; a batch is freed with
 * lac_output_batch_free, which removes temporary files not committed.
 */
#ifndef LAC_OUTPUT_H
#define LAC_OUTPUT_H

#include <stddef.h>
#include "fem/lac_material.h"
#include "fem/lac_mesh.h"

/* Nodal fields of one result. */
typedef struct lac_output_fields
{
  const lac_mesh *mesh;     /* borrowed                               */
  lac_model model;
  const double *u;          /* borrowed, nnodes*dim                   */
  const double *u_exact;    /* borrowed, nnodes*dim, or NULL          */
  const double *sigma;      /* borrowed, nnodes*ns, or NULL           */
  const double *vm;         /* borrowed, nnodes, or NULL              */
} lac_output_fields;

/* Names of the stress components of a model ("xx", "rr", ...), ns of them. */
const char *const *lac_output_stress_names (lac_model model);

/* write (to the given path) */
int lac_output_vtu (const char *path, const lac_output_fields *f);
int lac_output_csv (const char *path, const lac_output_fields *f);
int lac_output_summary (const char *path, size_t n, const char *const *key,
                        const char *const *val);

/* batches of files that appear together */
typedef struct lac_output_batch lac_output_batch;

/* Create the directory dir (and its parents) if needed. */
lac_output_batch *lac_output_batch_alloc (const char *dir);
void lac_output_batch_free (lac_output_batch *b);   /* NULL allowed */
/* The temporary path to write the file `name` of the batch to (owned by
 * the batch).  NULL with a message on failure. */
const char *lac_output_batch_add (lac_output_batch *b, const char *name);
/* Rename every temporary file to its final name, in the order added. */
int lac_output_commit (lac_output_batch *b);
/* Final path of the k-th file (after commit: the file's name). */
const char *lac_output_batch_path (const lac_output_batch *b, size_t k);

#endif /* LAC_OUTPUT_H */
