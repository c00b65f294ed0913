/* lac_file.c -- the files lac writes (see lac_file.h) */
#include "base/lac_file.h"

#include <errno.h>
#include <string.h>
#include "base/lac_status.h"

int
lac_file_create (const char *path, const char *mode, FILE **f)
{
  if (!(*f = fopen (path, mode)))
    LAC_ERROR (lac_status_errno (errno), "cannot create '%s' (%s)", path,
               strerror (errno));
  return LAC_SUCCESS;
}

/* A write that failed before the close set the stream's error flag; its
 * errno may have been overwritten since, and fclose, which writes what
 * the buffer still holds, usually fails again with the reason. */
int
lac_file_close (FILE *f, const char *path)
{
  int bad = ferror (f), e;
  errno = 0;
  if (fclose (f) == 0 && !bad)
    return LAC_SUCCESS;
  e = errno;
  LAC_ERROR (e ? lac_status_errno (e) : LAC_EIO, "cannot write '%s' (%s)",
             path, e ? strerror (e) : "a write failed");
}
