/* lac_blas.h -- how many threads the BLAS may use
 *
 * The supernodal Cholesky factorization (CHOLMOD) and the LU (UMFPACK)
 * spend their time in dense BLAS-3 kernels, which OpenBLAS runs on every
 * core.  Everything else (the forward and back substitutions of the
 * conjugate gradients, one right-hand side at a time) calls BLAS-2
 * kernels on small blocks, where the extra threads only wake up, spin
 * (sched_yield) and wait: lac asks for every core around a
 * factorization and for one thread otherwise.  With another BLAS (the
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

/* Before a factorization: the BLAS may use every core. */
void lac_blas_parallel (void);
/* After it: one thread. */
void lac_blas_serial (void);
/* Is the address space limited (RLIMIT_AS)?  See above. */
int lac_blas_limited (void);

#endif /* LAC_BLAS_H */
