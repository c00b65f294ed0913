/* t032: every allocation failure in box meshes, groups and gmsh reading is
 * reported as LAC_ENOMEM, leaks nothing and leaves no mesh  [LAC §2] */
#include "check.h"
#include "base/lac_mem.h"
#include "io/lac_mesh_gmsh.h"
#include "base/lac_status.h"

typedef int (*make_fn) (lac_mesh **m);

static int
make_box (lac_mesh **m)
{
  size_t n[3] = { 2, 1, 1 };
  double L[3] = { 1, 1, 1 };
  return lac_mesh_box (LAC_TET10, n, L, 0.1, m);
}

static int
make_read (lac_mesh **m)
{
  lac_mesh_opts o = { 0 };
  o.flip_inverted = 1;
  return lac_mesh_read ("tests/meshes/clockwise.geo", &o, m);
}

static int
make_read3 (lac_mesh **m)
{
  return lac_mesh_read ("tests/meshes/box-v41.msh", NULL, m);
}

/* Fail the k-th allocation for k = 0, 1, ... until the call succeeds. */
static void
sweep (make_fn make, const char *what)
{
  int bad = 0;
  long k;
  for (k = 0; k < 10000; k++)
    {
      lac_mesh *m = (lac_mesh *) 1;
      int status;
      lac_mem_fail_after (k);
      status = make (&m);
      lac_mem_fail_after (-1);
      if (status == LAC_SUCCESS)
        {
          lac_mesh_free (m);
          break;
        }
      if (status != LAC_ENOMEM || m != NULL)
        {
          check_status (status, LAC_ENOMEM, "%s: allocation %ld fails", what,
                        k);
          bad++;
        }
    }
  check_true (k > 5 && k < 10000, "%s: succeeds after %ld allocations", what,
              k);
  check_int (bad, 0, "%s: every failure is LAC_ENOMEM", what);
}

int
main (void)
{
  sweep (make_box, "box");
  sweep (make_read, "read clockwise.geo");
  sweep (make_read3, "read box-v41.msh");
  return check_summary ();
}
