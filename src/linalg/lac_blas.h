/* lac_blas.h -- how many threads the BLAS may use
 *
 * The supernodal Cholesky factorization (CHOLMOD) and the LU (UMFPACK)
 * spend their time in dense BLAS-3 kernels, which OpenBLAS runs on every
 * core; a solve with the factor reads it once forward and once back, in
 * matrix-vector products on its supernodes, and two cores read a factor
 * larger than the caches faster than one (0.20 -> 0.14 s on the fine
 * ring's 1.3 GB factor).  lac asks for every core around a
 * factorization and a solve (linalg/lac_solver.c) and for one thread
 * otherwise, so that OpenBLAS's worker is idle while lac's own two
 * threads work (linalg/lac_tasks.h).  An idle worker sleeps at once only
 * if OpenBLAS was told so (cli/lac_cli_openblas.h: by default it spins
 * 0.1 s, and takes a core from lac's threads).  With another BLAS (the
 * reference libblas of a plain Debian install) both calls do nothing.
 *
 * Under an address-space limit (ulimit -v) every thread that calls
 * OpenBLAS, its own or lac's, needs a 128 MB buffer of its own, and
 * OpenBLAS 0.3.21 waits forever for one the limit refuses
 * (cli/lac_cli_limits.h): then lac_blas_parallel does nothing, and
 * lac_tasks_pair runs its two tasks one after the other.
 * Chapter 07 has the measurement.
 */
#ifndef LAC_BLAS_H
#define LAC_BLAS_H

/* Before a factorization or a solve: the BLAS may use every core. */
void lac_blas_parallel (void);
/* After it: one thread. */
void lac_blas_serial (void);
/* Is the address space limited (RLIMIT_AS)?  See above. */
int lac_blas_limited (void);

#endif /* LAC_BLAS_H */
