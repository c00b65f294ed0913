/* lac_run_internal.h -- internal: shared by the lac_run*.c files
 *
 * Not part of the public interface: only lac_run.c (the run, stages mesh
 * to solve), lac_run_rigid.c (the rigid-motion check of the assemble
 * stage), lac_run_post.c (stages post and output), lac_run_contact.c and
 * lac_run_nonlinear.c (the large-deformation stages) include it.
 */
#ifndef LAC_RUN_INTERNAL_H
#define LAC_RUN_INTERNAL_H

#include "fem/lac_exact.h"
#include "io/lac_output.h"
#include "run/lac_run.h"

/* Append "key = value" to the summary (value from printf format). */
int lac_run_summary_add (lac_run *r, const char *key, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));

/* The [exact] solution of the scene, set up for the run's model (kind
 * LAC_EXACT_NONE without [exact]). */
void lac_run_exact (const lac_run *r, lac_exact *e);

/* Every connected body must be fixed against rigid motions by the fixed
 * dofs of d; otherwise LAC_ESING with a message naming the body and the
 * free motion (lac_run_rigid.c). */
int lac_run_check_rigid (lac_run *r, const lac_dirichlet *d);

/* Distinct cell types of the mesh, "tri6" or "tri6+quad8". */
void lac_run_cell_types (const lac_mesh *m, char *buf, size_t size);

/* The non-empty facet group `name` given by key `key` of the [contact]
 * section, or NULL with a message naming the scene line. */
const lac_group *lac_run_contact_group (lac_run *r, const char *key,
                                        const char *name);

/* Seconds on a monotonic clock. */
double lac_run_now (void);

/* The contact part (lac_run_contact.c). */
int lac_run_stage_contact (lac_run *r);
int lac_run_contact_assemble (lac_run *r, const lac_dirichlet *d);
int lac_run_contact_solve (lac_run *r);
int lac_run_contact_post (lac_run *r, const lac_exact *e);
int lac_run_contact_csv (const lac_run *r, const char *path);

/* The large-deformation run (lac_run_nonlinear.c): the stages contact,
 * solve (one load step per call: LAC_CONTINUE until the last), post and
 * output of a scene with [scene] large_deformation = yes. */
int lac_run_nl_contact (lac_run *r);
int lac_run_nl_solve (lac_run *r);
int lac_run_nl_post (lac_run *r);
int lac_run_nl_output (lac_run *r);
void lac_run_nl_free (struct lac_run_nl *nl);   /* NULL allowed */

/* Parts of the output stage shared by the linear and the large-
 * deformation runs (lac_run_post.c): the time_<stage> summary lines; the
 * files solution.vtu and nodes.csv into a batch; summary.txt (last) and
 * the renaming of the batch into place. */
int lac_run_stage_timings (lac_run *r);
int lac_run_write_fields (const lac_run *r, lac_output_batch *b,
                          const lac_output_fields *f);
int lac_run_write_summary (lac_run *r, lac_output_batch *b);

/* Stages 5 and 6 (lac_run_post.c). */
int lac_run_stage_post (lac_run *r);
int lac_run_stage_output (lac_run *r);

#endif /* LAC_RUN_INTERNAL_H */
