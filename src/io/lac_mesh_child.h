/* lac_mesh_child.h -- a mesh reader run in a child process, with limits
 *                                                                 [LAC §2]
 *
 * gmsh is a large C++ library that trusts its input: a malformed .msh file
 * can make it crash, abort on an assertion, call exit() from its lexer or
 * grow until the machine runs out of memory, all inside the process that
 * called it.  lac_mesh_child_run runs a reader in a child process (fork)
 * under limits:
 *
 *   - memory: the child may grow its address space by max_memory bytes
 *     (RLIMIT_AS; not under AddressSanitizer, whose shadow memory would
 *     hit it at once);
 *   - time: max_seconds of CPU (RLIMIT_CPU) and of wall clock (the parent
 *     kills the child);
 *   - no core dumps, stdin from /dev/null, stdout and stderr into a pipe
 *     that the parent keeps the end of (gmsh's own words about a failure,
 *     never shown raw), no other descriptor of lac's but the answer's,
 *     SIGINT and SIGTERM back to their defaults, and the child is killed
 *     if the parent dies;
 *   - gmsh's session shuts itself in a sandbox (lac_mesh_sandbox.h): no
 *     programs, no writes;
 *
 * and the mesh comes back through a pipe (lac_mesh_wire.h).  Whatever
 * happens in the child becomes a status and one message in the caller,
 * which names the limit it hit: "gmsh could not read 'FILE': killed by
 * signal 11 (Segmentation fault); the file is malformed or truncated",
 * "... out of memory (limit 5.9 GB, --max-memory)" (also when the reader
 * failed without a word within reach of the limit: gmsh swallows
 * std::bad_alloc), "... its stack overflowed (stack limit 64 KiB, ulimit
 * -s)", "... within the time limit of 3600 s", "... the script tried to
 * write 'x.msh' (openat): writes outside lac's output are not allowed".
 *
 * Only the child calls _exit, after it has written its answer: the
 * process that called lac_mesh_child_run never exits here.
 */
#ifndef LAC_MESH_CHILD_H
#define LAC_MESH_CHILD_H

#include "fem/lac_mesh.h"

/* Wall-clock and CPU seconds a read may take when the caller says 0. */
#define LAC_MESH_CHILD_SECONDS 3600.0

/* A reader: fills *out (LAC_SUCCESS) or returns a status with a message. */
typedef int (*lac_mesh_child_fn) (void *arg, lac_mesh **out);

/* Run fn (arg) in a child process and return its mesh in *out.
 *   verb         "read" or "mesh", for messages ("gmsh could not read")
 *   path         the file, for messages
 *   max_memory   bytes the child may add; <= 0: lac_mesh_default_memory ()
 *   max_seconds  <= 0: LAC_MESH_CHILD_SECONDS
 * Returns the reader's status and message, or LAC_EIO / LAC_EDEP (the
 * child died, exited, or its answer was cut short), LAC_ENOMEM (out of
 * memory in the child or here), LAC_EMAXITER (time limit). */
int lac_mesh_child_run (const char *verb, const char *path,
                        lac_mesh_child_fn fn, void *arg, double max_memory,
                        double max_seconds, lac_mesh **out);

/* The default memory limit: 80 % of the machine's physical memory (or of
 * the process's RLIMIT_AS, if lower), in bytes. */
double lac_mesh_default_memory (void);

#endif /* LAC_MESH_CHILD_H */
