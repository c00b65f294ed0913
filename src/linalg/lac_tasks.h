/* lac_tasks.h -- two independent tasks at the same time, one core each
 *
 * The split solve (solve/lac_split.h) factorizes two matrices that share
 * nothing: the bodies held by their Dirichlet conditions and those held
 * by contact alone.  A supernodal Cholesky factorization of a 3D mesh
 * spends its time on many medium-sized fronts, where a second BLAS thread
 * gains little; two factorizations side by side, one core each, use both
 * cores better.  Measured on the 3D patch test at 141k dofs (chapter 07):
 * the two factors one after the other, two BLAS threads each, 4.5 s; at
 * the same time, one thread each, 2.7 s.
 *
 * lac_tasks_pair runs a in the calling thread and b in a POSIX thread,
 * with the BLAS on one thread (linalg/lac_blas.h) and the OpenMP loops
 * inside the libraries (CHOLMOD's) on one thread, so that the two tasks
 * do not crowd four threads and more onto two cores.  If no thread can be
 * started, or the address space is limited (each thread would need a
 * BLAS buffer of its own, lac_blas.h), b runs after a.  A task that asks
 * for a pair of its own (lac_hyper_assemble_pattern, fem/lac_hyper.h,
 * called from a task) gets its two tasks one after the other, in its
 * thread: never more threads than cores.
 */
#ifndef LAC_TASKS_H
#define LAC_TASKS_H

/* A task: returns a status (base/lac_status.h) and sets its message. */
typedef int lac_task (void *ctx);

/* a(ca) and b(cb) at the same time.  Returns a's status if it failed,
 * else b's; the message of the task whose status is returned is the
 * caller's on return.  The tasks must share no mutable data. */
int lac_tasks_pair (lac_task *a, void *ca, lac_task *b, void *cb);

#endif /* LAC_TASKS_H */
