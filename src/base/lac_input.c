/* lac_input.c -- the files lac reads (see lac_input.h)
 *
 * Why stat, then open with O_NONBLOCK, then fstat: stat alone leaves a
 * window in which the path can be replaced by a named pipe, and a plain
 * open of a pipe without a writer blocks; O_NONBLOCK makes that open
 * return at once, and fstat then sees what was really opened.  The
 * descriptor goes back to blocking mode for the read (on a regular file
 * the flag changes nothing, but it is the file's, not ours, to keep).
 */
#include "base/lac_input.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

/* What a file of mode m is, in words, when it is not a regular file. */
static const char *
file_type (mode_t m)
{
  return S_ISDIR (m) ? "a directory" : S_ISFIFO (m) ? "a named pipe"
         : S_ISCHR (m) ? "a character device" : S_ISBLK (m)
         ? "a block device" : S_ISSOCK (m) ? "a socket" : "not a file";
}

/* bytes as "17 bytes", "512 kB", "3.4 MB", "12 GB" (powers of 1000, as
 * --max-memory reads them). */
static void
size_words (char *buf, size_t size, double bytes)
{
  static const char *const unit[] = { "kB", "MB", "GB", "TB" };
  int u = -1;
  while (u < 3 && bytes >= 1000)
    bytes /= 1000, u++;
  if (u < 0)
    snprintf (buf, size, "%.0f bytes", bytes);
  else
    snprintf (buf, size, "%.3g %s", bytes, unit[u]);
}

/* st describes a regular file of at most max_bytes. */
static int
check_stat (const char *path, const struct stat *st, double max_bytes,
            const char *limit)
{
  if (!S_ISREG (st->st_mode))
    return lac_error_place (LAC_EIO, path, "%s, not a regular file",
                            file_type (st->st_mode));
  if ((double) st->st_size > max_bytes)
    {
      char has[32], most[32];
      size_words (has, sizeof has, (double) st->st_size);
      size_words (most, sizeof most, max_bytes);
      return lac_error_place (LAC_EIO, path, "%s, more than the limit of %s "
                              "(%s)", has, most, limit);
    }
  return LAC_SUCCESS;
}

/* Open path for reading, checked as lac_input_check says; *fd, *st. */
static int
open_checked (const char *path, double max_bytes, const char *limit,
              int *fd, struct stat *st)
{
  struct stat before;
  int status, e;
  *fd = -1;
  if (stat (path, &before) != 0)
    return e = errno, lac_error_place (lac_status_errno (e), path, "cannot "
                                       "open (%s)", strerror (e));
  if ((status = check_stat (path, &before, max_bytes, limit)))
    return status;
  if ((*fd = open (path, O_RDONLY | O_NONBLOCK | O_CLOEXEC)) < 0)
    return e = errno, lac_error_place (lac_status_errno (e), path, "cannot "
                                       "open (%s)", strerror (e));
  if (fstat (*fd, st) != 0)
    status = lac_error_place (LAC_EIO, path, "cannot open (%s)",
                              strerror (errno));
  else if (!(status = check_stat (path, st, max_bytes, limit))
           && (st->st_dev != before.st_dev || st->st_ino != before.st_ino))
    status = lac_error_place (LAC_EIO, path, "replaced while it was "
                              "opened");
  if (!status)
    fcntl (*fd, F_SETFL, fcntl (*fd, F_GETFL) & ~O_NONBLOCK);
  if (status)
    close (*fd), *fd = -1;
  return status;
}

int
lac_input_check (const char *path, double max_bytes, const char *limit,
                 size_t *size)
{
  struct stat st;
  int fd, status = open_checked (path, max_bytes, limit, &fd, &st);
  if (status)
    return status;
  if (size)
    *size = (size_t) st.st_size;
  close (fd);
  return LAC_SUCCESS;
}

/* Read the n bytes of fd into buf; one more byte than n is an error (the
 * file grew since fstat). */
static int
read_all (const char *path, int fd, char *buf, size_t n, size_t *len)
{
  char extra;
  ssize_t k;
  *len = 0;
  while (*len < n && (k = read (fd, buf + *len, n - *len)) != 0)
    {
      if (k < 0 && errno == EINTR)
        continue;
      if (k < 0)
        return lac_error_place (lac_status_errno (errno), path, "cannot "
                                "read (%s)", strerror (errno));
      *len += (size_t) k;
    }
  while ((k = read (fd, &extra, 1)) < 0 && errno == EINTR)
    ;
  if (k > 0)
    return lac_error_place (LAC_EIO, path, "grew while it was read");
  buf[*len] = '\0';
  return LAC_SUCCESS;
}

int
lac_input_read (const char *path, double max_bytes, const char *limit,
                char **text, size_t *len)
{
  struct stat st;
  int fd, status = open_checked (path, max_bytes, limit, &fd, &st);
  *text = NULL;
  *len = 0;
  if (status)
    return status;
  if (!(*text = lac_malloc ((size_t) st.st_size + 1)))
    {
      char has[32];
      size_words (has, sizeof has, (double) st.st_size);
      status = lac_error_place (LAC_ENOMEM, path, "reading %s", has);
    }
  else
    status = read_all (path, fd, *text, (size_t) st.st_size, len);
  close (fd);
  if (status)
    {
      lac_free (*text);
      *text = NULL;
    }
  return status;
}
