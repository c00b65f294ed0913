/* bench_mesh_read -- what reading gmsh meshes at arm's length costs
 *                                                            [LAC §2; ch. 01]
 *
 * Build:        make build/bench/bench_mesh_read
 * Sample run:   build/bench/bench_mesh_read [FILE.msh ...]
 * Description:  lac_mesh_read runs gmsh in a child process and takes the
 *               mesh back through a pipe (io/lac_mesh_child.h).  Three
 *               rows per size:
 *                 child   lac_mesh_child_run on a reader that builds a box
 *                         mesh of that size with lac_mesh_box, minus the
 *                         time of the same lac_mesh_box in this process:
 *                         the cost of the fork, the pipe and the checks on
 *                         arrival, alone;
 *                 read    lac_mesh_read of bench/box-n.geo meshed with
 *                         the same 2n x n squares cut in triangles: the
 *                         whole read (gmsh start, meshing, copy, checks);
 *                 msh     lac_mesh_read of each FILE.msh given (saved from
 *                         gmsh), and the share of lac_msh_check (the line
 *                         by line check) in it.
 *               Times are the median of REPEAT (5) runs, wall clock.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_clock.h"
#include "base/lac_status.h"
#include "fem/lac_mesh_check.h"
#include "io/lac_mesh_child.h"
#include "io/lac_mesh_gmsh.h"
#include "io/lac_mesh_msh_check.h"

#define REPEAT 5

static size_t box_n[2];

static int
make_box (void *arg, lac_mesh **out)
{
  size_t n[3] = { box_n[0], box_n[1], 1 };
  double L[3] = { 2, 1, 1 };
  (void) arg;
  return lac_mesh_box (LAC_TRI3, n, L, 0, out);
}

static int
cmp_double (const void *a, const void *b)
{
  double x = *(const double *) a, y = *(const double *) b;
  return (x > y) - (x < y);
}

/* Median time of REPEAT calls of what (0: box here, 1: box in a child,
 * 2: lac_mesh_read of path with numbers, 3: lac_msh_check of path). */
static double
timed (int what, const char *path, const char *numbers, size_t *nnodes)
{
  double t[REPEAT];
  for (int r = 0; r < REPEAT; r++)
    {
      lac_mesh *m = NULL;
      lac_mesh_opts o = { 0 };
      int status;
      double t0 = lac_seconds ();
      o.numbers = numbers;
      if (what == 0)
        status = make_box (NULL, &m);
      else if (what == 1)
        status = lac_mesh_child_run ("read", "box", make_box, NULL, 0, 0, &m);
      else if (what == 2)
        status = lac_mesh_read (path, &o, &m);
      else
        status = lac_msh_check (path, 8e9, NULL);
      t[r] = lac_seconds () - t0;
      if (status)
        {
          fprintf (stderr, "bench_mesh_read: %s\n", lac_error_message ());
          exit (1);
        }
      if (m)
        *nnodes = m->nnodes;
      lac_mesh_free (m);
    }
  qsort (t, REPEAT, sizeof *t, cmp_double);
  return t[REPEAT / 2];
}

int
main (int argc, char **argv)
{
  static const size_t sizes[] = { 2, 40, 160, 320 };
  lac_init ();
  printf ("%-6s %-30s %9s %10s %10s %7s\n", "row", "what", "nodes",
          "total ms", "extra ms", "extra");
  for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++)
    {
      size_t nodes = 0;
      char numbers[32];
      double here, child, read;
      box_n[0] = 2 * sizes[k];
      box_n[1] = sizes[k];
      snprintf (numbers, sizeof numbers, "n=%zu", sizes[k]);
      here = timed (0, NULL, NULL, &nodes);
      child = timed (1, NULL, NULL, &nodes);
      printf ("%-6s %-30s %9zu %10.2f %10.2f %6.0f%%\n", "child",
              "fork + pipe of a box mesh", nodes, 1e3 * child,
              1e3 * (child - here), 100 * (child - here) / child);
      read = timed (2, "bench/box-n.geo", numbers, &nodes);
      printf ("%-6s box-n.geo, %-20s %9zu %10.2f %10.2f %6.0f%%\n",
              "read", numbers, nodes, 1e3 * read, 1e3 * (child - here),
              100 * (child - here) / read);
    }
  for (int i = 1; i < argc; i++)
    {
      size_t nodes = 0;
      double read = timed (2, argv[i], NULL, &nodes);
      double check = timed (3, argv[i], NULL, &nodes);
      printf ("%-6s %-30.30s %9zu %10.2f %10.2f %6.0f%%\n", "msh", argv[i],
              nodes, 1e3 * read, 1e3 * check, 100 * check / read);
    }
  lac_finalize ();
  return 0;
}
