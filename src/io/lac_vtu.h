/* lac_vtu.h -- one VTK XML UnstructuredGrid file (.vtu), ASCII or binary
 *
 * A VTU file is one Piece: Points (three coordinates each), Cells
 * (connectivity in VTK node order, offsets, VTK cell types), PointData
 * and CellData arrays.  The arrays are collected first (copied: the
 * caller's data may go), then lac_vtu_write writes the file in one of two
 * encodings:
 *
 *   binary (the default): every DataArray is format="appended"; after the
 *     XML comes <AppendedData encoding="raw">_ and, per array, a UInt64
 *     byte count followed by the values in the machine's byte order
 *     (byte_order says which).  Doubles are written exactly; a file is
 *     about 2.3 times smaller than the ASCII one.
 *   ascii: every value as text (%.10e for Float64), for reading by eye
 *     and for tools that compare text.
 *
 * Both are read by ParaView and by lac render (render/lac_render_vtu.c).
 *
 * Reference: VTK file formats, "VTK XML formats: UnstructuredGrid" and
 * "Appended data section"
 * (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html).
 *
 * Ownership: lac_vtu_alloc / lac_vtu_free; the arrays are owned copies.
 */
#ifndef LAC_VTU_H
#define LAC_VTU_H

#include <stddef.h>
#include <stdio.h>

typedef struct lac_vtu lac_vtu;

/* The sections an array belongs to. */
typedef enum { LAC_VTU_POINTS, LAC_VTU_CELLS, LAC_VTU_POINT_DATA,
               LAC_VTU_CELL_DATA } lac_vtu_section;

/* A grid of npoints points and ncells cells; ascii: 1 for text. */
lac_vtu *lac_vtu_alloc (size_t npoints, size_t ncells, int ascii);
void lac_vtu_free (lac_vtu *v);

/* Points: x[npoints * dim], padded to three coordinates. */
int lac_vtu_points (lac_vtu *v, const double *x, int dim);
/* Cells: conn (VTK node order, point indices), offsets (end of each
 * cell's nodes in conn), VTK types; nconn = offsets[ncells - 1]. */
int lac_vtu_cells (lac_vtu *v, const long *conn, const long *offsets,
                   const unsigned char *types);
/* A Float64 array of ncomp components; component k of item a is
 * val[a * stride + first + k], or 0 where first + k >= stride (a 2D
 * vector padded to three components). */
int lac_vtu_f64 (lac_vtu *v, lac_vtu_section s, const char *name, int ncomp,
                 const double *val, int stride, int first);
/* An Int32 array of one component. */
int lac_vtu_i32 (lac_vtu *v, lac_vtu_section s, const char *name,
                 const int *val);
/* The default arrays ParaView shows (Vectors=, Scalars= of PointData and
 * CellData); NULL: none. */
void lac_vtu_defaults (lac_vtu *v, const char *point_vectors,
                       const char *point_scalars, const char *cell_scalars);

/* Write the file. */
int lac_vtu_write (const lac_vtu *v, const char *path);

/* The head of a VTK XML file, this one or another (the .pvd collection of
 * a run's step files): the XML declaration and the opening VTKFile tag of
 * type `type`, file version `version`, the machine's byte order, and the
 * further attributes `attrs` ("" for none). */
void lac_vtu_xml_head (FILE *fp, const char *type, const char *version,
                       const char *attrs);

#endif /* LAC_VTU_H */
