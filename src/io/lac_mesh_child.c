/* lac_mesh_child.c -- a mesh reader in a child process (lac_mesh_child.h)
 *
 * The parent forks, reads the child's answer (pipe `data`) and its
 * stdout/stderr (pipe `talk`, of which it keeps the last bytes) with
 * poll() until both pipes close or the wall-clock limit passes, then
 * waits for the child and turns how it ended into a status and one
 * message.  The answer is decoded only if the child exited with status 0.
 *
 * Cost: one fork of the lac process and a copy of the mesh through a pipe:
 * 2-4 ms plus about 0.2 us per node (bench/bench_mesh_read.c; chapter 01,
 * bad-input.md, has the numbers against the time gmsh takes).
 */
#define _GNU_SOURCE            /* close_range, REG_RSP */
#include "io/lac_mesh_child.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <sys/mman.h>
#include <time.h>
#include <ucontext.h>
#include <unistd.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "io/lac_mesh_sandbox.h"
#include "io/lac_mesh_wire.h"

#if defined(__SANITIZE_ADDRESS__)
#define LAC_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LAC_ASAN 1
#endif
#endif

#define TAIL 2048      /* bytes of the child's stderr kept */

double
lac_mesh_default_memory (void)
{
  long pages = sysconf (_SC_PHYS_PAGES), size = sysconf (_SC_PAGESIZE);
  double mem = pages > 0 && size > 0 ? 0.8 * (double) pages * (double) size
                                     : 4e9;
  struct rlimit rl;
  if (getrlimit (RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY
      && 0.8 * (double) rl.rlim_cur < mem)
    mem = 0.8 * (double) rl.rlim_cur;
  return mem;
}

/* ---------------------------------------------------------------------- */
/* the child                                                               */
/* ---------------------------------------------------------------------- */

#ifndef LAC_ASAN   /* (under ASan the child gets no RLIMIT_AS) */
/* The address space the process holds now (bytes), from /proc. */
static double
address_space (void)
{
  FILE *f = fopen ("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (f)
    {
      if (fscanf (f, "%lu", &pages) != 1)
        pages = 0;
      fclose (f);
    }
  return (double) pages * (double) sysconf (_SC_PAGESIZE);
}
#endif

/* The soft limit of resource: value, or the hard limit if lower (a value
 * beyond 2^63, which rlim_t would not hold, is no limit of lac's). */
static void
set_limit (int resource, double value)
{
  struct rlimit rl;
  if (getrlimit (resource, &rl) != 0)
    return;
  if (value < 0x1p63
      && (value < (double) rl.rlim_max || rl.rlim_max == RLIM_INFINITY))
    rl.rlim_cur = (rlim_t) value;
  else
    rl.rlim_cur = rl.rlim_max;
  setrlimit (resource, &rl);
}

/* The stack pointer where a signal came, 0 if unknown here. */
static unsigned long
stack_pointer (const void *context)
{
  const ucontext_t *uc = context;
#if defined(__x86_64__)
  return (unsigned long) uc->uc_mcontext.gregs[REG_RSP];
#elif defined(__aarch64__)
  return (unsigned long) uc->uc_mcontext.sp;
#else
  (void) uc;
  return 0;
#endif
}

/* SIGSEGV from a fault (not kill) at an address within 64 kB of the stack
 * pointer: the stack overflowed (the page beyond it is not mapped).  Say
 * so on stderr, then die by the signal all the same (the handler runs on
 * its own stack). */
static void
on_segv (int sig, siginfo_t *si, void *context)
{
  static const char said[] = "\nlac-child: stack overflow\n";
  unsigned long sp = stack_pointer (context), a = (unsigned long) si->si_addr;
  if (si->si_code > 0 && sp && a + 65536 > sp && a < sp + 65536
      && write (2, said, sizeof said - 1) < 0)
    sp = 0;
  signal (sig, SIG_DFL);                  /* delivered when this returns */
  raise (sig);
}

/* A crash kills the child with its signal, whatever handler the process
 * had (AddressSanitizer installs its own); a stack overflow says so
 * first. */
static void
default_signals (void)
{
  static const int sig[] = { SIGINT, SIGTERM, SIGPIPE, SIGSEGV, SIGBUS,
                             SIGFPE, SIGILL, SIGABRT };
  stack_t ss = { 0 };
  struct sigaction sa;
  for (size_t k = 0; k < sizeof sig / sizeof sig[0]; k++)
    signal (sig[k], SIG_DFL);
  ss.ss_size = 1 << 16;
  ss.ss_sp = mmap (NULL, ss.ss_size, PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (ss.ss_sp == MAP_FAILED || sigaltstack (&ss, NULL) != 0)
    return;
  memset (&sa, 0, sizeof sa);
  sa.sa_sigaction = on_segv;
  sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset (&sa.sa_mask);
  sigaction (SIGSEGV, &sa, NULL);
}

/* stdin from /dev/null, stdout and stderr into `talk`, the answer on fd 3,
 * and every other descriptor lac held closed: gmsh gets nothing it could
 * write to but the two pipes.  Returns the answer's descriptor. */
static int
own_descriptors (int data, int talk)
{
  int devnull = open ("/dev/null", O_RDONLY);
  data = fcntl (data, F_DUPFD, 10);        /* out of the way of 0 .. 3 */
  talk = fcntl (talk, F_DUPFD, 10);
  if (devnull >= 0)
    dup2 (devnull, 0);
  dup2 (talk, 1);
  dup2 (talk, 2);
  if (data != 3)
    dup2 (data, 3);
  if (close_range (4, ~0u, 0) != 0)
    for (int fd = 4; fd < 4096; fd++)
      close (fd);
  return 3;
}

/* A reader that failed without a word (gmsh swallows std::bad_alloc)
 * while the address space was within reach of its limit ran out of
 * memory: say so, the parent adds the limit. */
static int
blame_memory (int status, double limit, double max_memory)
{
#ifndef LAC_ASAN
  double left = limit - address_space ();
  if (status && status != LAC_ENOMEM
      && strstr (lac_error_message (), "gives no details")
      && left < (0.1 * max_memory > 64e6 ? 0.1 * max_memory : 64e6))
    {
      char msg[900];
      const char *m = lac_error_message (), *colon = strstr (m, ": ");
      snprintf (msg, sizeof msg, "%s", colon ? colon + 2 : m);
      return lac_error_set (LAC_ENOMEM, "lac_mesh_read", "%s", msg);
    }
#else
  (void) limit, (void) max_memory;
#endif
  return status;
}

/* OpenBLAS in the child: one thread.  fork's pre-fork handler joined its
 * workers, and the first parallel BLAS call would start them again, each
 * wanting a 128 MB buffer that the memory limit may refuse: OpenBLAS
 * 0.3.21 then retries forever (cli/lac_cli_limits.h).  Found by its own
 * symbol: with the reference BLAS there is nothing to do. */
static void
one_blas_thread (void)
{
  void (*set) (int) = (void (*) (int)) dlsym (RTLD_DEFAULT,
                                              "openblas_set_num_threads");
  if (set)
    set (1);
}

/* Everything between fork and _exit. */
static void
child (int data, int talk, pid_t parent, lac_mesh_child_fn fn, void *arg,
       double max_memory, double max_seconds)
{
  lac_mesh *m = NULL;
  int status;
  double limit = 0;
  default_signals ();
  prctl (PR_SET_PDEATHSIG, SIGKILL);
  if (getppid () != parent)
    _exit (127);
  data = own_descriptors (data, talk);
  one_blas_thread ();
  set_limit (RLIMIT_CORE, 0);
  set_limit (RLIMIT_CPU, max_seconds + 1);
#ifndef LAC_ASAN
  limit = address_space () + max_memory;
  set_limit (RLIMIT_AS, limit);
#endif
  status = blame_memory (fn (arg, &m), limit, max_memory);
  if (status == LAC_SUCCESS && !m)
    status = LAC_ERRMSG (LAC_ESANITY, "the reader returned no mesh");
  _exit (lac_mesh_wire_write (data, status, status ? lac_error_message ()
                                                   : NULL, m) ? 3 : 0);
}

/* ---------------------------------------------------------------------- */
/* the parent                                                              */
/* ---------------------------------------------------------------------- */

typedef struct answer
{
  unsigned char *buf;          /* owned: the data pipe's bytes          */
  size_t len, cap;
  char tail[TAIL + 1];         /* the last bytes of the child's stderr  */
  size_t ntail;
  int nomem, timed_out;
} answer;

static double
now (void)
{
  struct timespec ts;
  clock_gettime (CLOCK_MONOTONIC, &ts);
  return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* Read what fd has; returns 0 at end of file. */
static int
drain (int fd, answer *a, int is_data)
{
  unsigned char chunk[1 << 15];
  ssize_t k = read (fd, chunk, sizeof chunk);
  if (k < 0)
    return errno == EINTR || errno == EAGAIN;
  if (k == 0)
    return 0;
  if (!is_data)
    {
      size_t n = (size_t) k > TAIL ? TAIL : (size_t) k;
      if (a->ntail + n > TAIL)
        {
          size_t drop = a->ntail + n - TAIL;
          memmove (a->tail, a->tail + drop, a->ntail - drop);
          a->ntail -= drop;
        }
      memcpy (a->tail + a->ntail, chunk + (size_t) k - n, n);
      a->ntail += n;
      a->tail[a->ntail] = '\0';
      return 1;
    }
  if (lac_grow (&a->buf, a->len + (size_t) k, &a->cap, 1, 1 << 16))
    return a->nomem = 1, 0;
  memcpy (a->buf + a->len, chunk, (size_t) k);
  a->len += (size_t) k;
  return 1;
}

/* Both pipes until they close, the memory runs out or the time is up. */
static void
collect (int data, int talk, pid_t pid, double seconds, answer *a)
{
  struct pollfd p[2] = { { data, POLLIN, 0 }, { talk, POLLIN, 0 } };
  double end = now () + seconds;
  while ((p[0].fd >= 0 || p[1].fd >= 0) && !a->nomem)
    {
      double left = end - now ();
      int r;
      if (left <= 0)
        {
          a->timed_out = 1;
          break;
        }
      r = poll (p, 2, left > 1e6 ? 1000000000 : (int) (left * 1000) + 1);
      if (r < 0 && errno != EINTR)
        break;
      for (int i = 0; i < 2 && r > 0; i++)
        if (p[i].fd >= 0 && (p[i].revents & (POLLIN | POLLHUP | POLLERR))
            && !drain (p[i].fd, a, i == 0))
          p[i].fd = -1;
    }
  if (a->timed_out || a->nomem)
    kill (pid, SIGKILL);
}

static int
wait_child (pid_t pid)
{
  int ws = 0;
  while (waitpid (pid, &ws, 0) < 0)
    if (errno != EINTR)
      return -1;
  return ws;
}

/* Did the child run out of memory?  Its stderr or message says so. */
static int
said_nomem (const answer *a, const char *msg)
{
  return strstr (a->tail, "bad_alloc") || strstr (a->tail, "out of memory")
         || strstr (a->tail, "Cannot allocate memory")
         || (msg && (strstr (msg, "bad_alloc")
                     || strstr (msg, "out of memory")));
}

/* A message stored by the child, stored again here. */
static int
restore (int status, const char *msg)
{
  return lac_error_set (status, NULL, "%s", msg);
}

/* bytes as "20.2 GB", "350.0 MB", "12.0 kB" or "1 byte(s)". */
static const char *
amount (double bytes, char *buf, size_t size)
{
  if (bytes >= 1e8)
    snprintf (buf, size, "%.1f GB", bytes / 1e9);
  else if (bytes >= 1e5)
    snprintf (buf, size, "%.1f MB", bytes / 1e6);
  else if (bytes >= 1e3)
    snprintf (buf, size, "%.1f kB", bytes / 1e3);
  else
    snprintf (buf, size, "%.0f byte%s", bytes, bytes == 1 ? "" : "s");
  return buf;
}

/* What a crash of the child may owe to a limit: its stack overflowed (it
 * said so), or the stack limit is below the 8 MB of a usual system. */
static void
stack_words (const answer *a, int sig, char *buf, size_t size)
{
  struct rlimit rl;
  char lim[32] = "";
  buf[0] = '\0';
  if (sig != SIGSEGV && sig != SIGBUS)
    return;
  if (getrlimit (RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
    snprintf (lim, sizeof lim, "%.0f KiB", (double) rl.rlim_cur / 1024);
  if (strstr (a->tail, "lac-child: stack overflow"))
    snprintf (buf, size, ": its stack overflowed%s%s%s", *lim ? " (stack "
              "limit " : "", lim, *lim ? ", ulimit -s)" : "");
  else if (*lim && rl.rlim_cur < 8u << 20)
    snprintf (buf, size, " (the stack limit is %s, ulimit -s: gmsh may need"
              " more)", lim);
}

/* The child died by a signal or exited with a status: one message. */
static int
ended (const char *verb, const char *path, int ws, const answer *a,
       double max_memory)
{
  char how[96], lim[32], stack[96] = "";
  int st;
  if (WIFSIGNALED (ws))
    snprintf (how, sizeof how, "killed by signal %d (%s)", WTERMSIG (ws),
              strsignal (WTERMSIG (ws)));
  else
    snprintf (how, sizeof how, "it exited with status %d", WEXITSTATUS (ws));
  if ((st = lac_mesh_sandbox_verdict (ws, a->tail, verb, path)))
    return st;
  if (said_nomem (a, NULL) || (WIFSIGNALED (ws) && WTERMSIG (ws) == SIGKILL))
    return lac_error_set (LAC_ENOMEM, "lac_mesh_read", "gmsh could not %s "
                          "'%s': %s: out of memory (limit %s, --max-memory)",
                          verb, path, how, amount (max_memory, lim,
                                                   sizeof lim));
  if (WIFSIGNALED (ws))
    stack_words (a, WTERMSIG (ws), stack, sizeof stack);
  if (strstr (stack, "overflowed"))
    return lac_error_set (LAC_EIO, "lac_mesh_read", "gmsh could not %s "
                          "'%s': %s%s", verb, path, how, stack);
  return lac_error_set (LAC_EIO, "lac_mesh_read", "gmsh could not %s '%s': "
                        "%s%s; %s", verb, path, how, stack, verb[0] == 'r'
                        ? "the file is malformed or truncated"
                        : "the .geo script or its options are beyond gmsh");
}

/* How the child ended, as a status and one message. */
static int
verdict (const char *verb, const char *path, int ws, const answer *a,
         double max_memory, double seconds, lac_mesh **out)
{
  char msg[1024], lim[32];
  int status = LAC_ESANITY, st;
  if (a->nomem)
    return lac_error_set (LAC_ENOMEM, "lac_mesh_read", "'%s': out of memory "
                          "receiving the mesh (%zu bytes)", path, a->len);
  if (a->timed_out || (WIFSIGNALED (ws) && WTERMSIG (ws) == SIGXCPU))
    return lac_error_set (LAC_EMAXITER, "lac_mesh_read", "gmsh could not %s "
                          "'%s' within the time limit of %.0f s", verb, path,
                          seconds);
  if (WIFSIGNALED (ws) || (WIFEXITED (ws) && WEXITSTATUS (ws) != 0))
    return ended (verb, path, ws, a, max_memory);
  st = lac_mesh_wire_read (a->buf, a->len, &status, msg, sizeof msg, out);
  if (st)
    {
      snprintf (msg, sizeof msg, "%s", lac_error_message ());
      return lac_error_set (st, "lac_mesh_read", "gmsh could not %s '%s': "
                            "%s", verb, path, msg);
    }
  if (status && said_nomem (a, msg))
    return lac_error_set (LAC_ENOMEM, "lac_mesh_read", "gmsh could not %s "
                          "'%s': out of memory (limit %s, --max-memory)",
                          verb, path, amount (max_memory, lim, sizeof lim));
  return status ? restore (status, msg) : LAC_SUCCESS;
}

static int
make_pipe (int fd[2])
{
  if (pipe (fd) != 0)
    return -1;
  fcntl (fd[0], F_SETFD, FD_CLOEXEC);
  fcntl (fd[1], F_SETFD, FD_CLOEXEC);
  return 0;
}

/* lac_mesh_child_run: see lac_mesh_child.h. */
int
lac_mesh_child_run (const char *verb, const char *path, lac_mesh_child_fn fn,
                    void *arg, double max_memory, double max_seconds,
                    lac_mesh **out)
{
  int data[2] = { -1, -1 }, talk[2] = { -1, -1 }, ws, status;
  answer *a;
  pid_t pid, parent = getpid ();
  *out = NULL;
  if (max_memory <= 0)
    max_memory = lac_mesh_default_memory ();
  if (max_seconds <= 0)
    max_seconds = LAC_MESH_CHILD_SECONDS;
  if (!(a = lac_calloc (1, sizeof *a)))
    return lac_error_set (LAC_ENOMEM, "lac_mesh_read", "'%s': out of memory",
                          path);
  if (make_pipe (data) || make_pipe (talk) || (pid = fork ()) < 0)
    {
      int e = errno;
      for (int i = 0; i < 2; i++)
        {
          if (data[i] >= 0)
            close (data[i]);
          if (talk[i] >= 0)
            close (talk[i]);
        }
      lac_free (a);
      return lac_error_set (e == ENOMEM || e == EAGAIN ? LAC_ENOMEM : LAC_EIO,
                            "lac_mesh_read", "'%s': cannot start a process "
                            "for gmsh (%s)%s", path, strerror (e),
                            e == ENOMEM ? ": out of memory" : "");
    }
  if (pid == 0)
    {
      close (data[0]);
      close (talk[0]);
      child (data[1], talk[1], parent, fn, arg, max_memory, max_seconds);
    }
  close (data[1]);
  close (talk[1]);
  collect (data[0], talk[0], pid, max_seconds, a);
  close (data[0]);
  close (talk[0]);
  ws = wait_child (pid);
  status = verdict (verb, path, ws, a, max_memory, max_seconds, out);
  lac_free (a->buf);
  lac_free (a);
  return status;
}
