/* lac_cli_limits.h -- an address-space limit (ulimit -v) and OpenBLAS
 *
 * OpenBLAS before 0.3.30 (Debian 12 ships 0.3.21) retries forever when
 * it cannot map the 128 MB work buffer of a thread (fixed upstream in
 * OpenBLAS pull request 5303).  Its pthread build starts a worker per
 * core when the library is loaded, before main; under `ulimit -v` the
 * worker can spin in that retry from the start, and then fork() (gmsh's
 * child: the pre-fork handler joins the workers) and exit() (the
 * library's destructor joins them too) hang -- `lac --version` included.
 *
 * So when the address space is limited, lac_cli_fit_limits makes the
 * process fit OpenBLAS's needs or refuses at once:
 *
 *   1. unless OPENBLAS_NUM_THREADS is set, it sets it to 1 and executes
 *      lac again (/proc/self/exe, same arguments): the workers and their
 *      buffers are gone, no thread is left to join;
 *   2. it checks that the limit leaves room for the one buffer of the
 *      main thread (LAC_CLI_BLAS_BUFFER, 128 MB and a page, measured)
 *      above what the process holds (its libraries: about 430 MB), else
 *      prints what to raise the limit to;
 *   3. it makes OpenBLAS map that buffer now, with one small product:
 *      later, when the run has taken the rest of the limit, a BLAS call
 *      finds its buffer and an allocation that fails is the plain "out of
 *      memory" of lac instead of a hang.
 *
 * Without a limit, or without OpenBLAS (the reference BLAS), it does
 * nothing.
 */
#ifndef LAC_CLI_LIMITS_H
#define LAC_CLI_LIMITS_H

/* The work buffer OpenBLAS 0.3.21 maps per thread, with its margin. */
#define LAC_CLI_BLAS_BUFFER (136.0 * 1024 * 1024)

/* See above; compute 0 (lac --help, --version): step 1 only.  Returns 0,
 * or LAC_CLI_FAILURE after printing why; then the caller must end with
 * _exit: an OpenBLAS worker that spins (a user's OPENBLAS_NUM_THREADS
 * above 1) would hang exit(). */
int lac_cli_fit_limits (char **argv, int compute);

#endif /* LAC_CLI_LIMITS_H */
