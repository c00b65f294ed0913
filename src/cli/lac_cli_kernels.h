/* lac_cli_kernels.h -- OpenBLAS's kernels for the CPU it runs on
 *
 * OpenBLAS (the BLAS of Debian's libopenblas0-pthread) carries kernels
 * for many CPUs and picks one set when it is loaded, by the CPU's model
 * number.  Before 0.3.25 (Debian 12 ships 0.3.21) a model it does not
 * know -- any CPU newer than the library -- gets its oldest x86-64
 * kernels, "Prescott" (SSE3), whatever instructions the CPU has (fixed
 * upstream in OpenBLAS pull request 4268).  The supernodal Cholesky
 * factorization spends its time in dgemm, and the Prescott dgemm runs at
 * a fraction of the AVX2 or AVX-512 one (chapter 13, section 4).
 *
 * The choice is made before main, from the environment variable
 * OPENBLAS_CORETYPE.  So when OpenBLAS reports "Prescott", that variable
 * is not set, and the CPU has AVX-512 (F, DQ, BW, VL) or AVX2 with FMA,
 * lac_cli_fit_kernels sets it to the kernels OpenBLAS has for those
 * instructions ("SkylakeX", "Haswell") and executes lac again
 * (/proc/self/exe, same arguments), as lac_cli_limits.h does for the
 * threads.  A variable set by the user is kept: OPENBLAS_CORETYPE=Prescott
 * runs the old kernels.  Under valgrind (which would lose the process at
 * the exec) and with another BLAS it does nothing.
 */
#ifndef LAC_CLI_KERNELS_H
#define LAC_CLI_KERNELS_H

/* The OPENBLAS_CORETYPE that fits this CPU better than OpenBLAS's own
 * choice, or NULL (another BLAS, no better kernels, or the user chose). */
const char *lac_cli_better_kernels (void);

/* See above: returns only if nothing is to be done or the exec failed
 * (then the run goes on with the kernels it has). */
void lac_cli_fit_kernels (char **argv);

/* OpenBLAS's configuration line (version, kernels), or NULL with
 * another BLAS: for lac --version. */
const char *lac_cli_blas_config (void);

#endif /* LAC_CLI_KERNELS_H */
