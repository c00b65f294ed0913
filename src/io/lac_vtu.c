/* lac_vtu.c -- VTU files, ASCII or appended raw binary (see lac_vtu.h)
 */
#include "io/lac_vtu.h"

#include <stdint.h>
#include <stdio.h>
#include "base/lac_file.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

typedef enum { F64, I64, U8, I32 } vtype;

static const char *const type_name[4] = { "Float64", "Int64", "UInt8",
                                          "Int32" };
static const size_t type_size[4] = { 8, 8, 1, 4 };

typedef struct varr
{
  lac_vtu_section sec;
  char name[64];
  vtype type;
  int ncomp;
  size_t n;            /* values (items x components) */
  void *data;          /* owned, n values of the type */
} varr;

struct lac_vtu
{
  size_t npoints, ncells;
  int ascii;
  size_t narr;
  varr arr[64];
  const char *pv, *ps, *cs;   /* default arrays (static names) */
};

lac_vtu *
lac_vtu_alloc (size_t npoints, size_t ncells, int ascii)
{
  lac_vtu *v = lac_calloc (1, sizeof *v);
  if (!v)
    return NULL;
  v->npoints = npoints;
  v->ncells = ncells;
  v->ascii = ascii;
  return v;
}

void
lac_vtu_free (lac_vtu *v)
{
  if (!v)
    return;
  for (size_t k = 0; k < v->narr; k++)
    lac_free (v->arr[k].data);
  lac_free (v);
}

void
lac_vtu_defaults (lac_vtu *v, const char *point_vectors,
                  const char *point_scalars, const char *cell_scalars)
{
  v->pv = point_vectors;
  v->ps = point_scalars;
  v->cs = cell_scalars;
}

/* *out: a new array of n values, its data uninitialised. */
static int
add (lac_vtu *v, lac_vtu_section s, const char *name, vtype t, int ncomp,
     size_t n, varr **out)
{
  varr *a;
  if (v->narr == sizeof v->arr / sizeof v->arr[0])
    LAC_ERROR (LAC_ESANITY, "VTU '%s': more than %zu arrays", name, v->narr);
  a = v->arr + v->narr;
  if (!(a->data = lac_malloc ((n ? n : 1) * type_size[t])))
    LAC_ERROR (LAC_ENOMEM, "VTU array '%s' of %zu values", name, n);
  a->sec = s;
  snprintf (a->name, sizeof a->name, "%s", name);
  a->type = t;
  a->ncomp = ncomp;
  a->n = n;
  v->narr++;
  *out = a;
  return LAC_SUCCESS;
}

static size_t
items (const lac_vtu *v, lac_vtu_section s)
{
  return s == LAC_VTU_POINTS || s == LAC_VTU_POINT_DATA ? v->npoints
         : v->ncells;
}

int
lac_vtu_f64 (lac_vtu *v, lac_vtu_section s, const char *name, int ncomp,
             const double *val, int stride, int first)
{
  size_t n = items (v, s);
  varr *a;
  int status = add (v, s, name, F64, ncomp, n * (size_t) ncomp, &a);
  if (status)
    return status;
  double *d = a->data;
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < ncomp; k++)
      d[i * (size_t) ncomp + (size_t) k] = first + k < stride
        ? val[i * (size_t) stride + (size_t) (first + k)] : 0.0;
  return LAC_SUCCESS;
}

int
lac_vtu_i32 (lac_vtu *v, lac_vtu_section s, const char *name,
             const int *val)
{
  size_t n = items (v, s);
  varr *a = NULL;
  int status = add (v, s, name, I32, 1, n, &a);
  if (status)
    return status;
  for (size_t i = 0; i < n; i++)
    ((int32_t *) a->data)[i] = (int32_t) val[i];
  return LAC_SUCCESS;
}

int
lac_vtu_points (lac_vtu *v, const double *x, int dim)
{
  return lac_vtu_f64 (v, LAC_VTU_POINTS, "coordinates", 3, x, dim, 0);
}

int
lac_vtu_cells (lac_vtu *v, const long *conn, const long *offsets,
               const unsigned char *types)
{
  size_t nc = v->ncells, nconn = nc ? (size_t) offsets[nc - 1] : 0;
  varr *a = NULL, *b = NULL, *t = NULL;
  int status;
  if ((status = add (v, LAC_VTU_CELLS, "connectivity", I64, 1, nconn, &a))
      || (status = add (v, LAC_VTU_CELLS, "offsets", I64, 1, nc, &b))
      || (status = add (v, LAC_VTU_CELLS, "types", U8, 1, nc, &t)))
    return status;
  for (size_t k = 0; k < nconn; k++)
    ((int64_t *) a->data)[k] = conn[k];
  for (size_t c = 0; c < nc; c++)
    {
      ((int64_t *) b->data)[c] = offsets[c];
      ((uint8_t *) t->data)[c] = types[c];
    }
  return LAC_SUCCESS;
}

/* ---- writing ---------------------------------------------------------- */

static void
ascii_values (FILE *fp, const varr *a)
{
  size_t per = a->ncomp > 0 ? (size_t) a->ncomp : 1;
  for (size_t i = 0; i < a->n; i++)
    {
      if (i % per == 0)
        fprintf (fp, "         ");
      switch (a->type)
        {
        case F64: fprintf (fp, " %.10e", ((const double *) a->data)[i]); break;
        case I64: fprintf (fp, " %lld", (long long) ((const int64_t *) a->data)[i]); break;
        case U8: fprintf (fp, " %d", ((const uint8_t *) a->data)[i]); break;
        case I32: fprintf (fp, " %d", (int) ((const int32_t *) a->data)[i]); break;
        }
      if ((i + 1) % per == 0)
        fprintf (fp, "\n");
    }
}

/* The DataArrays of section s; *off: the running offset in the appended
 * data (UInt64 count + bytes per array). */
static void
section_arrays (FILE *fp, const lac_vtu *v, lac_vtu_section s,
                uint64_t *off)
{
  for (size_t k = 0; k < v->narr; k++)
    {
      const varr *a = v->arr + k;
      if (a->sec != s)
        continue;
      fprintf (fp, "        <DataArray type=\"%s\" Name=\"%s\"",
               type_name[a->type], a->name);
      if (a->ncomp > 1)
        fprintf (fp, " NumberOfComponents=\"%d\"", a->ncomp);
      if (!v->ascii)
        {
          fprintf (fp, " format=\"appended\" offset=\"%llu\"/>\n",
                   (unsigned long long) *off);
          *off += 8 + a->n * type_size[a->type];
          continue;
        }
      fprintf (fp, " format=\"ascii\">\n");
      ascii_values (fp, a);
      fprintf (fp, "        </DataArray>\n");
    }
}

static void
data_tag (FILE *fp, const char *tag, const char *vec, const char *sca)
{
  fprintf (fp, "      <%s", tag);
  if (vec)
    fprintf (fp, " Vectors=\"%s\"", vec);
  if (sca)
    fprintf (fp, " Scalars=\"%s\"", sca);
  fprintf (fp, ">\n");
}

static void
appended (FILE *fp, const lac_vtu *v)
{
  static const lac_vtu_section order[4] = { LAC_VTU_POINTS, LAC_VTU_CELLS,
                                            LAC_VTU_POINT_DATA,
                                            LAC_VTU_CELL_DATA };
  fprintf (fp, "  <AppendedData encoding=\"raw\">\n   _");
  for (int s = 0; s < 4; s++)           /* the order of the offsets */
    for (size_t k = 0; k < v->narr; k++)
      if (v->arr[k].sec == order[s])
        {
          uint64_t nb = v->arr[k].n * type_size[v->arr[k].type];
          fwrite (&nb, sizeof nb, 1, fp);
          fwrite (v->arr[k].data, 1, nb, fp);
        }
  fprintf (fp, "\n  </AppendedData>\n");
}

void
lac_vtu_xml_head (FILE *fp, const char *type, const char *version,
                  const char *attrs)
{
  const uint16_t one = 1;      /* its first byte is 1 on a little-endian
                                  machine */
  fprintf (fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"%s\" version=\"%s\""
           " byte_order=\"%s\"%s>\n", type, version,
           *(const unsigned char *) &one ? "LittleEndian" : "BigEndian",
           attrs);
}

int
lac_vtu_write (const lac_vtu *v, const char *path)
{
  uint64_t off = 0;
  FILE *fp;
  int status = lac_file_create (path, "wb", &fp);
  if (status)
    return status;
  lac_vtu_xml_head (fp, "UnstructuredGrid", "1.0",
                    " header_type=\"UInt64\"");
  fprintf (fp, "  <UnstructuredGrid>\n"
           "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n",
           v->npoints, v->ncells);
  fprintf (fp, "      <Points>\n");
  section_arrays (fp, v, LAC_VTU_POINTS, &off);
  fprintf (fp, "      </Points>\n      <Cells>\n");
  section_arrays (fp, v, LAC_VTU_CELLS, &off);
  fprintf (fp, "      </Cells>\n");
  data_tag (fp, "PointData", v->pv, v->ps);
  section_arrays (fp, v, LAC_VTU_POINT_DATA, &off);
  fprintf (fp, "      </PointData>\n");
  data_tag (fp, "CellData", NULL, v->cs);
  section_arrays (fp, v, LAC_VTU_CELL_DATA, &off);
  fprintf (fp, "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n");
  if (!v->ascii)
    appended (fp, v);
  fprintf (fp, "</VTKFile>\n");
  return lac_file_close (fp, path);
}
