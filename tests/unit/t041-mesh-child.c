/* t041: a mesh reader in a child process: whatever the reader does there
 * (crash, abort, exit, loop, eat memory, talk) is one status and one
 * message here; the mesh crosses the pipe intact, and a stream cut short
 * at any byte is an error, never a smaller mesh                  [LAC §2] */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_mesh_check.h"
#include "io/lac_mesh_child.h"
#include "io/lac_mesh_wire.h"

/* Under AddressSanitizer, LeakSanitizer checks for leaks when a process
 * calls exit() and changes its exit status when it finds any (the reader
 * below leaves its memory to the exit, as gmsh does). */
#if defined(__SANITIZE_ADDRESS__)
#define EXIT2 "it exited with status"
#define EXIT0 "gmsh could not read 'bad.msh'"
#else
#define EXIT2 "it exited with status 2"
#define EXIT0 "no mesh came back"
#endif

static int
make_box (void *arg, lac_mesh **out)
{
  size_t n[3] = { 2, 3, 1 };
  double L[3] = { 1, 2, 1 };
  (void) arg;
  return lac_mesh_box (LAC_TET10, n, L, 0.1, out);
}

static int
crash (void *arg, lac_mesh **out)
{
  (void) out;
  raise (*(int *) arg);
  return LAC_SUCCESS;
}

static int
leave (void *arg, lac_mesh **out)
{
  (void) out;
  fprintf (stderr, "Fatal   : syntax error, bye\n");
  exit (*(int *) arg);
}

static int
loop (void *arg, lac_mesh **out)
{
  (void) arg;
  (void) out;
  while (pause () < 0 || 1)
    ;
  return LAC_SUCCESS;
}

#if !defined(__SANITIZE_ADDRESS__)
/* Grow until the limit stops us, as gmsh does with a huge count. */
static int
eat (void *arg, lac_mesh **out)
{
  (void) arg;
  (void) out;
  for (;;)
    {
      char *p = malloc (1 << 24);
      if (!p)
        {
          fputs ("std::bad_alloc\n", stderr);
          abort ();
        }
      memset (p, 1, 1 << 24);
    }
}
#endif

static int
refuse (void *arg, lac_mesh **out)
{
  (void) arg;
  (void) out;
  return lac_error_set (LAC_EINVAL, "lac_mesh_read", "'x.msh': element 7 "
                        "has 4 nodes, expected 3");
}

/* Two meshes are the same, array by array. */
static int
same_mesh (const lac_mesh *a, const lac_mesh *b)
{
  size_t nc = a->ptr[a->ncells];
  int same = a->dim == b->dim && a->nnodes == b->nnodes
             && a->ncells == b->ncells && a->ngroups == b->ngroups
             && b->ptr[b->ncells] == nc;
  same = same && !memcmp (a->x, b->x, a->nnodes * (size_t) a->dim
                          * sizeof *a->x)
         && !memcmp (a->conn, b->conn, nc * sizeof *a->conn)
         && !memcmp (a->type, b->type, a->ncells * sizeof *a->type)
         && !memcmp (a->body, b->body, a->ncells * sizeof *a->body);
  for (size_t g = 0; same && g < a->ngroups; g++)
    {
      const lac_group *A = &a->group[g], *B = &b->group[g];
      same = !strcmp (A->name, B->name) && A->dim == B->dim && A->n == B->n
             && A->nnodes == B->nnodes
             && !memcmp (A->cell, B->cell, A->n * sizeof *A->cell)
             && !memcmp (A->node, B->node, A->nnodes * sizeof *A->node)
             && (!A->face) == (!B->face)
             && (!A->face || !memcmp (A->face, B->face,
                                      A->n * sizeof *A->face));
    }
  return same;
}

static void
good_path (void)
{
  lac_mesh *m = NULL, *ref = NULL;
  int status = lac_mesh_child_run ("read", "box", make_box, NULL, 0, 10, &m);
  check_status (status, LAC_SUCCESS, "child: a box mesh comes back");
  check_status (make_box (NULL, &ref), LAC_SUCCESS, "box here");
  if (m && ref)
    {
      check_true (same_mesh (m, ref), "child: the mesh is the same, array "
                  "by array");
      check_status (lac_mesh_validate (m), LAC_SUCCESS, "child: valid");
      check_status (lac_mesh_check_topology (m), LAC_SUCCESS, "child: a "
                    "mesh");
    }
  lac_mesh_free (m);
  lac_mesh_free (ref);
}

/* Every way the reader may end badly. */
static void
bad_endings (void)
{
  static const struct
  {
    lac_mesh_child_fn fn;
    int arg, status;
    double mem, sec;
    const char *words;
  } t[] = {
    { crash, SIGSEGV, LAC_EIO, 0, 10, "killed by signal 11" },
    { crash, SIGABRT, LAC_EIO, 0, 10, "killed by signal 6" },
    { crash, SIGBUS, LAC_EIO, 0, 10, "malformed or truncated" },
    { leave, 2, LAC_EIO, 0, 10, EXIT2 },
    { leave, 0, LAC_EIO, 0, 10, EXIT0 },
    { loop, 0, LAC_EMAXITER, 0, 1, "time limit of 1 s" },
    { refuse, 0, LAC_EINVAL, 0, 10, "element 7 has 4 nodes" },
  };
  for (size_t k = 0; k < sizeof t / sizeof t[0]; k++)
    {
      lac_mesh *m = (lac_mesh *) 1;
      int arg = t[k].arg;
      int status = lac_mesh_child_run ("read", "bad.msh", t[k].fn, &arg,
                                       t[k].mem, t[k].sec, &m);
      check_status (status, t[k].status, "ending %zu", k);
      check_message (t[k].words, "ending %zu", k);
      check_true (m == NULL, "ending %zu: no mesh", k);
      check_true (strchr (lac_error_message (), '\n') == NULL,
                  "ending %zu: one line", k);
    }
}

/* The memory limit (not under AddressSanitizer, see lac_mesh_child.h). */
static void
memory_limit (void)
{
#if !defined(__SANITIZE_ADDRESS__)
  lac_mesh *m = NULL;
  int status = lac_mesh_child_run ("read", "huge.msh", eat, NULL, 2e8, 60,
                                   &m);
  check_status (status, LAC_ENOMEM, "eat: out of memory");
  check_message ("out of memory (limit 0.2 GB", "eat");
#endif
}

/* The stream cut at every length, and one byte changed in the header. */
static void
wire_cut (void)
{
  lac_mesh *m = NULL;
  int fd[2], status, st, bad = 0;
  unsigned char *buf = lac_malloc (1 << 20);
  char msg[64];
  ssize_t len;
  make_box (NULL, &m);
  if (!buf || !m || pipe (fd) != 0)
    {
      check_true (0, "wire: set-up");
      return;
    }
  lac_mesh_wire_write (fd[1], LAC_SUCCESS, NULL, m);
  close (fd[1]);
  len = read (fd[0], buf, 1 << 20);
  close (fd[0]);
  lac_mesh_free (m);
  check_true (len > 1000 && len < (1 << 20), "wire: %zd bytes", len);
  for (ssize_t n = 0; n < len; n++)
    {
      st = lac_mesh_wire_read (buf, (size_t) n, &status, msg, sizeof msg, &m);
      bad += st != LAC_EIO || m != NULL;
      lac_mesh_free (m);
    }
  check_int (bad, 0, "wire: cut short at every byte is LAC_EIO");
  st = lac_mesh_wire_read (buf, (size_t) len, &status, msg, sizeof msg, &m);
  check_true (st == LAC_SUCCESS && status == LAC_SUCCESS && m,
              "wire: whole stream");
  lac_mesh_free (m);
  /* magic, status, message length, dim, then a high byte of nnodes */
  buf[8 + sizeof (int) + sizeof (size_t) + sizeof (int) + 4] ^= 0x40;
  st = lac_mesh_wire_read (buf, (size_t) len, &status, msg, sizeof msg, &m);
  check_true (st != LAC_SUCCESS && !m, "wire: a wrong count is refused");
  lac_free (buf);
}

int
main (void)
{
  good_path ();
  bad_endings ();
  memory_limit ();
  wire_cut ();
  return check_summary ();
}
