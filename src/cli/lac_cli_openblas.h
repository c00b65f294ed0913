/* lac_cli_openblas.h -- what OpenBLAS reads from the environment when it
 *                       is loaded: its kernels and its workers' spin
 *
 * OpenBLAS (the BLAS of Debian's libopenblas0-pthread) makes two choices
 * before main, from environment variables, that lac corrects when the
 * user left them alone:
 *
 * 1. Its kernels (OPENBLAS_CORETYPE).  OpenBLAS carries kernels for many
 *    CPUs and picks one set by the CPU's model number.  Before 0.3.25
 *    (Debian 12 ships 0.3.21) a model it does not know -- any CPU newer
 *    than the library -- gets its oldest x86-64 kernels, "Prescott"
 *    (SSE3), whatever instructions the CPU has (fixed upstream in
 *    OpenBLAS pull request 4268).  The supernodal Cholesky factorization
 *    spends its time in dgemm, and the Prescott dgemm runs at a fraction
 *    of the AVX2 or AVX-512 one.  When OpenBLAS reports "Prescott" and
 *    the CPU has AVX-512 (F, DQ, BW, VL) or AVX2 with FMA, lac asks for
 *    "SkylakeX" or "Haswell".
 *
 * 2. How long a worker thread spins for more work before it sleeps
 *    (OPENBLAS_THREAD_TIMEOUT, a power of two of CPU cycles; 2^28, about
 *    0.1 s, by default).  lac hands the BLAS both cores around a
 *    factorization and each solve with a factor (linalg/lac_blas.h), and
 *    between them runs its own two threads (the assembly, the pairing,
 *    the products of GMRES): a worker that spins 0.1 s after each solve
 *    takes a core from them.  LAC_OPENBLAS_SPIN = 16 (2^16 cycles, tens
 *    of microseconds) lets it sleep at once; the workers of a
 *    factorization wake for each of its products all the same.
 *
 * So, unless the variable is set, lac_cli_fit_openblas sets what is to
 * be set (the spin only when OpenBLAS runs more than one thread) and
 * executes lac again (/proc/self/exe, same arguments), as lac_cli_limits.h
 * does for the threads.  A variable set by the user is kept:
 * OPENBLAS_CORETYPE=Prescott runs the old kernels.  Under valgrind (which
 * would lose the process at the exec) and with another BLAS it does
 * nothing.  Chapter 13 measures both.
 */
#ifndef LAC_CLI_OPENBLAS_H
#define LAC_CLI_OPENBLAS_H

/* log2 of the cycles an idle OpenBLAS worker spins (see above). */
#define LAC_OPENBLAS_SPIN "16"

/* The OPENBLAS_CORETYPE that fits this CPU better than OpenBLAS's own
 * choice, or NULL (another BLAS, no better kernels, or the user chose). */
const char *lac_cli_better_kernels (void);

/* See above: returns only if nothing is to be done or the exec failed
 * (then the run goes on with what OpenBLAS chose). */
void lac_cli_fit_openblas (char **argv);

/* OpenBLAS's configuration line (version, kernels), or NULL with
 * another BLAS: for lac --version. */
const char *lac_cli_blas_config (void);

#endif /* LAC_CLI_OPENBLAS_H */
