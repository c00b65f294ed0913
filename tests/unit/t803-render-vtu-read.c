/* t803: VTU round trip -- lac_output_vtu then lac_render_result_read
 *
 * For every 2D and 3D element type a box mesh with a displacement, an exact
 * displacement and stresses is written and read back: same nodes, same
 * cells (types and gmsh-order connectivity, through the inverse of
 * vtk_perm), same bodies, same arrays.  Coordinates and values are dyadic
 * numbers with few digits, which the writer's %.10e keeps exactly, so the
 * comparison is to 1e-12; a distorted mesh is compared to the writer's 11
 * significant digits.  Then the scalar fields by name and alias (components,
 * magnitudes, radial stress, error), the list of names, and bad files.
 * Every type again in binary (appended raw, the default): every bit kept
 * (tolerance 0); bad binary files (cut short, offsets past the data).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "base/lac_mem.h"
#include "io/lac_output.h"
#include "render/lac_render.h"
#include "base/lac_status.h"
#include "t8-render.h"

typedef struct data
{
  double *u, *ue, *sigma, *vm;
} data;

static void
make_data (const lac_mesh *m, lac_model model, data *d)
{
  int dim = m->dim, ns = lac_model_nstress (model);
  d->u = lac_malloc (m->nnodes * (size_t) dim * sizeof *d->u);
  d->ue = lac_malloc (m->nnodes * (size_t) dim * sizeof *d->ue);
  d->sigma = lac_malloc (m->nnodes * (size_t) ns * sizeof *d->sigma);
  d->vm = lac_malloc (m->nnodes * sizeof *d->vm);
  for (size_t a = 0; a < m->nnodes; a++)
    {
      const double *x = m->x + a * (size_t) dim;
      for (int i = 0; i < dim; i++)
        {
          d->u[a * (size_t) dim + (size_t) i] = 0.125 * x[i] - 0.5 * x[0] * x[1]
                                                + i;
          d->ue[a * (size_t) dim + (size_t) i] = 0.125 * x[i];
        }
      for (int k = 0; k < ns; k++)
        d->sigma[a * (size_t) ns + (size_t) k] = (k + 1) * x[0] - 0.25 * x[1];
      d->vm[a] = x[0] * x[1] + 2;
    }
}

static void
free_data (data *d)
{
  lac_free (d->u);
  lac_free (d->ue);
  lac_free (d->sigma);
  lac_free (d->vm);
}

static void
compare (const lac_mesh *m, const data *d, lac_model model,
         const lac_render_result *r, double tol, const char *name)
{
  const lac_mesh *b = r->mesh;
  int dim = m->dim, ns = lac_model_nstress (model), nc, bad = 0;
  const char *const *sn = lac_output_stress_names (model);
  const double *v;
  double *u;
  check_int (b->dim, dim, "%s: dim", name);
  check_int ((long) b->nnodes, (long) m->nnodes, "%s: nodes", name);
  check_int ((long) b->ncells, (long) m->ncells, "%s: cells", name);
  if (b->dim != dim || b->nnodes != m->nnodes || b->ncells != m->ncells)
    return;
  for (size_t k = 0; k < m->nnodes * (size_t) dim; k++)
    bad += fabs (b->x[k] - m->x[k]) > tol * (1 + fabs (m->x[k]));
  check_int (bad, 0, "%s: coordinates", name);
  bad = 0;
  for (size_t c = 0; c < m->ncells; c++)
    {
      bad += b->type[c] != m->type[c] || b->ptr[c + 1] != m->ptr[c + 1]
             || b->body[c] != (m->body[c] < 0 ? 0 : m->body[c]);
      for (size_t k = m->ptr[c]; k < m->ptr[c + 1] && !bad; k++)
        bad += b->conn[k] != m->conn[k];
    }
  check_int (bad, 0, "%s: cell types, connectivity, bodies", name);
  check_int (r->axisymmetric, model == LAC_AXISYMMETRIC, "%s: axi", name);

  u = lac_malloc (m->nnodes * (size_t) dim * sizeof *u);
  check_status (lac_render_result_displacement (r, u), LAC_SUCCESS,
                "%s: displacement", name);
  bad = 0;
  for (size_t k = 0; k < m->nnodes * (size_t) dim; k++)
    bad += fabs (u[k] - d->u[k]) > tol * (1 + fabs (d->u[k]));
  check_int (bad, 0, "%s: displacement values", name);
  v = lac_render_result_array (r, "displacement_exact", &nc);
  check_true (v && nc == 3, "%s: exact displacement, 3 components", name);
  for (int k = 0; k < ns; k++)
    {
      char an[32];
      snprintf (an, sizeof an, "stress_%s", sn[k]);
      v = lac_render_result_array (r, an, &nc);
      check_true (v && nc == 1, "%s: %s", name, an);
      bad = 0;
      for (size_t a = 0; v && a < m->nnodes; a++)
        bad += fabs (v[a] - d->sigma[a * (size_t) ns + (size_t) k])
               > tol * (1 + fabs (v[a]));
      check_int (bad, 0, "%s: %s values", name, an);
    }
  v = lac_render_result_array (r, "von_mises", &nc);
  bad = !v;
  for (size_t a = 0; v && a < m->nnodes; a++)
    bad += fabs (v[a] - d->vm[a]) > tol * (1 + fabs (v[a]));
  check_int (bad, 0, "%s: von_mises", name);
  lac_free (u);
}

static void
round_trip (lac_elem_type t, double distort, double tol, int ascii)
{
  const lac_refelem *re = lac_refelem_get (t);
  size_t n[3] = { 4, 2, 2 };
  double L[3] = { 2, 1, 1 };
  lac_mesh *m = NULL;
  lac_render_result *r = NULL;
  lac_model model = re->dim == 3 ? LAC_SOLID3D
                    : t == LAC_QUAD9 ? LAC_AXISYMMETRIC : LAC_PLANE_STRAIN;
  lac_output_fields f;
  data d;
  char name[64];
  const char *path = t8_path ("t803.vtu");
  snprintf (name, sizeof name, "%s distort %g %s", re->name, distort,
            ascii ? "ascii" : "binary");
  if (lac_mesh_box (t, n, L, distort, &m))
    {
      check_true (0, "%s: box: %s", name, lac_error_message ());
      return;
    }
  for (size_t c = 0; c < m->ncells; c++)
    m->body[c] = (int) (c % 3);
  make_data (m, model, &d);
  memset (&f, 0, sizeof f);
  f.mesh = m;
  f.model = model;
  f.u = d.u;
  f.u_exact = d.ue;
  f.sigma = d.sigma;
  f.vm = d.vm;
  f.vtu_ascii = ascii;
  check_status (lac_output_vtu (path, &f), LAC_SUCCESS, "%s: write", name);
  check_status (lac_render_result_read (path, &r), LAC_SUCCESS, "%s: read",
                name);
  if (r)
    compare (m, &d, model, r, tol, name);
  lac_render_result_free (r);
  free_data (&d);
  lac_mesh_free (m);
}

/* Scalar fields by name on a quad4 plane-strain result. */
static void
test_fields (void)
{
  size_t n[2] = { 2, 2 };
  double L[2] = { 2, 2 }, *s, rr, x, y;
  lac_mesh *m = NULL;
  lac_render_result *r = NULL;
  lac_output_fields f;
  data d;
  char list[1024];
  const char *path = t8_path ("t803-fields.vtu");
  lac_mesh_box (LAC_QUAD4, n, L, 0, &m);
  make_data (m, LAC_PLANE_STRAIN, &d);
  memset (&f, 0, sizeof f);
  f.mesh = m;
  f.model = LAC_PLANE_STRAIN;
  f.u = d.u;
  f.u_exact = d.ue;
  f.sigma = d.sigma;
  f.vm = d.vm;
  lac_output_vtu (path, &f);
  check_status (lac_render_result_read (path, &r), LAC_SUCCESS, "read");
  if (!r)
    goto done;
  s = lac_malloc (m->nnodes * sizeof *s);
  lac_render_result_list (r, list, sizeof list);
  check_true (strstr (list, "von_mises") && strstr (list, "stress_xy")
              && strstr (list, "displacement_magnitude")
              && strstr (list, "displacement_y") && !strstr (list,
                                                             "displacement_z")
              && strstr (list, "radial_stress")
              && strstr (list, "displacement_error"), "list: %s", list);
  /* node 8 is (2, 2) in the 3 x 3 grid of vertices */
  x = m->x[16];
  y = m->x[17];
  check_abs (x + y, 4, 0, "node 8 at (2, 2)");
  check_status (lac_render_result_scalar (r, "vm", s), LAC_SUCCESS, "vm");
  check_abs (s[8], 6, 1e-12, "vm at (2, 2)");
  check_status (lac_render_result_scalar (r, "u_y", s), LAC_SUCCESS, "u_y");
  check_abs (s[8], 0.25 - 2 + 1, 1e-12, "u_y at (2, 2)");
  check_status (lac_render_result_scalar (r, "|u|", s), LAC_SUCCESS, "|u|");
  check_abs (s[8], sqrt (1.75 * 1.75 + 0.75 * 0.75), 1e-12, "|u| at (2, 2)");
  check_status (lac_render_result_scalar (r, "displacement_error", s),
                LAC_SUCCESS, "error");
  check_abs (s[8], sqrt (2.0 * 2.0 + 1.0), 1e-12, "|u - ue| at (2, 2)");
  check_status (lac_render_result_scalar (r, "sxy", s), LAC_SUCCESS, "sxy");
  check_abs (s[8], 4 * 2 - 0.5, 1e-12, "s_xy at (2, 2)");
  /* radial: n = (1, 1)/sqrt 2: (s_xx + s_yy)/2 + s_xy */
  check_status (lac_render_result_scalar (r, "radial_stress", s), LAC_SUCCESS,
                "radial");
  rr = 0.5 * ((2 - 0.5) + (4 - 0.5)) + (8 - 0.5);
  check_abs (s[8], rr, 1e-12, "radial stress at (2, 2)");
  check_true (isnan (s[0]), "radial stress at the origin: NaN");
  check_status (lac_render_result_scalar (r, "y", s), LAC_SUCCESS, "y");
  check_abs (s[8], 2, 0, "coordinate y at (2, 2)");
  check_status (lac_render_result_scalar (r, "pressure", s), LAC_EINVAL,
                "unknown field");
  check_message ("available: ", "the message lists the fields");
  check_message ("von_mises", "the list has von_mises");
  lac_free (s);
done:
  lac_render_result_free (r);
  free_data (&d);
  lac_mesh_free (m);
}

static void
write_text (const char *path, const char *text)
{
  FILE *fp = fopen (path, "w");
  if (fp)
    {
      fputs (text, fp);
      fclose (fp);
    }
}

static void
test_bad_files (void)
{
  lac_render_result *r = NULL;
  const char *path = t8_path ("t803-bad.vtu");
  check_status (lac_render_result_read ("/nonexistent.vtu", &r), LAC_EIO,
                "missing file");
  check_message ("/nonexistent.vtu", "message names the file");
  write_text (path, "hello\n");
  check_status (lac_render_result_read (path, &r), LAC_EIO, "not a VTU");
  write_text (path, "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n"
              "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n<Points>\n"
              "<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
              "format=\"binary\">AAAA</DataArray>\n");
  check_status (lac_render_result_read (path, &r), LAC_EIO, "binary");
  check_message ("only ascii", "binary: message");
  write_text (path, "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n"
              "<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n<Points>\n"
              "<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
              "format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points>\n"
              "<Cells><DataArray Name=\"connectivity\" format=\"ascii\">"
              "0 1 7</DataArray><DataArray Name=\"offsets\">3</DataArray>"
              "<DataArray Name=\"types\">5</DataArray></Cells></Piece>\n");
  check_status (lac_render_result_read (path, &r), LAC_EIO, "bad node");
  check_message ("connectivity entry 2 = 7", "bad node: message");
  check_true (r == NULL, "no result on failure");
}

/* The binary encoding; a file cut short, an offset past the data, appended arrays
 * without AppendedData, base64 appended data: one-line errors. */
static void
test_bad_appended (void)
{
  static const char head[] =
    "<VTKFile type=\"UnstructuredGrid\" header_type=\"UInt64\">\n"
    "<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n"
    "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
    "format=\"appended\" offset=\"%d\"/></Points></Piece>\n"
    "</UnstructuredGrid>\n";
  lac_render_result *r = NULL;
  const char *path = t8_path ("t803-bad.vtu");
  char text[2048];
  snprintf (text, sizeof text, head, 0);
  write_text (path, text);
  check_status (lac_render_result_read (path, &r), LAC_EIO, "no data");
  check_message ("has no AppendedData", "no data: message");
  {
    char t2[512];
    snprintf (t2, sizeof t2, head, 0);
    snprintf (text, sizeof text, "%s<AppendedData encoding=\"raw\">_"
              "\030\001\001\001\001\001\001\001abc", t2);
  }
  write_text (path, text);
  check_status (lac_render_result_read (path, &r), LAC_EIO, "cut short");
  check_message ("beyond the end of the file", "cut short: message");
  {
    char t2[512];
    snprintf (t2, sizeof t2, head, 99);
    snprintf (text, sizeof text, "%s<AppendedData encoding=\"raw\">_"
              "abcdefgh", t2);
  }
  write_text (path, text);
  check_status (lac_render_result_read (path, &r), LAC_EIO, "offset");
  check_message ("offset '99' outside the appended data", "offset: message");
  {
    char t2[512];
    snprintf (t2, sizeof t2, head, 0);
    snprintf (text, sizeof text, "%s<AppendedData encoding=\"base64\">_"
              "AAAA", t2);
  }
  write_text (path, text);
  check_status (lac_render_result_read (path, &r), LAC_EIO, "base64");
  check_message ("only raw", "base64: message");
  check_true (r == NULL, "no result on failure");
}

int
main (void)
{
  static const lac_elem_type types[] = {
    LAC_TRI3, LAC_TRI6, LAC_QUAD4, LAC_QUAD8, LAC_QUAD9,
    LAC_TET4, LAC_TET10, LAC_HEX8, LAC_HEX20, LAC_HEX27
  };
  lac_init ();
  for (size_t k = 0; k < sizeof types / sizeof *types; k++)
    {
      round_trip (types[k], 0, 1e-12, 1);
      round_trip (types[k], 0, 0, 0);        /* binary: every bit kept */
    }
  round_trip (LAC_TET10, 0.2, 1e-10, 1);
  round_trip (LAC_QUAD8, 0.2, 1e-10, 1);
  round_trip (LAC_TET10, 0.2, 0, 0);
  round_trip (LAC_QUAD8, 0.2, 0, 0);
  test_bad_appended ();
  test_fields ();
  test_bad_files ();
  return check_summary ();
}
