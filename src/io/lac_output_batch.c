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

/* Messages name the module, not a static helper: the caller (run/)
 * strips the "lac_..." part and keeps what names the path and reason. */
#define OUT_ERR(status, ...) lac_error_set ((status), "lac_output_batch", \
                                            __VA_ARGS__)

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
  mode_t mode;        /* the earlier DIR's permissions (0: none)       */
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
    return OUT_ERR (LAC_ENOMEM, "out of memory");
  for (p = s + 1; ; p++)
    if (*p == '/' || *p == '\0')
      {
        char c = *p;
        *p = '\0';
        if (mkdir (s, 0777) != 0 && errno != EEXIST)
          {
            status = OUT_ERR (LAC_EIO, "cannot create directory '%s' "
                              "for the output directory (%s)", s,
                              strerror (errno));
            break;
          }
        *p = c;
        if (c == '\0')
          break;
      }
  if (!status && (stat (dir, &st) != 0 || !S_ISDIR (st.st_mode)))
    status = OUT_ERR (LAC_EIO, "cannot make the output directory inside "
                      "'%s': it is not a directory", dir);
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
/* what must hold before anything is written                               */
/* ---------------------------------------------------------------------- */

/* Can this process create, rename and remove entries of the directory
 * path?  Asked as the effective user, as the calls that follow will be
 * (root always can); errno says why not. */
static int
writable (const char *path)
{
  return faccessat (AT_FDCWD, path, W_OK | X_OK, AT_EACCESS) == 0;
}

static const char *
kind_of (mode_t mode)
{
  return S_ISREG (mode) ? "a regular file" : S_ISLNK (mode)
         ? "a symbolic link" : "a special file";
}

/* A symbolic link to a directory stands for that directory: the exchange
 * must move the directory, not replace the link.  *real: the directory
 * (owned, malloc'ed by realpath), or NULL when dir is no link. */
static int
follow_link (const char *dir, char **real)
{
  struct stat st;
  char target[256];
  ssize_t n;
  *real = NULL;
  if (lstat (dir, &st) != 0 || !S_ISLNK (st.st_mode))
    return LAC_SUCCESS;
  n = readlink (dir, target, sizeof target - 1);
  target[n > 0 ? n : 0] = '\0';
  if (stat (dir, &st) != 0)
    return OUT_ERR (LAC_EIO, "the output directory '%s' is a symbolic link "
                    "to '%s', which cannot be reached (%s)", dir, target,
                    strerror (errno));
  if (!S_ISDIR (st.st_mode))
    return OUT_ERR (LAC_EIO, "the output directory '%s' is a symbolic link "
                    "to '%s', which is %s, not a directory", dir, target,
                    kind_of (st.st_mode));
  if (!(*real = realpath (dir, NULL)))
    return OUT_ERR (lac_status_errno (errno), "the output directory '%s': "
                    "cannot resolve its link to '%s' (%s)", dir, target,
                    strerror (errno));
  return LAC_SUCCESS;
}

/* DIR, if it exists, is a directory this process may write into, and its
 * parent too (the temporary directory is made there, the two are
 * exchanged there).  A directory made read-only keeps its files: a run
 * into it fails here instead of replacing it by a writable one. */
static int
check_dir (const char *dir, const char *parent)
{
  struct stat st;
  if (lstat (dir, &st) == 0 && !S_ISDIR (st.st_mode))
    return OUT_ERR (LAC_EIO, "the output directory '%s' exists and is %s, "
                    "not a directory", dir, kind_of (st.st_mode));
  if (lstat (dir, &st) == 0 && !writable (dir))
    return OUT_ERR (LAC_EIO, "the output directory '%s' is not writable "
                    "(%s): a run writes its files anew and keeps the others, "
                    "which needs write permission there", dir,
                    strerror (errno));
  if (!writable (parent))
    return OUT_ERR (LAC_EIO, "cannot write beside the output directory '%s':"
                    " '%s' is not writable (%s); a run writes its files into"
                    " a temporary directory there first", dir, parent,
                    strerror (errno));
  return LAC_SUCCESS;
}

/* The directory that holds path, in buf ("." for a name without '/'). */
static void
parent_of (const char *path, char *buf, size_t size)
{
  char *slash;
  snprintf (buf, size, "%s", path);
  while ((slash = strrchr (buf, '/')) && slash > buf && !slash[1])
    *slash = '\0';                          /* trailing slashes */
  if (!(slash = strrchr (buf, '/')))
    snprintf (buf, size, ".");
  else
    slash[slash == buf] = '\0';             /* "/a": keep "/" */
}

/* The deepest part of path that exists, in buf. */
static void
existing_part (const char *path, char *buf, size_t size)
{
  struct stat st;
  char up[4096];
  snprintf (buf, size, "%s", path);
  while (strcmp (buf, ".") && strcmp (buf, "/") && lstat (buf, &st) != 0)
    {
      parent_of (buf, up, sizeof up);
      snprintf (buf, size, "%s", up);
    }
}

int
lac_output_batch_check (const char *dir)
{
  char *real = NULL, part[4096], parent[4096];
  const char *d;
  struct stat st;
  int status;
  if (!dir || !*dir)
    return OUT_ERR (LAC_EINVAL, "empty output directory name");
  if ((status = follow_link (dir, &real)))
    return status;
  d = real ? real : dir;
  existing_part (d, part, sizeof part);
  parent_of (d, parent, sizeof parent);
  if (strcmp (part, d) == 0)
    status = check_dir (d, parent);
  else if (stat (part, &st) != 0 || !S_ISDIR (st.st_mode))
    status = OUT_ERR (LAC_EIO, "cannot make the output directory '%s': "
                      "'%s' is not a directory", dir, part);
  else if (!writable (part))
    status = OUT_ERR (LAC_EIO, "cannot make the output directory '%s': "
                      "'%s' is not writable (%s)", dir, part,
                      strerror (errno));
  free (real);
  return status;
}

/* Before the exchange: every entry of the earlier DIR (read by d) that a
 * run never writes must be able to go back into the new DIR: a directory
 * moves to another parent only if this process may write into it, and in
 * a sticky directory only its owner (or DIR's) may move an entry.  Were
 * one left behind, it would end hidden in the temporary directory. */
static int
check_foreign (DIR *d, const char *dir)
{
  struct dirent *e;
  struct stat sd, st;
  int status = LAC_SUCCESS;
  uid_t me = geteuid ();
  if (fstat (dirfd (d), &sd) != 0)
    return LAC_SUCCESS;
  while (!status && (e = readdir (d)))
    {
      if (!strcmp (e->d_name, ".") || !strcmp (e->d_name, "..")
          || lac_output_batch_ours (e->d_name)
          || fstatat (dirfd (d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0)
        continue;
      if (S_ISDIR (st.st_mode)
          && faccessat (dirfd (d), e->d_name, W_OK, AT_EACCESS) != 0)
        status = OUT_ERR (LAC_EIO, "cannot publish into '%s': its "
                          "subdirectory '%s' is not writable (%s), so it "
                          "cannot be moved into the new directory", dir,
                          e->d_name, strerror (errno));
      else if ((sd.st_mode & S_ISVTX) && me != 0 && me != sd.st_uid
               && me != st.st_uid)
        status = OUT_ERR (LAC_EIO, "cannot publish into '%s': it is a "
                          "sticky directory and '%s' belongs to another "
                          "user, so it cannot be moved into the new "
                          "directory", dir, e->d_name);
    }
  rewinddir (d);
  return status;
}

/* ---------------------------------------------------------------------- */
/* the batch                                                               */
/* ---------------------------------------------------------------------- */

/* b->dir = dir without trailing slashes (a link to a directory: that
 * directory); b->tmp, b->old beside it; the parent in *parent (owned by
 * the caller), NAME in *name (inside b->dir). */
static int
set_paths (lac_output_batch *b, const char *dir, char **parent,
           const char **name)
{
  size_t len, plen;
  char *slash, *real = NULL;
  int status = follow_link (dir, &real);
  if (status)
    return status;
  if (real)
    dir = real;
  len = strlen (dir);
  while (len > 1 && dir[len - 1] == '/')
    len--;
  if ((b->dir = lac_malloc (len + 1)))
    {
      memcpy (b->dir, dir, len);
      b->dir[len] = '\0';
    }
  free (real);
  if (!b->dir)
    return OUT_ERR (LAC_ENOMEM, "out of memory");
  slash = strrchr (b->dir, '/');
  *name = slash ? slash + 1 : b->dir;
  plen = slash ? (size_t) (slash - b->dir) : 1;
  if (!(*parent = lac_malloc (plen + 1)))
    return OUT_ERR (LAC_ENOMEM, "out of memory");
  memcpy (*parent, slash ? b->dir : ".", slash && plen == 0 ? 1 : plen);
  (*parent)[slash && plen == 0 ? 1 : plen] = '\0';
  len = strlen (*parent) + strlen (*name) + 40;
  if (!(b->tmp = lac_malloc (len)) || !(b->old = lac_malloc (len)))
    return OUT_ERR (LAC_ENOMEM, "out of memory");
  snprintf (b->tmp, len, "%s/.%s" NEW "%ld", *parent, *name,
            (long) getpid ());
  snprintf (b->old, len, "%s/.%s" OLD "%ld", *parent, *name,
            (long) getpid ());
  if (!**name || !strcmp (*name, ".") || !strcmp (*name, ".."))
    return OUT_ERR (LAC_EINVAL, "'%s': name the output directory", dir);
  return LAC_SUCCESS;
}

lac_output_batch *
lac_output_batch_alloc (const char *dir, const volatile sig_atomic_t *stop)
{
  lac_output_batch *b;
  char *parent = NULL;
  const char *name = NULL;
  int status;
  if (!dir || !*dir)
    {
      OUT_ERR (LAC_EINVAL, "empty output directory name");
      return NULL;
    }
  if (!(b = lac_calloc (1, sizeof *b)))
    {
      OUT_ERR (LAC_ENOMEM, "out of memory");
      return NULL;
    }
  b->stop = stop;
  status = set_paths (b, dir, &parent, &name);
  if (!status)
    status = make_dirs (parent);
  if (!status)
    {
      clean_beside (parent, name, b->dir);
      clean_inside (b->dir);
      status = check_dir (b->dir, parent);
    }
  if (!status && mkdir (b->tmp, 0777) != 0)
    status = OUT_ERR (LAC_EIO, "cannot create the temporary directory '%s' "
                      "beside the output directory (%s)", b->tmp,
                      strerror (errno));
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
  OUT_ERR (LAC_EIO, "interrupted by signal %d: nothing "
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
    {
      OUT_ERR (LAC_ENOMEM, "out of memory");
      return NULL;
    }
  b->final[b->n] = join (b->dir, name);
  b->path[b->n] = join (b->tmp, name);
  if (!b->final[b->n] || !b->path[b->n])
    {
      lac_free (b->final[b->n]);
      lac_free (b->path[b->n]);
      OUT_ERR (LAC_ENOMEM, "out of memory");
      return NULL;
    }
  return b->path[b->n++];
}

/* Where RENAME_EXCHANGE is not supported: DIR -> old, tmp -> DIR. */
static int
swap_by_renames (lac_output_batch *b)
{
  if (rename (b->dir, b->old) != 0)
    return OUT_ERR (LAC_EIO, "cannot rename '%s' to '%s' (%s)", b->dir,
                    b->old, strerror (errno));
  if (rename (b->tmp, b->dir) != 0)
    {
      int e = errno;
      rename (b->old, b->dir);
      return OUT_ERR (LAC_EIO, "cannot rename '%s' to '%s' (%s)", b->tmp,
                      b->dir, strerror (e));
    }
  return LAC_SUCCESS;
}

/* What can be checked before the exchange: DIR and its parent still
 * writable, every foreign entry of DIR movable; then the new directory
 * takes the earlier one's permissions (a directory shared with a group
 * stays shared).  *old: the earlier DIR opened (NULL: none), *to: the
 * new one; both opened now, so that the earlier files can be finished
 * after the exchange without an allocation (opendir needs one). */
static int
prepare (lac_output_batch *b, DIR **old, int *to)
{
  char parent[4096];
  struct stat st;
  int status;
  parent_of (b->dir, parent, sizeof parent);
  if ((status = check_dir (b->dir, parent)))
    return status;
  *old = opendir (b->dir);
  if (!*old && errno != ENOENT)
    return OUT_ERR (lac_status_errno (errno), "cannot read the output "
                    "directory '%s' (%s)", b->dir, strerror (errno));
  if (*old && (status = check_foreign (*old, b->dir)))
    return status;
  if ((*to = open (b->tmp, O_RDONLY | O_DIRECTORY)) < 0)
    return OUT_ERR (LAC_EIO, "cannot open '%s' (%s)", b->tmp,
                    strerror (errno));
  if (*old && fstat (dirfd (*old), &st) == 0)   /* the owner's bits until */
    {                                           /* the foreign files are  */
      b->mode = st.st_mode & 07777;             /* back (see commit)      */
      fchmod (*to, b->mode | S_IRWXU);
    }
  return LAC_SUCCESS;
}

/* Publish: exchange tmp and DIR (see lac_output_batch.h). */
int
lac_output_commit (lac_output_batch *b)
{
  DIR *old = NULL;
  int to = -1, status;
  const char *where = b->tmp;                /* the earlier files after */
  if (interrupted (b))
    return LAC_EIO;
  status = prepare (b, &old, &to);
  if (!status && !old && rename (b->tmp, b->dir) != 0)
    status = OUT_ERR (LAC_EIO, "cannot rename '%s' to '%s' (%s)", b->tmp,
                      b->dir, strerror (errno));
  else if (!status && old && renameat2 (AT_FDCWD, b->tmp, AT_FDCWD, b->dir,
                                        RENAME_EXCHANGE) != 0)
    {
      if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP)
        status = swap_by_renames (b), where = b->old;
      else
        status = OUT_ERR (LAC_EIO, "cannot exchange '%s' and '%s' (%s)",
                          b->tmp, b->dir, strerror (errno));
    }
  if (status || !old)
    {
      if (old)
        closedir (old);
      if (to >= 0)
        close (to);
      b->committed = !status;
      return status;
    }
  finish_in (old, to, where);     /* to is now DIR, old the earlier DIR */
  if ((b->mode & S_IRWXU) != S_IRWXU)
    chmod (b->dir, b->mode);
  b->committed = 1;
  return LAC_SUCCESS;
}

const char *
lac_output_batch_path (const lac_output_batch *b, size_t k)
{
  return k < b->n ? b->final[k] : NULL;
}
