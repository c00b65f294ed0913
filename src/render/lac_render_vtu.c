/* lac_render_vtu.c -- read back the VTU files lac writes; nodal fields
 *
 * lac_output_vtu (io/lac_vtu.h) writes one UnstructuredGrid piece:
 * Points (three coordinates), Cells (connectivity in VTK node order,
 * offsets, types), PointData (displacement, displacement_exact, stress_*,
 * von_mises) and CellData (body), either as ascii DataArrays or as
 * appended raw binary data.  This reader takes the same subset of the
 * format: one piece, ascii or appended raw DataArrays (Float32/64,
 * Int8..64, UInt8..64, headers UInt32 or UInt64, the machine's byte
 * order), any order of the sections and arrays, any whitespace; it does
 * not handle inline base64 ("binary") or compressed data, nor polyhedra.  A cell's VTK type is mapped back to the lac type
 * with the same vtk_type, and its nodes back to gmsh order through
 * vtk_perm (VTK node k is gmsh node vtk_perm[k]).
 *
 * Reference: VTK file formats, "VTK XML formats: UnstructuredGrid".
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "io/lac_mesh_child.h"
#include "render/lac_render.h"
#include "base/lac_status.h"

/* ---- reading the file -------------------------------------------------- */

/* Bytes of a VTK scalar type name, 0 if unknown. */
static size_t
type_size (const char *t)
{
  static const char *const name[10] = { "Float64", "Float32", "Int64",
    "UInt64", "Int32", "UInt32", "Int16", "UInt16", "Int8", "UInt8" };
  static const size_t size[10] = { 8, 4, 8, 8, 4, 4, 2, 2, 1, 1 };
  for (int k = 0; k < 10; k++)
    if (!strcmp (t, name[k]))
      return size[k];
  return 0;
}

typedef struct vtu_array
{
  char name[64];
  int section;        /* 0 Points, 1 Cells, 2 PointData, 3 CellData */
  int ncomp;
  size_t n;           /* number of values */
  double *v;          /* owned */
} vtu_array;

typedef struct vtu_file
{
  const char *path;
  char *text;         /* owned, NUL-terminated (cut before AppendedData) */
  const unsigned char *bin;  /* into text: the appended data after '_' */
  size_t nbin;               /* its bytes (up to the end of the file)   */
  int header64;              /* header_type UInt64 (else UInt32)        */
  size_t npoints, ncells;
  size_t narrays, cap;
  vtu_array *a;       /* owned */
} vtu_file;

static void
vtu_file_free (vtu_file *f)
{
  for (size_t k = 0; k < f->narrays; k++)
    lac_free (f->a[k].v);
  lac_free (f->a);
  lac_free (f->text);
}

static int
line_of (const vtu_file *f, const char *p)
{
  int line = 1;
  for (const char *q = f->text; q < p; q++)
    line += *q == '\n';
  return line;
}

static int attr (const char *p, const char *name, char *buf, size_t len);

/* The raw appended data, if any: after the '_' that follows
 * <AppendedData encoding="raw">; the text is cut before the tag, so that
 * the XML scan never reads binary bytes. */
static int
appended_start (vtu_file *f, size_t len)
{
  char *a = strstr (f->text, "<AppendedData");
  const char *u, *end;
  const uint16_t one = 1;
  char buf[32];
  if (strstr (f->text, "header_type=\"UInt64\""))
    f->header64 = 1;
  if (!a)
    return LAC_SUCCESS;
  if (!(end = strchr (a, '>')) || !(u = strchr (end, '_')))
    LAC_ERROR (LAC_EIO, "%s:%d: AppendedData without its '_' marker",
               f->path, line_of (f, a));
  if (attr (a, "encoding", buf, sizeof buf) && strcmp (buf, "raw"))
    LAC_ERROR (LAC_EIO, "%s:%d: AppendedData encoding \"%s\": only raw "
               "appended data (as lac writes it) can be read", f->path,
               line_of (f, a), buf);
  if (strstr (f->text, *(const unsigned char *) &one
                       ? "byte_order=\"BigEndian\""
                       : "byte_order=\"LittleEndian\""))
    LAC_ERROR (LAC_EIO, "'%s': binary data in the other byte order than "
               "this machine's", f->path);
  f->bin = (const unsigned char *) u + 1;
  f->nbin = len - (size_t) (u + 1 - f->text);
  *a = '\0';
  return LAC_SUCCESS;
}

/* The whole file: a regular file of at most 80 % of the machine's memory
 * (base/lac_input.h: a named pipe in the result directory blocked lac
 * render, /dev/zero fed it without end). */
static int
slurp (vtu_file *f)
{
  size_t len = 0;
  int status = lac_input_read (f->path, lac_mesh_default_memory (), "80 % "
                               "of the memory", &f->text, &len);
  return status ? status : appended_start (f, len);
}

/* The value of attribute `name` of the tag starting at p (up to '>'),
 * copied to buf; 0 if absent. */
static int
attr (const char *p, const char *name, char *buf, size_t len)
{
  const char *end = strchr (p, '>');
  size_t nl = strlen (name);
  for (const char *q = p; q && end && q < end; q++)
    if (!strncmp (q, name, nl) && isspace ((unsigned char) q[-1])
        && q[nl] == '=' && (q[nl + 1] == '"' || q[nl + 1] == '\''))
      {
        const char *v = q + nl + 2, *e = strchr (v, q[nl + 1]);
        size_t n;
        if (!e || e > end)
          return 0;
        n = (size_t) (e - v) < len - 1 ? (size_t) (e - v) : len - 1;
        memcpy (buf, v, n);
        buf[n] = '\0';
        return 1;
      }
  return 0;
}

/* Value k of a binary array of type t (its bytes at b). */
static double
binary_value (const char *t, const unsigned char *b, size_t k)
{
  union { double f64; float f32; int64_t i64; uint64_t u64; int32_t i32;
          uint32_t u32; int16_t i16; uint16_t u16; int8_t i8; uint8_t u8; } v;
  size_t w = type_size (t);
  memcpy (&v, b + k * w, w);
  return !strcmp (t, "Float64") ? v.f64 : !strcmp (t, "Float32") ? v.f32
         : !strcmp (t, "Int64") ? (double) v.i64
         : !strcmp (t, "UInt64") ? (double) v.u64
         : !strcmp (t, "Int32") ? (double) v.i32 : !strcmp (t, "UInt32") ? (double) v.u32
         : !strcmp (t, "Int16") ? (double) v.i16 : !strcmp (t, "UInt16") ? (double) v.u16
         : !strcmp (t, "Int8") ? (double) v.i8 : (double) v.u8;
}

/* The values of an appended DataArray (tag at p): at offset bytes into
 * the appended data, a header (the byte count) then the values. */
static int
read_appended (vtu_file *f, const char *p, vtu_array *a)
{
  char type[32], buf[32];
  size_t w, hs = f->header64 ? 8 : 4;
  uint64_t nb = 0;
  unsigned long long off;
  if (!f->bin)
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray \"%s\" is appended but the file "
               "has no AppendedData", f->path, line_of (f, p), a->name);
  if (!attr (p, "type", type, sizeof type)
      || !(w = type_size (type)))
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray \"%s\" of unknown type",
               f->path, line_of (f, p), a->name);
  if (!attr (p, "offset", buf, sizeof buf)
      || sscanf (buf, "%llu", &off) != 1 || off > f->nbin
      || f->nbin - off < hs)
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray \"%s\": offset '%s' outside the "
               "appended data (%zu bytes)", f->path, line_of (f, p), a->name,
               buf, f->nbin);
  if (f->header64)
    memcpy (&nb, f->bin + off, 8);
  else
    {
      uint32_t n32;
      memcpy (&n32, f->bin + off, 4);
      nb = n32;
    }
  if (nb % w || nb > f->nbin - off - hs)
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray \"%s\": %llu bytes of %s beyond "
               "the end of the file", f->path, line_of (f, p), a->name,
               (unsigned long long) nb, type);
  a->n = (size_t) (nb / w);
  lac_free (a->v);
  if (!(a->v = lac_malloc ((a->n + 1) * sizeof *a->v)))
    LAC_ERROR (LAC_ENOMEM, "out of memory reading '%s'", f->path);
  for (size_t k = 0; k < a->n; k++)
    a->v[k] = binary_value (type, f->bin + off + hs, k);
  return LAC_SUCCESS;
}

/* Parse the numbers of the DataArray whose opening tag starts at p. */
static int
read_array (vtu_file *f, const char *p, int section, const char **next)
{
  char buf[64];
  const char *q = strchr (p, '>'), *end;
  vtu_array *a;
  size_t cap = 64;
  if (q && q[-1] == '/')                     /* <DataArray ... /> */
    {
      end = q;
      *next = q + 1;
    }
  else if (!q || !(end = strstr (q, "</DataArray>")))
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray not closed", f->path,
               line_of (f, p));
  else
    *next = end + 12;
  int app = attr (p, "format", buf, sizeof buf) && !strcmp (buf, "appended");
  if (!app && attr (p, "format", buf, sizeof buf) && strcmp (buf, "ascii"))
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray format \"%s\": only ascii and "
               "appended raw VTU files (as lac writes them) can be read",
               f->path, line_of (f, p), buf);
  if (lac_grow (&f->a, f->narrays + 1, &f->cap, sizeof *f->a, 16))
    LAC_ERROR (LAC_ENOMEM, "out of memory reading '%s'", f->path);
  a = f->a + f->narrays;
  memset (a, 0, sizeof *a);
  if (!attr (p, "Name", a->name, sizeof a->name))
    strcpy (a->name, "");
  a->section = section;
  a->ncomp = attr (p, "NumberOfComponents", buf, sizeof buf) ? atoi (buf) : 1;
  if (a->ncomp < 1 || a->ncomp > 9)
    LAC_ERROR (LAC_EIO, "%s:%d: DataArray \"%s\" has %d components",
               f->path, line_of (f, p), a->name, a->ncomp);
  if (!(a->v = lac_malloc (cap * sizeof *a->v)))
    LAC_ERROR (LAC_ENOMEM, "out of memory reading '%s'", f->path);
  f->narrays++;
  if (app)
    return read_appended (f, p, a);
  for (q++; ; )
    {
      char *e;
      double v;
      while (q < end && isspace ((unsigned char) *q))
        q++;
      if (q >= end)
        break;
      v = strtod (q, &e);
      if (e == q)
        LAC_ERROR (LAC_EIO, "%s:%d: DataArray \"%s\": not a number: '%.12s'",
                   f->path, line_of (f, q), a->name, q);
      if (a->n == cap)
        {
          double *nv = lac_realloc (a->v, 2 * cap * sizeof *nv);
          if (!nv)
            LAC_ERROR (LAC_ENOMEM, "out of memory reading '%s'", f->path);
          a->v = nv;
          cap *= 2;
        }
      a->v[a->n++] = v;
      q = e;
    }
  return LAC_SUCCESS;
}

/* Walk the tags: Piece, the four sections, DataArrays. */
static int
scan (vtu_file *f)
{
  static const char *const sec[4] = { "<Points", "<Cells", "<PointData",
                                       "<CellData" };
  const char *p = f->text;
  int section = -1, pieces = 0, status;
  char buf[64];
  if (!strstr (p, "<VTKFile") || !strstr (p, "UnstructuredGrid"))
    LAC_ERROR (LAC_EIO, "'%s' is not a VTK UnstructuredGrid (.vtu) file",
               f->path);
  while ((p = strchr (p, '<')) != NULL)
    {
      if (!strncmp (p, "<Piece", 6))
        {
          if (pieces++)
            LAC_ERROR (LAC_EIO, "%s:%d: more than one Piece", f->path,
                       line_of (f, p));
          if (!attr (p, "NumberOfPoints", buf, sizeof buf))
            LAC_ERROR (LAC_EIO, "%s:%d: Piece without NumberOfPoints",
                       f->path, line_of (f, p));
          f->npoints = (size_t) strtoull (buf, NULL, 10);
          if (!attr (p, "NumberOfCells", buf, sizeof buf))
            LAC_ERROR (LAC_EIO, "%s:%d: Piece without NumberOfCells",
                       f->path, line_of (f, p));
          f->ncells = (size_t) strtoull (buf, NULL, 10);
        }
      else if (!strncmp (p, "<DataArray", 10))
        {
          if ((status = read_array (f, p, section, &p)))
            return status;
          continue;
        }
      else if (p[1] == '/')
        section = -1;
      else
        for (int k = 0; k < 4; k++)
          if (!strncmp (p, sec[k], strlen (sec[k]))
              && !isalpha ((unsigned char) p[strlen (sec[k])]))
            section = k;
      p++;
    }
  if (!pieces)
    LAC_ERROR (LAC_EIO, "'%s' has no Piece", f->path);
  return LAC_SUCCESS;
}

static const vtu_array *
find (const vtu_file *f, int section, const char *name)
{
  for (size_t k = 0; k < f->narrays; k++)
    if (f->a[k].section == section && !strcmp (f->a[k].name, name))
      return f->a + k;
  return NULL;
}

/* ---- building the mesh ------------------------------------------------- */

static const lac_refelem *
by_vtk (int vtk_type)
{
  for (int t = 0; t < LAC_NELEM_TYPES; t++)
    {
      const lac_refelem *re = lac_refelem_get ((lac_elem_type) t);
      if (re && re->vtk_type == vtk_type && re->dim >= 2)
        return re;
    }
  return NULL;
}

static int
check_cells (const vtu_file *f, const vtu_array *conn, const vtu_array *off,
             const vtu_array *types, int *dim)
{
  size_t prev = 0;
  *dim = 0;
  if (off->n != f->ncells || types->n != f->ncells)
    LAC_ERROR (LAC_EIO, "'%s': %zu offsets and %zu types for %zu cells",
               f->path, off->n, types->n, f->ncells);
  for (size_t c = 0; c < f->ncells; c++)
    {
      const lac_refelem *re = by_vtk ((int) types->v[c]);
      if (!re)
        LAC_ERROR (LAC_EIO, "'%s': cell %zu has VTK type %g, which is no "
                   "2D or 3D lac element", f->path, c, types->v[c]);
      if (*dim && re->dim != *dim)
        LAC_ERROR (LAC_EIO, "'%s': cells of dimensions %d and %d mixed",
                   f->path, *dim, re->dim);
      *dim = re->dim;
      if (off->v[c] - (double) prev != re->nnodes || off->v[c] > conn->n)
        LAC_ERROR (LAC_EIO, "'%s': cell %zu (%s) has offset %g after %zu",
                   f->path, c, re->name, off->v[c], prev);
      prev = (size_t) off->v[c];
    }
  for (size_t k = 0; k < conn->n; k++)
    if (!(conn->v[k] >= 0 && conn->v[k] < (double) f->npoints))
      LAC_ERROR (LAC_EIO, "'%s': connectivity entry %zu = %g is not a point "
                 "(0..%zu)", f->path, k, conn->v[k], f->npoints - 1);
  if (!*dim)
    LAC_ERROR (LAC_EIO, "'%s' has no cell", f->path);
  return LAC_SUCCESS;
}

static int
build_mesh (const vtu_file *f, lac_mesh **out)
{
  const vtu_array *pts = find (f, 0, "coordinates"), *body,
    *conn = find (f, 1, "connectivity"), *off = find (f, 1, "offsets"),
    *types = find (f, 1, "types");
  lac_mesh *m;
  int dim, status;
  size_t pos = 0;
  if (!pts)                       /* the points array may have any name */
    for (size_t k = 0; k < f->narrays && !pts; k++)
      pts = f->a[k].section == 0 ? f->a + k : NULL;
  if (!pts || !conn || !off || !types)
    LAC_ERROR (LAC_EIO, "'%s' lacks %s", f->path, !pts ? "the Points"
               : !conn ? "the connectivity" : !off ? "the offsets"
               : "the cell types");
  if (pts->ncomp != 3 || pts->n != 3 * f->npoints)
    LAC_ERROR (LAC_EIO, "'%s': %zu coordinates for %zu points", f->path,
               pts->n, f->npoints);
  if ((status = check_cells (f, conn, off, types, &dim)))
    return status;
  if (!(m = lac_mesh_alloc (dim, f->npoints, f->ncells, conn->n)))
    return LAC_ENOMEM;
  for (size_t a = 0; a < f->npoints; a++)
    for (int i = 0; i < dim; i++)
      m->x[a * (size_t) dim + (size_t) i] = pts->v[3 * a + (size_t) i];
  body = find (f, 3, "body");
  for (size_t c = 0; c < f->ncells; c++)
    {
      const lac_refelem *re = by_vtk ((int) types->v[c]);
      m->type[c] = re->type;
      m->ptr[c + 1] = m->ptr[c] + (size_t) re->nnodes;
      for (int k = 0; k < re->nnodes; k++)   /* VTK node k = gmsh node */
        m->conn[m->ptr[c] + (size_t) re->vtk_perm[k]] =
          (int) conn->v[pos + (size_t) k];
      pos += (size_t) re->nnodes;
      m->body[c] = body && body->n == f->ncells ? (int) body->v[c] : 0;
    }
  *out = m;
  return LAC_SUCCESS;
}

/* lac_render_result_read: the mesh and point data of a VTU file. */
int
lac_render_result_read (const char *path, lac_render_result **out)
{
  vtu_file f;
  lac_render_result *r;
  int status;
  size_t np = 0;
  if (!path || !out)
    LAC_ERROR (LAC_EINVAL, "no path or no result pointer");
  *out = NULL;
  memset (&f, 0, sizeof f);
  f.path = path;
  if (!(r = lac_calloc (1, sizeof *r)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  if ((status = slurp (&f)) || (status = scan (&f))
      || (status = build_mesh (&f, &r->mesh)))
    goto done;
  for (size_t k = 0; k < f.narrays; k++)
    np += f.a[k].section == 2;
  r->name = lac_calloc (np + 1, sizeof *r->name);
  r->ncomp = lac_calloc (np + 1, sizeof *r->ncomp);
  r->value = lac_calloc (np + 1, sizeof *r->value);
  if (!r->name || !r->ncomp || !r->value)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "out of memory");
      goto done;
    }
  for (size_t k = 0; k < f.narrays; k++)
    {
      vtu_array *a = f.a + k;
      if (a->section != 2)
        continue;
      if (a->n != f.npoints * (size_t) a->ncomp)
        {
          status = LAC_ERRMSG (LAC_EIO, "'%s': point array \"%s\" has %zu "
                               "values for %zu points x %d components",
                               path, a->name, a->n, f.npoints, a->ncomp);
          goto done;
        }
      if (!(r->name[r->narrays] = lac_strdup (a->name)))
        {
          status = LAC_ERRMSG (LAC_ENOMEM, "out of memory");
          goto done;
        }
      r->ncomp[r->narrays] = a->ncomp;
      r->value[r->narrays++] = a->v;       /* moved from the file */
      a->v = NULL;
      r->axisymmetric |= !strcmp (a->name, "stress_rr");
    }
done:
  vtu_file_free (&f);
  if (status)
    lac_render_result_free (r);
  else
    *out = r;
  return status;
}

void
lac_render_result_free (lac_render_result *r)
{
  if (!r)
    return;
  for (size_t k = 0; k < r->narrays; k++)
    {
      lac_free (r->name[k]);
      lac_free (r->value[k]);
    }
  lac_free (r->name);
  lac_free (r->ncomp);
  lac_free (r->value);
  lac_mesh_free (r->mesh);
  lac_free (r);
}

/* ---- fields ------------------------------------------------------------ */

const double *
lac_render_result_array (const lac_render_result *r, const char *name,
                         int *ncomp)
{
  for (size_t k = 0; r && k < r->narrays; k++)
    if (!strcmp (r->name[k], name))
      {
        if (ncomp)
          *ncomp = r->ncomp[k];
        return r->value[k];
      }
  return NULL;
}

int
lac_render_result_displacement (const lac_render_result *r, double *u)
{
  int nc = 0, dim = r->mesh->dim;
  const double *d = lac_render_result_array (r, "displacement", &nc);
  if (!d || nc < dim)
    LAC_ERROR (LAC_EINVAL, "the result has no displacement array");
  for (size_t a = 0; a < r->mesh->nnodes; a++)
    for (int i = 0; i < dim; i++)
      u[a * (size_t) dim + (size_t) i] = d[a * (size_t) nc + (size_t) i];
  return LAC_SUCCESS;
}

/* Component index of a suffix: x y z (r z in the axisymmetric model);
 * 3: magnitude; -1 otherwise. */
static int coordinate_comp (const lac_render_result *r, const char *s);

static int
suffix_comp (const lac_render_result *r, const char *s)
{
  return !strcmp (s, "magnitude") ? 3 : coordinate_comp (r, s);
}

/* A coordinate as a field: x, y (, z); r, z in the axisymmetric model;
 * -1 for other names. */
static int
coordinate_comp (const lac_render_result *r, const char *s)
{
  if (r->axisymmetric)
    return !strcmp (s, "r") ? 0 : !strcmp (s, "z") ? 1 : -1;
  return !strcmp (s, "x") ? 0 : !strcmp (s, "y") ? 1
         : !strcmp (s, "z") && r->mesh->dim == 3 ? 2 : -1;
}

/* n.sigma.n with n = x/|x| (see lac_render.h). */
static int
radial_stress (const lac_render_result *r, double *out)
{
  static const char *const n3[6] = { "xx", "yy", "zz", "xy", "yz", "zx" };
  static const char *const n2[3] = { "xx", "yy", "xy" };
  static const char *const na[3] = { "rr", "zz", "rz" };
  const char *const *nm = r->mesh->dim == 3 ? n3 : r->axisymmetric ? na : n2;
  int ns = r->mesh->dim == 3 ? 6 : 3, dim = r->mesh->dim;
  const double *s[6];
  char name[32];
  for (int k = 0; k < ns; k++)
    {
      snprintf (name, sizeof name, "stress_%s", nm[k]);
      if (!(s[k] = lac_render_result_array (r, name, NULL)))
        LAC_ERROR (LAC_EINVAL, "radial_stress needs %s, which the result "
                   "does not have", name);
    }
  for (size_t a = 0; a < r->mesh->nnodes; a++)
    {
      const double *x = r->mesh->x + a * (size_t) dim;
      double n[3] = { 0, 0, 0 }, len = 0, S[3][3];
      for (int i = 0; i < dim; i++)
        len += x[i] * x[i];
      len = sqrt (len);
      for (int i = 0; i < dim; i++)
        n[i] = len > 0 ? x[i] / len : NAN;
      if (dim == 3)
        {
          double v[6];
          for (int k = 0; k < 6; k++)
            v[k] = s[k][a];
          S[0][0] = v[0], S[1][1] = v[1], S[2][2] = v[2];
          S[0][1] = S[1][0] = v[3];
          S[1][2] = S[2][1] = v[4];
          S[2][0] = S[0][2] = v[5];
        }
      else
        {
          memset (S, 0, sizeof S);
          S[0][0] = s[0][a], S[1][1] = s[1][a];
          S[0][1] = S[1][0] = s[2][a];
        }
      out[a] = 0;
      for (int i = 0; i < dim; i++)
        for (int j = 0; j < dim; j++)
          out[a] += n[i] * S[i][j] * n[j];
    }
  return LAC_SUCCESS;
}

static int
error_field (const lac_render_result *r, double *out)
{
  int nc, ne;
  const double *u = lac_render_result_array (r, "displacement", &nc),
    *ue = lac_render_result_array (r, "displacement_exact", &ne);
  if (!u || !ue || nc != ne)
    LAC_ERROR (LAC_EINVAL, "displacement_error needs the displacement and "
               "the exact displacement, which the result does not have");
  for (size_t a = 0; a < r->mesh->nnodes; a++)
    {
      double s = 0;
      for (int i = 0; i < nc; i++)
        s += (u[a * (size_t) nc + (size_t) i] - ue[a * (size_t) nc + (size_t) i])
             * (u[a * (size_t) nc + (size_t) i] - ue[a * (size_t) nc + (size_t) i]);
      out[a] = sqrt (s);
    }
  return LAC_SUCCESS;
}

/* Canonical name of an alias, or name itself. */
static void
canonical (const char *name, char *buf, size_t len)
{
  if (!strcmp (name, "vm"))
    name = "von_mises";
  else if (!strcmp (name, "u") || !strcmp (name, "|u|"))
    name = "displacement_magnitude";
  if (!strncmp (name, "u_", 2) || (name[0] == 'u' && strlen (name) == 2))
    snprintf (buf, len, "displacement_%s", name + (name[1] == '_' ? 2 : 1));
  else if (!strncmp (name, "sigma_", 6))
    snprintf (buf, len, "stress_%s", name + 6);
  else if (!strncmp (name, "s_", 2))
    snprintf (buf, len, "stress_%s", name + 2);
  else if (name[0] == 's' && strlen (name) == 3 && strchr ("xyzrt", name[1]))
    snprintf (buf, len, "stress_%s", name + 1);
  else
    snprintf (buf, len, "%s", name);
}

int
lac_render_result_scalar (const lac_render_result *r, const char *name,
                          double *out)
{
  char cn[96], avail[1024];
  const char *us;
  int nc, comp;
  const double *v;
  if (!r || !name || !out)
    LAC_ERROR (LAC_EINVAL, "no result, field name or output array");
  canonical (name, cn, sizeof cn);
  if ((v = lac_render_result_array (r, cn, &nc)) && nc == 1)
    {
      memcpy (out, v, r->mesh->nnodes * sizeof *out);
      return LAC_SUCCESS;
    }
  if ((comp = coordinate_comp (r, cn)) >= 0)
    {
      for (size_t a = 0; a < r->mesh->nnodes; a++)
        out[a] = r->mesh->x[a * (size_t) r->mesh->dim + (size_t) comp];
      return LAC_SUCCESS;
    }
  if (!strcmp (cn, "radial_stress"))
    return radial_stress (r, out);
  if (!strcmp (cn, "displacement_error"))
    return error_field (r, out);
  if ((us = strrchr (cn, '_')) != NULL)
    {
      char base[96];
      comp = suffix_comp (r, us + 1);
      snprintf (base, sizeof base, "%.*s", (int) (us - cn), cn);
      v = lac_render_result_array (r, base, &nc);
      if (v && nc > 1 && comp >= 0)
        {
          for (size_t a = 0; a < r->mesh->nnodes; a++)
            {
              const double *p = v + a * (size_t) nc;
              out[a] = comp < 3 ? p[comp]
                       : sqrt (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            }
          return LAC_SUCCESS;
        }
    }
  lac_render_result_list (r, avail, sizeof avail);
  LAC_ERROR (LAC_EINVAL, "no field '%s' in the result; available: %s", name,
             avail);
}

static void
append (char *buf, size_t len, const char *s)
{
  size_t n = strlen (buf);
  if (n + 2 < len)
    snprintf (buf + n, len - n, "%s%s", n ? ", " : "", s);
}

void
lac_render_result_list (const lac_render_result *r, char *buf, size_t len)
{
  static const char *const sx[3] = { "x", "y", "z" }, *const sa[2] =
    { "r", "z" };
  char s[96];
  int has_u = 0, has_ue = 0, has_s = 0;
  if (!len)
    return;
  buf[0] = '\0';
  for (size_t k = 0; r && k < r->narrays; k++)
    {
      if (r->ncomp[k] == 1)
        append (buf, len, r->name[k]);
      else
        {
          for (int i = 0; i < r->mesh->dim; i++)
            {
              snprintf (s, sizeof s, "%s_%s", r->name[k],
                        r->axisymmetric ? sa[i] : sx[i]);
              append (buf, len, s);
            }
          snprintf (s, sizeof s, "%s_magnitude", r->name[k]);
          append (buf, len, s);
        }
      has_u |= !strcmp (r->name[k], "displacement");
      has_ue |= !strcmp (r->name[k], "displacement_exact");
      has_s |= !strncmp (r->name[k], "stress_", 7);
    }
  if (has_s)
    append (buf, len, "radial_stress");
  append (buf, len, r && r->axisymmetric ? "r, z" : r && r->mesh->dim == 3
          ? "x, y, z" : "x, y");
  if (has_u && has_ue)
    append (buf, len, "displacement_error");
}
