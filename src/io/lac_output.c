/* lac_output.c -- VTU, CSV and summary files; batches of files that
 * appear together (see lac_output.h).
 *
 * References: VTK file formats, "VTK XML formats: UnstructuredGrid"
 * (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html).
 */
#include "io/lac_output.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "base/lac_mem.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"

static const char *const stress_plane[] = { "xx", "yy", "zz", "xy" };
static const char *const stress_axi[] = { "rr", "zz", "tt", "rz" };
static const char *const stress_3d[] = { "xx", "yy", "zz", "xy", "yz", "zx" };

const char *const *
lac_output_stress_names (lac_model model)
{
  return model == LAC_AXISYMMETRIC ? stress_axi
         : model == LAC_SOLID3D ? stress_3d : stress_plane;
}

/* Close f and turn a write error into a message. */
static int
close_checked (FILE *f, const char *path)
{
  int bad = ferror (f);
  if (fclose (f) != 0 || bad)
    LAC_ERROR (LAC_EIO, "cannot write '%s' (%s)", path, strerror (errno));
  return LAC_SUCCESS;
}

static int
check_fields (const lac_output_fields *f)
{
  if (!f || !f->mesh || !f->u)
    LAC_ERROR (LAC_EINVAL, "no mesh or no displacement to write");
  return LAC_SUCCESS;
}

/* ---- VTU -------------------------------------------------------------- */

/* A point-data array of ncomp components taken from v (stride, first). */
static void
vtu_point_array (FILE *fp, const char *name, size_t n, int ncomp,
                 const double *v, int stride, int first)
{
  fprintf (fp, "        <DataArray type=\"Float64\" Name=\"%s\"", name);
  if (ncomp > 1)
    fprintf (fp, " NumberOfComponents=\"%d\"", ncomp);
  fprintf (fp, " format=\"ascii\">\n");
  for (size_t a = 0; a < n; a++)
    {
      fprintf (fp, "         ");
      for (int k = 0; k < ncomp; k++)
        fprintf (fp, " %.10e", (first + k < stride)
                 ? v[a * (size_t) stride + (size_t) (first + k)] : 0.0);
      fprintf (fp, "\n");
    }
  fprintf (fp, "        </DataArray>\n");
}

static void
vtu_points (FILE *fp, const lac_mesh *m)
{
  fprintf (fp, "      <Points>\n");
  vtu_point_array (fp, "coordinates", m->nnodes, 3, m->x, m->dim, 0);
  fprintf (fp, "      </Points>\n");
}

static int
vtu_cells (FILE *fp, const lac_mesh *m)
{
  size_t off = 0;
  fprintf (fp, "      <Cells>\n        <DataArray type=\"Int64\" "
           "Name=\"connectivity\" format=\"ascii\">\n");
  for (size_t c = 0; c < m->ncells; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      if (!re)
        LAC_ERROR (LAC_ESANITY, "cell %zu has no reference element", c);
      fprintf (fp, "         ");
      for (int k = 0; k < re->nnodes; k++)      /* VTK node k = gmsh node */
        fprintf (fp, " %d", m->conn[m->ptr[c] + (size_t) re->vtk_perm[k]]);
      fprintf (fp, "\n");
    }
  fprintf (fp, "        </DataArray>\n        <DataArray type=\"Int64\" "
           "Name=\"offsets\" format=\"ascii\">\n");
  for (size_t c = 0; c < m->ncells; c++)
    {
      off += m->ptr[c + 1] - m->ptr[c];
      fprintf (fp, "          %zu\n", off);
    }
  fprintf (fp, "        </DataArray>\n        <DataArray type=\"UInt8\" "
           "Name=\"types\" format=\"ascii\">\n");
  for (size_t c = 0; c < m->ncells; c++)
    fprintf (fp, "          %d\n", lac_refelem_get (m->type[c])->vtk_type);
  fprintf (fp, "        </DataArray>\n      </Cells>\n");
  return LAC_SUCCESS;
}

static void
vtu_point_data (FILE *fp, const lac_output_fields *f)
{
  const lac_mesh *m = f->mesh;
  int ns = lac_model_nstress (f->model);
  const char *const *names = lac_output_stress_names (f->model);
  char name[32];
  fprintf (fp, "      <PointData Vectors=\"displacement\"%s>\n",
           f->vm ? " Scalars=\"von_mises\"" : "");
  vtu_point_array (fp, "displacement", m->nnodes, 3, f->u, m->dim, 0);
  if (f->u_exact)
    vtu_point_array (fp, "displacement_exact", m->nnodes, 3, f->u_exact,
                     m->dim, 0);
  for (int k = 0; f->sigma && k < ns; k++)
    {
      snprintf (name, sizeof name, "stress_%s", names[k]);
      vtu_point_array (fp, name, m->nnodes, 1, f->sigma, ns, k);
    }
  if (f->vm)
    vtu_point_array (fp, "von_mises", m->nnodes, 1, f->vm, 1, 0);
  fprintf (fp, "      </PointData>\n");
}

static void
vtu_cell_data (FILE *fp, const lac_mesh *m)
{
  fprintf (fp, "      <CellData Scalars=\"body\">\n        <DataArray "
           "type=\"Int32\" Name=\"body\" format=\"ascii\">\n");
  for (size_t c = 0; c < m->ncells; c++)
    fprintf (fp, "          %d\n", m->body ? m->body[c] : 0);
  fprintf (fp, "        </DataArray>\n      </CellData>\n");
}

/* lac_output_vtu: write the mesh and the nodal fields as a VTU file. */
int
lac_output_vtu (const char *path, const lac_output_fields *f)
{
  FILE *fp;
  int status;
  if ((status = check_fields (f)))
    return status;
  if (!(fp = fopen (path, "w")))
    LAC_ERROR (LAC_EIO, "cannot create '%s' (%s)", path, strerror (errno));
  fprintf (fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\""
           " version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n  <UnstructuredGrid>\n"
           "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n",
           f->mesh->nnodes, f->mesh->ncells);
  vtu_points (fp, f->mesh);
  status = vtu_cells (fp, f->mesh);
  vtu_point_data (fp, f);
  vtu_cell_data (fp, f->mesh);
  fprintf (fp, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  if (status)
    {
      fclose (fp);
      return status;
    }
  return close_checked (fp, path);
}

/* ---- CSV -------------------------------------------------------------- */

/* lac_output_csv: one row per node: node tag, coordinates (always x, y, z;
 * r, z, theta for the axisymmetric model), displacement, stress, vm. */
int
lac_output_csv (const char *path, const lac_output_fields *f)
{
  const lac_mesh *m;
  const char *const *names;
  int ns, dim, status, axi;
  FILE *fp;
  if ((status = check_fields (f)))
    return status;
  m = f->mesh;
  dim = m->dim;
  ns = lac_model_nstress (f->model);
  names = lac_output_stress_names (f->model);
  axi = f->model == LAC_AXISYMMETRIC;
  if (!(fp = fopen (path, "w")))
    LAC_ERROR (LAC_EIO, "cannot create '%s' (%s)", path, strerror (errno));
  fprintf (fp, axi ? "node,r,z,theta,u_r,u_z" : dim == 2
           ? "node,x,y,z,u_x,u_y" : "node,x,y,z,u_x,u_y,u_z");
  for (int k = 0; f->sigma && k < ns; k++)
    fprintf (fp, ",s_%s", names[k]);
  fprintf (fp, "%s\n", f->vm ? ",von_mises" : "");
  for (size_t a = 0; a < m->nnodes; a++)
    {
      fprintf (fp, "%zu", m->node_tag ? m->node_tag[a] : a + 1);
      for (int k = 0; k < 3; k++)
        fprintf (fp, ",%.10e", k < dim ? m->x[a * (size_t) dim + (size_t) k]
                 : 0.0);
      for (int k = 0; k < dim; k++)
        fprintf (fp, ",%.10e", f->u[a * (size_t) dim + (size_t) k]);
      for (int k = 0; f->sigma && k < ns; k++)
        fprintf (fp, ",%.10e", f->sigma[a * (size_t) ns + (size_t) k]);
      if (f->vm)
        fprintf (fp, ",%.10e", f->vm[a]);
      fprintf (fp, "\n");
    }
  return close_checked (fp, path);
}

/* ---- summary ---------------------------------------------------------- */

int
lac_output_summary (const char *path, size_t n, const char *const *key,
                    const char *const *val)
{
  FILE *fp = fopen (path, "w");
  if (!fp)
    LAC_ERROR (LAC_EIO, "cannot create '%s' (%s)", path, strerror (errno));
  for (size_t k = 0; k < n; k++)
    fprintf (fp, "%s = %s\n", key[k], val[k]);
  return close_checked (fp, path);
}
