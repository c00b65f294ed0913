/* lac_input.h -- the files lac reads: regular files of bounded size
 *
 * A scene or a mesh named by a user may be anything a path can name: a
 * directory, a named pipe without a writer (opening it blocks forever), a
 * device (/dev/zero never ends), a symbolic link to one of those, a file
 * of gigabytes.  Read as a stream, each of them hung lac or grew it
 * without bound.  Here a path is checked for what it is before a byte is
 * read: stat, then open with O_NONBLOCK (a named pipe put in its place in
 * between does not block either), then fstat of what was opened: a
 * regular file, the one stat saw, of at most max_bytes.  Then it is read
 * whole, into one buffer allocated once (linear time, bounded memory).
 *
 * Messages are "FILE: what is wrong" (lac_error_place): "x.msh: a named
 * pipe, not a regular file", "big.msh: 12 GB, more than the limit of 10 GB
 * (--max-memory)", "x.scene: cannot open (No such file or
 * directory)".  Statuses: LAC_EIO (not found, not a regular file, too
 * large, unreadable), LAC_ENOMEM.
 */
#ifndef LAC_INPUT_H
#define LAC_INPUT_H

#include <stddef.h>

/* path names a regular file of at most max_bytes (limit: the name of
 * that limit for the message, e.g. "--max-memory") that can be opened
 * for reading; *size (may be NULL) its size. */
int lac_input_check (const char *path, double max_bytes, const char *limit,
                     size_t *size);

/* lac_input_check, then the whole file into *text (lac_malloc'd, len
 * bytes and a terminating NUL; free with lac_free). */
int lac_input_read (const char *path, double max_bytes, const char *limit,
                    char **text, size_t *len);

#endif /* LAC_INPUT_H */
