/* lac_file.h -- the files lac writes: opened and closed with a message
 *
 * A result file is created by lac_file_create and closed by
 * lac_file_close, which also reports a write that failed on the way (a
 * full disk shows only at the end, when the buffers are flushed): each
 * message names the file and the reason (strerror), the status is that
 * of errno (lac_status_errno).
 */
#ifndef LAC_FILE_H
#define LAC_FILE_H

#include <stdio.h>

/* *f = fopen (path, mode) for writing ("w" or "wb"); LAC_SUCCESS, or the
 * status of errno with the message "cannot create 'path' (reason)". */
int lac_file_create (const char *path, const char *mode, FILE **f);
/* fclose (f); LAC_SUCCESS, or the status of errno with the message
 * "cannot write 'path' (reason)" if the close or any earlier write of f
 * failed. */
int lac_file_close (FILE *f, const char *path);

#endif /* LAC_FILE_H */
