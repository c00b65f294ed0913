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
 * Chapter 07 has the measurement.
 */
#ifndef LAC_BLAS_H
#define LAC_BLAS_H

/* Before a factorization: the BLAS may use every core. */
void lac_blas_parallel (void);
/* After it: one thread. */
void lac_blas_serial (void);

#endif /* LAC_BLAS_H */
