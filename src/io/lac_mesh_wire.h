/* lac_mesh_wire.h -- a mesh, or why there is none, as a byte stream [LAC §2]
 *
 * The gmsh reader runs in a child process (lac_mesh_child.h); what it
 * found crosses back through a pipe as one stream: a magic word, the
 * reader's status and message, then (status 0) the mesh of fem/lac_mesh.h
 * array by array, and a trailer.  Both ends are the same program on the
 * same machine, so numbers travel in the machine's own layout; the reader
 * side still trusts nothing: every count is checked against the bytes that
 * remain before anything is allocated, and the caller (lac_mesh_read)
 * passes the mesh to lac_mesh_validate (fem/lac_mesh_check.h) before it
 * reads a single index.  A stream cut short (the child died while
 * writing) is an error, never a smaller mesh.
 */
#ifndef LAC_MESH_WIRE_H
#define LAC_MESH_WIRE_H

#include <stddef.h>
#include "fem/lac_mesh.h"

/* Child side: write status, msg (may be NULL) and, if status is
 * LAC_SUCCESS, the mesh m to the file descriptor fd.  Returns 0, or -1 if
 * a write failed (errno set). */
int lac_mesh_wire_write (int fd, int status, const char *msg,
                         const lac_mesh *m);

/* Parent side: decode the len bytes of buf.  On LAC_SUCCESS the stream was
 * whole: *status is the child's status, msg (msgsize bytes) its message,
 * *out the mesh (NULL unless *status is LAC_SUCCESS; the caller frees it).
 * LAC_EIO (message set): the stream is cut short or malformed; LAC_ENOMEM.
 * The arrays of the mesh are as they came: validate them before use. */
int lac_mesh_wire_read (const void *buf, size_t len, int *status, char *msg,
                        size_t msgsize, lac_mesh **out);

#endif /* LAC_MESH_WIRE_H */
