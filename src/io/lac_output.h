/* lac_output.h -- result files: VTU for ParaView, CSV tables, summaries
 *
 * VTU (io/lac_vtu.h): one XML UnstructuredGrid piece, binary (appended
 * raw) unless vtu_ascii asks for text; points always have three
 * coordinates; quadratic cells are written as VTK quadratic cells (cell
 * type and node order from lac_refelem's vtk_type and vtk_perm).  Point
 * data: displacement (3 components), the exact displacement when there is
 * one, the stress components (one array each) and von Mises; cell data: the
 * body index.  CSV: one row per node (coordinates, displacement, stress,
 * von Mises).  Summary: "name = value" lines.
 *
 * The files of one run are written through a batch (lac_output_batch.h),
 * which publishes them together or not at all.  A writer that fails
 * (a full disk) says so: every write is checked when the file is closed.
 *
 * Ownership: the fields are borrowed.
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
  int vtu_ascii;            /* 1: ASCII VTU, 0: binary (the default)  */
} lac_output_fields;

/* Names of the stress components of a model ("xx", "rr", ...), ns of them. */
const char *const *lac_output_stress_names (lac_model model);

/* write (to the given path) */
int lac_output_vtu (const char *path, const lac_output_fields *f);
int lac_output_csv (const char *path, const lac_output_fields *f);
int lac_output_summary (const char *path, size_t n, const char *const *key,
                        const char *const *val);

#endif /* LAC_OUTPUT_H */
