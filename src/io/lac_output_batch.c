/* lac_output_batch.c -- the files of a run appear together
 * (see lac_output_batch.h)
 *
 * Paths: DIR = PARENT/NAME; the batch's files are PARENT/.NAME.lac-new-PID/
 * FILE until the commit; the earlier DIR is PARENT/.NAME.lac-old-PID only
 * on file systems without RENAME_EXCHANGE.  A temporary of another process
 * is stale when kill (pid, 0) says that process does not exist.
 */
#define _GNU_SOURCE            /* renameat2, RENAME_EXCHANGE (glibc 2.28) */
#include "io/lac_output_batch.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

#define NEW ".lac-new-"
#define OLD ".lac-old-"

struct lac_output_batch
{
  char *dir;          /* owned: DIR, as given (no trailing slash)      */
  char *tmp;          /* owned: PARENT/.NAME.lac-new-PID               */
  char *old;          /* owned: PARENT/.NAME.lac-old-PID               */
  size_t n, cap;
  char **final;       /* owned, n: DIR/FILE                            */
  char **path;        /* owned, n: tmp/FILE                            */
  const volatile sig_atomic_t *stop;
  int committed;
};

/* ---------------------------------------------------------------------- */
/* small helpers                                                           */
/* ---------------------------------------------------------------------- */

int
lac_output_batch_ours (const char *name)
{
  static const char *const fixed[] = {
    "solution.vtu", "nodes.csv", "contact.csv", "contact_steps.csv",
    "contact.vtu",
    "curve.csv", "K.mtx", "summary.txt", "steps.pvd" };
  size_t k;
  for (k = 0; k < sizeof fixed / sizeof fixed[0]; k++)
    if (strcmp (name, fixed[k]) == 0)
      return 1;
  if (strncmp (name, "step_", 5) != 0)
    return 0;
  for (k = 5; isdigit ((unsigned char) name[k]); k++)
    ;
  return k > 5 && strcmp (name + k, ".vtu") == 0;
}

static char *
join (const char *a, const char *b)
{
  size_t len = strlen (a) + strlen (b) + 2;
  char *s = lac_malloc (len);
  if (s)
    snprintf (s, len, "%s/%s", a, b);
  return s;
}

/* mkdir -p */
static int
make_dirs (const char *dir)
{
  char *p, *s = lac_strdup (dir);
  struct stat st;
  int status = LAC_SUCCESS;
  if (!s)
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  for (p = s + 1; ; p++)
    if (*p == '/' || *p == '\0')
      {
        char c = *p;
        *p = '\0';
        if (mkdir (s, 0777) != 0 && errno != EEXIST)
          {
            status = LAC_ERRMSG (LAC_EIO, "cannot create directory '%s' "
                                 "(%s)", s, strerror (errno));
            break;
          }
        *p = c;
        if (c == '\0')
          break;
      }
  if (!status && (stat (dir, &st) != 0 || !S_ISDIR (st.st_mode)))
    status = LAC_ERRMSG (LAC_EIO, "'%s' is not a directory", dir);
  lac_free (s);
  return status;
}

/* Unlink the regular files of the directory path that d reads, close d,
 * then remove the directory if it is empty.  No allocation (the *at calls
 * name a file by its directory and its name), so that out of memory
 * cannot leave the files behind. */
static void
remove_in (DIR *d, const char *path)
{
  struct dirent *e;
  while ((e = readdir (d)))
    {
      struct stat st;
      if (fstatat (dirfd (d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0
          && !S_ISDIR (st.st_mode))
        unlinkat (dirfd (d), e->d_name, 0);
    }
  closedir (d);
  rmdir (path);
}

static void
remove_files (const char *dir)
{
  DIR *d = opendir (dir);
  if (d)
    remove_in (d, dir);
}

/* The earlier files, in the directory path that d reads: what a run never
 * writes goes back into the directory `to` (unless it has its own), the
 * rest is removed, then the directory itself; d and to are closed.  No
 * allocation: out of memory must not lose a foreign file. */
static void
finish_in (DIR *d, int to, const char *path)
{
  struct dirent *e;
  while ((e = readdir (d)))
    {
      struct stat st;
      if (!strcmp (e->d_name, ".") || !strcmp (e->d_name, "..")
          || lac_output_batch_ours (e->d_name))
        continue;
      if (fstatat (to, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0
          && renameat (dirfd (d), e->d_name, to, e->d_name) != 0)
        {
          closedir (d);         /* a foreign file could not go back: keep */
          close (to);           /* the directory (the next run tries)   */
          return;
        }
    }
  close (to);
  rewinddir (d);
  remove_in (d, path);
}

static void
finish_old (const char *old, const char *dir)
{
  DIR *d = opendir (old);
  int to = open (dir, O_RDONLY | O_DIRECTORY);
  if (d && to >= 0)
    finish_in (d, to, old);
  else if (d)
    closedir (d);
  else if (to >= 0)
    close (to);
}

/* The process id at the end of a temporary's name, or 0. */
static long
name_pid (const char *s)
{
  char *end;
  long pid = strtol (s, &end, 10);
  return *s && *end == '\0' && pid > 0 ? pid : 0;
}

static int
gone (long pid)
{
  return pid > 0 && pid != (long) getpid () && kill ((pid_t) pid, 0) != 0
         && errno == ESRCH;
}

/* ---------------------------------------------------------------------- */
/* what killed runs left                                                   */
/* ---------------------------------------------------------------------- */

/* In parent: .NAME.lac-new-PID and .NAME.lac-old-PID of dead processes. */
static void
clean_beside (const char *parent, const char *name, const char *dir)
{
  DIR *d = opendir (parent);
  struct dirent *e;
  size_t n = strlen (name);
  if (!d)
    return;
  while ((e = readdir (d)))
    {
      const char *s = e->d_name, *kind = s + 1 + n;
      char *p;
      struct stat st;
      if (s[0] != '.' || strncmp (s + 1, name, n) != 0
          || (strncmp (kind, NEW, 9) && strncmp (kind, OLD, 9))
          || !gone (name_pid (kind + 9)) || !(p = join (parent, s)))
        continue;
      if (lstat (dir, &st) != 0)   /* new: never published; old: lost */
        kind[5] == 'n' ? remove_files (p) : (void) rename (p, dir);
      else                          /* new after the exchange holds the */
        finish_old (p, dir);        /* earlier files: as old             */
      lac_free (p);
    }
  closedir (d);
}

/* In dir: the .FILE.tmpPID files of dead processes (lac before batches
 * had their own directory wrote those). */
static void
clean_inside (const char *dir)
{
  DIR *d = opendir (dir);
  struct dirent *e;
  if (!d)
    return;
  while ((e = readdir (d)))
    {
      const char *t = e->d_name[0] == '.' ? strstr (e->d_name, ".tmp") : NULL;
      char *p;
      while (t && strstr (t + 1, ".tmp"))
        t = strstr (t + 1, ".tmp");
      if (t && gone (name_pid (t + 4)) && (p = join (dir, e->d_name)))
        {
          unlink (p);
          lac_free (p);
        }
    }
  closedir (d);
}

/* ---------------------------------------------------------------------- */
/* the batch                                                               */
/* ---------------------------------------------------------------------- */

/* b->dir = dir without trailing slashes; b->tmp, b->old beside it; the
 * parent in *parent (owned by the caller), NAME in *name (inside it). */
static int
set_paths (lac_output_batch *b, const char *dir, char **parent,
           const char **name)
{
  size_t len = strlen (dir), plen;
  char *slash;
  while (len > 1 && dir[len - 1] == '/')
    len--;
  if (!(b->dir = lac_malloc (len + 1)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  memcpy (b->dir, dir, len);
  b->dir[len] = '\0';
  slash = strrchr (b->dir, '/');
  *name = slash ? slash + 1 : b->dir;
  plen = slash ? (size_t) (slash - b->dir) : 1;
  if (!(*parent = lac_malloc (plen + 1)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  memcpy (*parent, slash ? b->dir : ".", slash && plen == 0 ? 1 : plen);
  (*parent)[slash && plen == 0 ? 1 : plen] = '\0';
  len = strlen (*parent) + strlen (*name) + 40;
  if (!(b->tmp = lac_malloc (len)) || !(b->old = lac_malloc (len)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  snprintf (b->tmp, len, "%s/.%s" NEW "%ld", *parent, *name,
            (long) getpid ());
  snprintf (b->old, len, "%s/.%s" OLD "%ld", *parent, *name,
            (long) getpid ());
  if (!**name || !strcmp (*name, ".") || !strcmp (*name, ".."))
    LAC_ERROR (LAC_EINVAL, "'%s': name the output directory", dir);
  return LAC_SUCCESS;
}

lac_output_batch *
lac_output_batch_alloc (const char *dir, const volatile sig_atomic_t *stop)
{
  lac_output_batch *b;
  char *parent = NULL;
  const char *name = NULL;
  struct stat st;
  int status;
  if (!dir || !*dir)
    LAC_ERROR_NULL (LAC_EINVAL, "empty output directory name");
  if (!(b = lac_calloc (1, sizeof *b)))
    LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
  b->stop = stop;
  status = set_paths (b, dir, &parent, &name);
  if (!status)
    status = make_dirs (parent);
  if (!status)
    {
      clean_beside (parent, name, b->dir);
      clean_inside (b->dir);
      if (lstat (b->dir, &st) == 0 && !S_ISDIR (st.st_mode))
        status = LAC_ERRMSG (LAC_EIO, "'%s' is not a directory", b->dir);
    }
  if (!status && mkdir (b->tmp, 0777) != 0)
    status = LAC_ERRMSG (LAC_EIO, "cannot create directory '%s' (%s)",
                         b->tmp, strerror (errno));
  lac_free (parent);
  if (status)
    {
      b->committed = 1;                    /* nothing of ours to remove */
      lac_output_batch_free (b);
      return NULL;
    }
  return b;
}

void
lac_output_batch_free (lac_output_batch *b)
{
  if (!b)
    return;
  if (!b->committed)
    {
      for (size_t k = 0; k < b->n; k++)   /* no allocation needed here */
        unlink (b->path[k]);
      if (rmdir (b->tmp) != 0)
        remove_files (b->tmp);
    }
  for (size_t k = 0; k < b->n; k++)
    {
      lac_free (b->final[k]);
      lac_free (b->path[k]);
    }
  lac_free (b->final);
  lac_free (b->path);
  lac_free (b->dir);
  lac_free (b->tmp);
  lac_free (b->old);
  lac_free (b);
}

static int
interrupted (const lac_output_batch *b)
{
  if (!b->stop || !*b->stop)
    return 0;
  lac_error_set (LAC_EIO, "lac_output", "interrupted by signal %d: nothing "
                 "written, the files in '%s' are those of the earlier run",
                 (int) *b->stop, b->dir);
  return 1;
}

const char *
lac_output_batch_add (lac_output_batch *b, const char *name)
{
  if (interrupted (b))
    return NULL;
  size_t cap = b->cap;                   /* final and path share it */
  if (lac_grow (&b->final, b->n + 1, &cap, sizeof *b->final, 8)
      || lac_grow (&b->path, b->n + 1, &b->cap, sizeof *b->path, 8))
    LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
  b->final[b->n] = join (b->dir, name);
  b->path[b->n] = join (b->tmp, name);
  if (!b->final[b->n] || !b->path[b->n])
    {
      lac_free (b->final[b->n]);
      lac_free (b->path[b->n]);
      LAC_ERROR_NULL (LAC_ENOMEM, "out of memory");
    }
  return b->path[b->n++];
}

/* Where RENAME_EXCHANGE is not supported: DIR -> old, tmp -> DIR. */
static int
swap_by_renames (lac_output_batch *b)
{
  if (rename (b->dir, b->old) != 0)
    LAC_ERROR (LAC_EIO, "cannot rename '%s' to '%s' (%s)", b->dir, b->old,
               strerror (errno));
  if (rename (b->tmp, b->dir) != 0)
    {
      int e = errno;
      rename (b->old, b->dir);
      LAC_ERROR (LAC_EIO, "cannot rename '%s' to '%s' (%s)", b->tmp, b->dir,
                 strerror (e));
    }
  return LAC_SUCCESS;
}

/* Publish: exchange tmp and DIR.  The earlier DIR and the new one are
 * opened first, so that the earlier files can be finished after the
 * exchange without an allocation (opendir needs one). */
int
lac_output_commit (lac_output_batch *b)
{
  DIR *old;
  int to, status = LAC_SUCCESS;
  const char *where = b->tmp;                /* the earlier files after */
  if (interrupted (b))
    return LAC_EIO;
  old = opendir (b->dir);
  if (!old && errno != ENOENT)
    LAC_ERROR (lac_status_errno (errno), "cannot read '%s' "
               "(%s)", b->dir, strerror (errno));
  if ((to = open (b->tmp, O_RDONLY | O_DIRECTORY)) < 0)
    {
      if (old)
        closedir (old);
      LAC_ERROR (LAC_EIO, "cannot open '%s' (%s)", b->tmp, strerror (errno));
    }
  if (!old)
    {
      if (rename (b->tmp, b->dir) != 0)
        status = LAC_ERRMSG (LAC_EIO, "cannot rename '%s' to '%s' (%s)",
                             b->tmp, b->dir, strerror (errno));
    }
  else if (renameat2 (AT_FDCWD, b->tmp, AT_FDCWD, b->dir, RENAME_EXCHANGE)
           != 0)
    {
      if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP)
        status = swap_by_renames (b), where = b->old;
      else
        status = LAC_ERRMSG (LAC_EIO, "cannot exchange '%s' and '%s' (%s)",
                             b->tmp, b->dir, strerror (errno));
    }
  if (status || !old)
    {
      if (old)
        closedir (old);
      close (to);
      b->committed = !status;
      return status;
    }
  finish_in (old, to, where);     /* to is now DIR, old the earlier DIR */
  b->committed = 1;
  return LAC_SUCCESS;
}

const char *
lac_output_batch_path (const lac_output_batch *b, size_t k)
{
  return k < b->n ? b->final[k] : NULL;
}
