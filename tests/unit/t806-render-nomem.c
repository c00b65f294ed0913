/* t806: every allocation failure in rendering and in reading a VTU back is
 * reported as LAC_ENOMEM and leaks nothing (run under ASan: make test-asan)
 *
 * The k-th allocation through lac_malloc fails, k = 0, 1, ... until the
 * call succeeds: a 2D quad8 mesh with a field, the boundary of a hex20
 * mesh with facets and discs, the VTU reader.  Small images keep it fast.
 */
#include <string.h>
#include "check.h"
#include "base/lac_mem.h"
#include "io/lac_output.h"
#include "render/lac_render.h"
#include "base/lac_status.h"
#include "t8-render.h"

static lac_mesh *m2, *m3;
static double *f2, *v3, *xyz, *sig;
static unsigned char *img;
static lac_render_opts opts;
static const char *vtu;

static int
draw_2d (void)
{
  return lac_render_mesh_rgba (m2, f2, f2, &opts, img);
}

static int
draw_3d (void)
{
  const lac_group *g = lac_mesh_group (m3, "zmax");
  int status = lac_render_mesh_rgba (m3, NULL, m3->x, &opts, img);
  if (!status)
    status = lac_render_facets_rgba (m3, NULL, g->n, g->cell, g->face, v3,
                                     &opts, img);
  if (!status)
    status = lac_render_points_rgba (m3, NULL, g->n, xyz, NULL, v3, &opts,
                                     img);
  return status;
}

static int
read_vtu (void)
{
  lac_render_result *r = NULL;
  int status = lac_render_result_read (vtu, &r);
  double *s = status ? NULL : lac_malloc (r->mesh->nnodes * sizeof *s);
  if (!status && !s)
    status = LAC_ENOMEM;
  if (!status)
    status = lac_render_result_scalar (r, "radial_stress", s);
  lac_free (s);
  lac_render_result_free (r);
  return status;
}

static void
sweep (int (*fn) (void), const char *what)
{
  int bad = 0;
  long k;
  for (k = 0; k < 100000; k++)
    {
      int status;
      lac_mem_fail_after (k);
      status = fn ();
      lac_mem_fail_after (-1);
      if (status == LAC_SUCCESS)
        break;
      if (status != LAC_ENOMEM && !bad++)
        check_status (status, LAC_ENOMEM, "%s: failing allocation %ld", what,
                      k);
    }
  check_int (bad, 0, "%s: every failure is LAC_ENOMEM", what);
  check_true (k > 2, "%s: %ld allocations swept", what, k);
}

int
main (void)
{
  size_t n2[2] = { 2, 1 }, n3[3] = { 2, 1, 1 };
  double L[3] = { 2, 1, 1 };
  const lac_group *g;
  lac_output_fields f;
  lac_init ();
  lac_render_opts_init (&opts);
  opts.width = opts.height = 64;
  opts.supersample = 1;
  opts.edges = 1;
  img = lac_malloc (64 * 64 * 4);
  lac_mesh_box (LAC_QUAD8, n2, L, 0.1, &m2);
  lac_mesh_box (LAC_HEX20, n3, L, 0.1, &m3);
  f2 = lac_malloc (2 * m2->nnodes * sizeof *f2);
  for (size_t a = 0; a < 2 * m2->nnodes; a++)
    f2[a] = 0.01 * (double) a;
  sig = lac_malloc (4 * m2->nnodes * sizeof *sig);
  for (size_t a = 0; a < 4 * m2->nnodes; a++)
    sig[a] = 1.0 + (double) a;
  g = lac_mesh_group (m3, "zmax");
  v3 = lac_malloc (g->n * sizeof *v3);
  xyz = lac_calloc (3 * g->n, sizeof *xyz);
  for (size_t k = 0; k < g->n; k++)
    {
      v3[k] = (double) k;
      xyz[3 * k] = 0.5 + (double) k;
      xyz[3 * k + 1] = 0.5;
      xyz[3 * k + 2] = 1;
    }
  sweep (draw_2d, "2D mesh");
  sweep (draw_3d, "3D boundary, facets, discs");

  vtu = t8_path ("t806.vtu");
  memset (&f, 0, sizeof f);
  f.mesh = m2;
  f.model = LAC_PLANE_STRAIN;
  f.u = f2;
  f.sigma = sig;
  f.vm = f2;
  check_status (lac_output_vtu (vtu, &f), LAC_SUCCESS, "write %s", vtu);
  sweep (read_vtu, "VTU reader");

  lac_free (f2);
  lac_free (sig);
  lac_free (v3);
  lac_free (xyz);
  lac_free (img);
  lac_mesh_free (m2);
  lac_mesh_free (m3);
  return check_summary ();
}
