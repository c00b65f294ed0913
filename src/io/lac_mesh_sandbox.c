/* lac_mesh_sandbox.c -- what gmsh may do in lac's child process
 * (see lac_mesh_sandbox.h)
 *
 * A seccomp filter is a small BPF program the kernel runs at every system
 * call (Linux, Documentation/userspace-api/seccomp_filter.rst).  Ours
 * checks the architecture (a 32-bit or x32 call would bypass the numbers
 * below: the process is killed), then the calls of the table `rules`, two
 * or five instructions each:
 *
 *   if (nr == N) return ACTION;                          plain rule
 *   if (nr == N) return args[A] & MASK ? ACTION : ALLOW;  open for writing
 *   if (nr == N) return args[A] & MASK ? ALLOW : ACTION;  clone of a process
 *
 * and allows the rest.  Filters stack: of two, the stricter action wins,
 * so the second step's SIGSYS overrides the first step's EACCES.
 *
 * SIGSYS (SECCOMP_RET_TRAP) carries the call's number; its arguments are
 * in the registers saved in the signal's context (the path a call names
 * is shown in the message, up to 160 bytes).  The handler uses write and
 * _exit only.
 */
#define _GNU_SOURCE            /* REG_RDI and the other registers */
#include "io/lac_mesh_sandbox.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <ucontext.h>
#include <unistd.h>

#include "base/lac_status.h"

#if defined(__x86_64__)
#define ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define ARCH AUDIT_ARCH_AARCH64
#endif

enum kind
{
  PROGRAM,        /* starts a program: SIGSYS                          */
  FILES,          /* changes a file: EACCES while gmsh starts, then SIGSYS */
  DENY,           /* EACCES, quietly (network, ptrace, mounts)         */
  NOSYS           /* ENOSYS: glibc falls back to a call we can inspect  */
};

enum cond { ALWAYS, IF_SET, UNLESS_SET };

typedef struct rule
{
  long nr;
  const char *name;
  enum kind kind;
  const char *what;       /* for the message: "write", "remove", ...    */
  int path;               /* the argument naming a file, or -1          */
  enum cond cond;         /* on the bits `mask` of argument `arg`       */
  int arg;
  unsigned mask;
} rule;

#define WRITES (O_WRONLY | O_RDWR | O_CREAT | O_TRUNC | O_APPEND)
#define R(call, kind, what, path) { SYS_##call, #call, kind, what, path, \
                                    ALWAYS, 0, 0 }
#define OPEN(call, path, arg) { SYS_##call, #call, FILES, "write", path, \
                                IF_SET, arg, WRITES }

static const rule rules[] = {
  R (execve, PROGRAM, "start a program", 0),
  R (execveat, PROGRAM, "start a program", 1),
#ifdef SYS_fork
  R (fork, PROGRAM, "start a program", -1),
  R (vfork, PROGRAM, "start a program", -1),
#endif
  { SYS_clone, "clone", PROGRAM, "start a program", -1, UNLESS_SET, 0,
    CLONE_THREAD },
#ifdef SYS_clone3
  R (clone3, NOSYS, "", -1),
#endif
#ifdef SYS_openat2
  R (openat2, NOSYS, "", -1),
#endif
#ifdef SYS_open
  OPEN (open, 0, 1),
  R (creat, FILES, "write", 0),
  R (mkdir, FILES, "create", 0),
  R (mknod, FILES, "create", 0),
  R (unlink, FILES, "remove", 0),
  R (rmdir, FILES, "remove", 0),
  R (rename, FILES, "rename", 0),
  R (link, FILES, "link", 1),
  R (symlink, FILES, "link", 1),
  R (chmod, FILES, "change", 0),
  R (chown, FILES, "change", 0),
  R (lchown, FILES, "change", 0),
  R (utime, FILES, "change", 0),
  R (utimes, FILES, "change", 0),
  R (futimesat, FILES, "change", 1),
#endif
  OPEN (openat, 1, 2),
  OPEN (open_by_handle_at, -1, 2),
  R (truncate, FILES, "write", 0),
  R (mkdirat, FILES, "create", 1),
  R (mknodat, FILES, "create", 1),
  R (unlinkat, FILES, "remove", 1),
  R (renameat, FILES, "rename", 1),
  R (renameat2, FILES, "rename", 1),
  R (linkat, FILES, "link", 3),
  R (symlinkat, FILES, "link", 2),
  R (fchmod, FILES, "change", -1),
  R (fchmodat, FILES, "change", 1),
  R (fchown, FILES, "change", -1),
  R (fchownat, FILES, "change", 1),
  R (utimensat, FILES, "change", 1),
  R (setxattr, FILES, "change", 0),
  R (lsetxattr, FILES, "change", 0),
  R (fsetxattr, FILES, "change", -1),
  R (removexattr, FILES, "change", 0),
  R (lremovexattr, FILES, "change", 0),
  R (fremovexattr, FILES, "change", -1),
  R (io_uring_setup, NOSYS, "", -1),
  R (socket, DENY, "", -1),
  R (ptrace, DENY, "", -1),
  R (process_vm_writev, DENY, "", -1),
  R (mount, DENY, "", -1),
  R (umount2, DENY, "", -1),
  R (pivot_root, DENY, "", -1),
  R (chroot, DENY, "", -1),
  R (unshare, DENY, "", -1),
  R (setns, DENY, "", -1),
  R (bpf, DENY, "", -1),
};
#define NRULES (sizeof rules / sizeof rules[0])

/* ---------------------------------------------------------------------- */
/* the child: SIGSYS                                                       */
/* ---------------------------------------------------------------------- */

/* Argument k of the call that trapped, from the saved registers. */
static unsigned long
call_arg (const void *context, int k)
{
  const ucontext_t *uc = context;
#if defined(__x86_64__)
  static const int reg[6] = { REG_RDI, REG_RSI, REG_RDX, REG_R10, REG_R8,
                              REG_R9 };
  return (unsigned long) uc->uc_mcontext.gregs[reg[k]];
#elif defined(__aarch64__)
  return (unsigned long) uc->uc_mcontext.regs[k];
#else
  (void) uc, (void) k;
  return 0;
#endif
}

static size_t
put (char *buf, size_t n, size_t size, const char *s, size_t max)
{
  for (size_t k = 0; s[k] && k < max && n + 1 < size; k++)
    buf[n++] = s[k];
  return n;
}

/* "lac-sandbox: write 'x.msh' (openat)" on stderr, then exit. */
static void
on_sigsys (int sig, siginfo_t *si, void *context)
{
  char buf[400];
  const rule *r = NULL;
  const char *path = NULL;
  size_t n = 0;
  (void) sig;
  for (size_t k = 0; k < NRULES && !r; k++)
    if (rules[k].nr == si->si_syscall)
      r = &rules[k];
  if (r && r->path >= 0)
    path = (const char *) call_arg (context, r->path);
  n = put (buf, n, sizeof buf, "\nlac-sandbox: ", 20);
  n = put (buf, n, sizeof buf, r ? r->what : "make a forbidden call", 40);
  if (path)
    {
      n = put (buf, n, sizeof buf, " '", 2);
      n = put (buf, n, sizeof buf, path, 160);
      n = put (buf, n, sizeof buf, "'", 1);
    }
  n = put (buf, n, sizeof buf, " (", 2);
  n = put (buf, n, sizeof buf, r ? r->name : "?", 40);
  n = put (buf, n, sizeof buf, ")\n", 2);
  if (write (2, buf, n) < 0)
    n = 0;
  _exit (LAC_SANDBOX_EXIT);
}

/* ---------------------------------------------------------------------- */
/* the child: the filter                                                   */
/* ---------------------------------------------------------------------- */

#define ARG_LO(k) (offsetof (struct seccomp_data, args) + 8 * (k) \
                   + (__BYTE_ORDER__ == __ORDER_BIG_ENDIAN__ ? 4 : 0))

static unsigned
action (const rule *r, int step)
{
  switch (r->kind)
    {
    case PROGRAM: return SECCOMP_RET_TRAP;
    case FILES: return step == LAC_SANDBOX_INIT
                       ? SECCOMP_RET_ERRNO | EACCES : SECCOMP_RET_TRAP;
    case DENY: return SECCOMP_RET_ERRNO | EACCES;
    default: return SECCOMP_RET_ERRNO | ENOSYS;
    }
}

/* The instructions of one rule at p; returns their number. */
static size_t
rule_code (const rule *r, int step, struct sock_filter *p)
{
  unsigned act = action (r, step);
  if (r->cond == ALWAYS)
    {
      p[0] = (struct sock_filter) BPF_JUMP (BPF_JMP | BPF_JEQ | BPF_K,
                                            (unsigned) r->nr, 0, 1);
      p[1] = (struct sock_filter) BPF_STMT (BPF_RET | BPF_K, act);
      return 2;
    }
  p[0] = (struct sock_filter) BPF_JUMP (BPF_JMP | BPF_JEQ | BPF_K,
                                        (unsigned) r->nr, 0, 4);
  p[1] = (struct sock_filter) BPF_STMT (BPF_LD | BPF_W | BPF_ABS,
                                        ARG_LO (r->arg));
  p[2] = (struct sock_filter) BPF_JUMP (BPF_JMP | BPF_JSET | BPF_K, r->mask,
                                        r->cond == IF_SET ? 0 : 1,
                                        r->cond == IF_SET ? 1 : 0);
  p[3] = (struct sock_filter) BPF_STMT (BPF_RET | BPF_K, act);
  p[4] = (struct sock_filter) BPF_STMT (BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
  return 5;
}

#ifdef ARCH
static int
install (int step)
{
  struct sock_filter code[8 + 5 * NRULES];
  struct sock_fprog prog;
  size_t n = 0;
  code[n++] = (struct sock_filter) BPF_STMT (BPF_LD | BPF_W | BPF_ABS,
                                      offsetof (struct seccomp_data, arch));
  code[n++] = (struct sock_filter) BPF_JUMP (BPF_JMP | BPF_JEQ | BPF_K, ARCH,
                                             1, 0);
  code[n++] = (struct sock_filter) BPF_STMT (BPF_RET | BPF_K,
                                             SECCOMP_RET_KILL_PROCESS);
  code[n++] = (struct sock_filter) BPF_STMT (BPF_LD | BPF_W | BPF_ABS,
                                        offsetof (struct seccomp_data, nr));
#if defined(__x86_64__)                /* x32 calls: numbers | 0x40000000 */
  code[n++] = (struct sock_filter) BPF_JUMP (BPF_JMP | BPF_JGE | BPF_K,
                                             0x40000000u, 0, 1);
  code[n++] = (struct sock_filter) BPF_STMT (BPF_RET | BPF_K,
                                             SECCOMP_RET_KILL_PROCESS);
#endif
  for (size_t k = 0; k < NRULES; k++)
    n += rule_code (&rules[k], step, code + n);
  code[n++] = (struct sock_filter) BPF_STMT (BPF_RET | BPF_K,
                                             SECCOMP_RET_ALLOW);
  prog.len = (unsigned short) n;
  prog.filter = code;
  return (int) syscall (SYS_seccomp, SECCOMP_SET_MODE_FILTER,
                        SECCOMP_FILTER_FLAG_TSYNC, &prog);
}
#else
static int
install (int step)
{
  (void) step;
  errno = ENOSYS;
  return -1;
}
#endif

int
lac_mesh_sandbox_enter (int step)
{
  struct sigaction sa;
  sigset_t set;
  memset (&sa, 0, sizeof sa);
  sa.sa_sigaction = on_sigsys;
  sa.sa_flags = SA_SIGINFO;
  sigemptyset (&sa.sa_mask);
  sigemptyset (&set);
  sigaddset (&set, SIGSYS);
  if (sigaction (SIGSYS, &sa, NULL) != 0
      || sigprocmask (SIG_UNBLOCK, &set, NULL) != 0
      || prctl (PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 || install (step) != 0)
    return lac_error_set (LAC_EDEP, "lac_mesh_read", "cannot shut gmsh in "
                          "(seccomp: %s): lac does not run gmsh without its "
                          "sandbox (chapter 01, bad-input.md)",
                          strerror (errno));
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* the parent                                                              */
/* ---------------------------------------------------------------------- */

/* A forbidden call made with every signal blocked (posix_spawn, behind
 * system (), blocks them before it clones) cannot run the handler: the
 * kernel kills the child with SIGSYS, and what it tried is left unsaid;
 * in gmsh that is SystemCall and its kin. */
int
lac_mesh_sandbox_verdict (int ws, const char *talk, const char *verb,
                          const char *path)
{
  const char *said = strstr (talk, "lac-sandbox: ");
  const char *who = verb[0] == 'm' ? "the script" : "gmsh";
  size_t len;
  if (WIFSIGNALED (ws) && WTERMSIG (ws) == SIGSYS && !said)
    return lac_error_set (LAC_EIO, "lac_mesh_read", "gmsh could not %s "
                          "'%s': killed by signal %d (%s): %s tried to start "
                          "a program: SystemCall, NonBlockingSystemCall and "
                          "OnelabRun are not allowed", verb, path, SIGSYS,
                          strsignal (SIGSYS), who);
  if (!WIFEXITED (ws) || WEXITSTATUS (ws) != LAC_SANDBOX_EXIT || !said)
    return LAC_SUCCESS;
  said += 13;
  len = strcspn (said, "\n");
  if (strncmp (said, "start", 5) == 0)
    return lac_error_set (LAC_EIO, "lac_mesh_read", "gmsh could not %s "
                          "'%s': %s tried to %.*s: SystemCall, "
                          "NonBlockingSystemCall and OnelabRun are not "
                          "allowed", verb, path, who, (int) len, said);
  return lac_error_set (LAC_EIO, "lac_mesh_read", "gmsh could not %s '%s': "
                        "%s tried to %.*s: writes outside lac's output are "
                        "not allowed (Save, Print, Printf > FILE, "
                        "CreateDir)", verb, path, who, (int) len, said);
}
