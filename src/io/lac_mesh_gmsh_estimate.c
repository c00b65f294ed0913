/* lac_mesh_gmsh_estimate.c -- the size of a .geo mesh before it is made
 *                                                 (lac_mesh_gmsh_estimate.h)
 *
 *   h      = total length of the 1D segments / their number;
 *   nodes  = c_d * sum over the entities of dimension d of
 *            measure(bounding box) / h^d, times 2^d for order 2,
 *            c_2 = 2/sqrt(3) (vertices per h^2 of equilateral triangles),
 *            c_3 = 1.4 (vertices per h^3 of a Delaunay tetrahedral mesh);
 *   bytes  = 1e8 + 4e3 nodes (2D), 1e8 + 1.2e3 k nodes^(4/3) (3D, k = 2 for
 *            order 2): the process itself, then lac's measured peaks.
 */
#include "io/lac_mesh_gmsh_estimate.h"

#include <gmshc.h>
#include <math.h>
#include <stdint.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "io/lac_mesh_gmsh_cells.h"

/* Number and total length of the segments of the 1D mesh. */
static int
segments (lac_gmsh_reader *R, double *nseg, double *len)
{
  lac_gmsh_elements E;
  int status = lac_gmsh_read_nodes (R);
  *nseg = *len = 0;
  if (!status)
    status = lac_gmsh_get_elements (R, &E, 1, -1);
  for (size_t i = 0; !status && i < E.ntypes; i++)
    {
      size_t ne = E.etags_n[i], nn = ne ? E.ntags_n[i] / ne : 0;
      for (size_t j = 0; nn >= 2 && j < ne; j++)
        {
          size_t a = lac_gmsh_tag_position (R, E.ntags[i][j * nn]);
          size_t b = lac_gmsh_tag_position (R, E.ntags[i][j * nn + 1]);
          double d2 = 0;
          if (a == SIZE_MAX || b == SIZE_MAX)
            continue;
          for (int k = 0; k < 3; k++)
            d2 += pow (R->coord[3 * a + k] - R->coord[3 * b + k], 2);
          *len += sqrt (d2);
          *nseg += 1;
        }
    }
  if (!status)
    lac_gmsh_elements_free (&E);
  lac_free (R->tag), lac_free (R->index), lac_free (R->coord);
  R->tag = R->index = NULL;
  R->coord = NULL;
  R->nall = 0;
  return status;
}

/* Sum over the entities of dimension dim of the measure of their
 * bounding boxes (the dim largest extents multiplied). */
static int
box_measure (lac_gmsh_reader *R, int dim, double *measure)
{
  int *dimtags = NULL, ierr = 0;
  size_t n = 0;
  *measure = 0;
  gmshModelGetEntities (&dimtags, &n, dim, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "cannot get the entities");
  for (size_t e = 0; e + 1 < n; e += 2)
    {
      double lo[3], hi[3], ext[3], m = 1;
      gmshModelGetBoundingBox (dim, dimtags[e + 1], &lo[0], &lo[1], &lo[2],
                               &hi[0], &hi[1], &hi[2], &ierr);
      if (ierr)
        continue;
      for (int k = 0; k < 3; k++)
        ext[k] = isfinite (hi[k] - lo[k]) && hi[k] > lo[k] ? hi[k] - lo[k] : 0;
      for (int i = 0; i < 3; i++)              /* largest first */
        for (int j = i + 1; j < 3; j++)
          if (ext[j] > ext[i])
            {
              double t = ext[i];
              ext[i] = ext[j];
              ext[j] = t;
            }
      for (int k = 0; k < dim; k++)
        m *= ext[k];
      *measure += m;
    }
  gmshFree (dimtags);
  return LAC_SUCCESS;
}

/* lac_gmsh_estimate: see lac_mesh_gmsh_estimate.h. */
int
lac_gmsh_estimate (lac_gmsh_reader *R, int dim, double *nodes, double *bytes)
{
  double nseg, len, measure, h;
  int ierr = 0, status, order2 = R->opts->order == 2;
  *nodes = *bytes = 0;
  gmshModelMeshGenerate (1, &ierr);
  if (ierr)
    return lac_gmsh_fail (R, LAC_EDEP, "meshing the curves failed");
  if ((status = segments (R, &nseg, &len))
      || (status = box_measure (R, dim, &measure)))
    return status;
  if (nseg < 1 || len <= 0)
    return LAC_SUCCESS;
  h = len / nseg;
  *nodes = (dim == 2 ? 2 / sqrt (3) : 1.4) * measure / pow (h, dim)
           * (order2 ? pow (2, dim) : 1);
  *bytes = 1e8 + (dim == 2 ? 4e3 * *nodes
                  : 1.2e3 * (order2 ? 2 : 1) * pow (*nodes, 4.0 / 3));
  return LAC_SUCCESS;
}

/* lac_gmsh_estimate_check: see lac_mesh_gmsh_estimate.h. */
int
lac_gmsh_estimate_check (lac_gmsh_reader *R, int dim)
{
  const lac_mesh_opts *o = R->opts;
  double nodes, bytes;
  int status = lac_gmsh_estimate (R, dim, &nodes, &bytes);
  if (status || o->max_memory <= 0 || bytes <= o->max_memory)
    return status;
  return READ_ERR (LAC_EINVAL, "'%s': level = %d, size = %g: an estimated "
                   "%.2g nodes, which need about %.3g GB of memory, more "
                   "than the limit of %.3g GB (--max-memory)", R->path,
                   o->level, o->size > 0 ? o->size : 1, nodes, bytes / 1e9,
                   o->max_memory / 1e9);
}
