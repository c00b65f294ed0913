/* lac_output.c -- VTU, CSV and summary files; batches of files that
 * appear together (see lac_output.h).
 *
 * References: VTK file formats, "VTK XML formats: UnstructuredGrid"
 * (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html).
 */
#include "io/lac_output.h"

#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>
#include "base/lac_file.h"
#include "base/lac_mem.h"
#include "fem/lac_spaces.h"
#include "base/lac_status.h"
#include "io/lac_vtu.h"

static const char *const stress_plane[] = { "xx", "yy", "zz", "xy" };
static const char *const stress_axi[] = { "rr", "zz", "tt", "rz" };
static const char *const stress_3d[] = { "xx", "yy", "zz", "xy", "yz", "zx" };

const char *const *
lac_output_stress_names (lac_model model)
{
  return model == LAC_AXISYMMETRIC ? stress_axi
         : model == LAC_SOLID3D ? stress_3d : stress_plane;
}

static int
check_fields (const lac_output_fields *f)
{
  if (!f || !f->mesh || !f->u)
    LAC_ERROR (LAC_EINVAL, "no mesh or no displacement to write");
  return LAC_SUCCESS;
}

/* ---- VTU -------------------------------------------------------------- */

/* The cells of m in VTK node order (io/lac_vtu.h). */
static int
vtu_cells (lac_vtu *v, const lac_mesh *m)
{
  size_t nc = m->ncells, nconn = m->ptr[nc];
  long *conn = lac_malloc ((nconn + 1) * sizeof *conn);
  long *off = lac_malloc ((nc + 1) * sizeof *off);
  unsigned char *types = lac_malloc (nc + 1);
  int status = conn && off && types ? LAC_SUCCESS
               : LAC_ERRMSG (LAC_ENOMEM, "VTU cells of %zu cells", nc);
  for (size_t c = 0; c < nc && !status; c++)
    {
      const lac_refelem *re = lac_refelem_get (m->type[c]);
      if (!re)
        {
          status = LAC_ERRMSG (LAC_ESANITY, "cell %zu has no reference "
                               "element", c);
          break;
        }
      for (int k = 0; k < re->nnodes; k++)      /* VTK node k = gmsh node */
        conn[m->ptr[c] + (size_t) k] =
          m->conn[m->ptr[c] + (size_t) re->vtk_perm[k]];
      off[c] = (long) m->ptr[c + 1];
      types[c] = (unsigned char) re->vtk_type;
    }
  if (!status)
    status = lac_vtu_cells (v, conn, off, types);
  lac_free (conn);
  lac_free (off);
  lac_free (types);
  return status;
}

static int
vtu_point_data (lac_vtu *v, const lac_output_fields *f)
{
  const lac_mesh *m = f->mesh;
  int ns = lac_model_nstress (f->model), status;
  const char *const *names = lac_output_stress_names (f->model);
  char name[32];
  lac_vtu_defaults (v, "displacement", f->vm ? "von_mises" : NULL, "body");
  status = lac_vtu_f64 (v, LAC_VTU_POINT_DATA, "displacement", 3, f->u,
                        m->dim, 0);
  if (!status && f->u_exact)
    status = lac_vtu_f64 (v, LAC_VTU_POINT_DATA, "displacement_exact", 3,
                          f->u_exact, m->dim, 0);
  for (int k = 0; !status && f->sigma && k < ns; k++)
    {
      snprintf (name, sizeof name, "stress_%s", names[k]);
      status = lac_vtu_f64 (v, LAC_VTU_POINT_DATA, name, 1, f->sigma, ns, k);
    }
  if (!status && f->vm)
    status = lac_vtu_f64 (v, LAC_VTU_POINT_DATA, "von_mises", 1, f->vm, 1,
                          0);
  return status;
}

static int
vtu_cell_data (lac_vtu *v, const lac_mesh *m)
{
  int *body = lac_calloc (m->ncells + 1, sizeof *body), status;
  if (!body)
    LAC_ERROR (LAC_ENOMEM, "VTU body of %zu cells", m->ncells);
  for (size_t c = 0; m->body && c < m->ncells; c++)
    body[c] = m->body[c];
  status = lac_vtu_i32 (v, LAC_VTU_CELL_DATA, "body", body);
  lac_free (body);
  return status;
}

/* lac_output_vtu: write the mesh and the nodal fields as a VTU file. */
int
lac_output_vtu (const char *path, const lac_output_fields *f)
{
  lac_vtu *v;
  int status;
  if ((status = check_fields (f)))
    return status;
  if (!(v = lac_vtu_alloc (f->mesh->nnodes, f->mesh->ncells, f->vtu_ascii)))
    LAC_ERROR (LAC_ENOMEM, "VTU of %zu nodes", f->mesh->nnodes);
  if (!(status = lac_vtu_points (v, f->mesh->x, f->mesh->dim))
      && !(status = vtu_cells (v, f->mesh))
      && !(status = vtu_point_data (v, f))
      && !(status = vtu_cell_data (v, f->mesh)))
    status = lac_vtu_write (v, path);
  lac_vtu_free (v);
  return status;
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
  if ((status = lac_file_create (path, "w", &fp)))
    return status;
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
  return lac_file_close (fp, path);
}

/* ---- summary ---------------------------------------------------------- */

int
lac_output_summary (const char *path, size_t n, const char *const *key,
                    const char *const *val)
{
  FILE *fp;
  int status = lac_file_create (path, "w", &fp);
  if (status)
    return status;
  for (size_t k = 0; k < n; k++)
    fprintf (fp, "%s = %s\n", key[k], val[k]);
  return lac_file_close (fp, path);
}
