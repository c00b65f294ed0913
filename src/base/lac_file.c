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

int
lac_file_close (FILE *f, const char *path)
{
  int bad = ferror (f);
  if (fclose (f) != 0 || bad)
    LAC_ERROR (lac_status_errno (errno), "cannot write '%s' (%s)", path,
               strerror (errno));
  return LAC_SUCCESS;
}
