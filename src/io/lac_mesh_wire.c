/* lac_mesh_wire.c -- a mesh as a byte stream (see lac_mesh_wire.h)
 *
 *   "LACMESH1"  int status  size_t msglen  msg
 *   status 0:   int dim  size_t nnodes ncells nconn ngroups ndropped
 *               x[nnodes*dim]  node_tag[nnodes]  int type[ncells]
 *               ptr[ncells+1]  int conn[nconn]  cell_tag[ncells]
 *               int body[ncells]
 *               per group: size_t namelen  name  int dim tag  size_t n
 *               cell[n]  int hasface  int face[n] (if hasface)
 *               size_t nnodes  node[nnodes]
 *   "END!"
 */
#include "io/lac_mesh_wire.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "base/lac_mem.h"
#include "base/lac_status.h"

static const char magic[8] = "LACMESH1", trailer[4] = "END!";

/* ---------------------------------------------------------------------- */
/* writing (child side)                                                    */
/* ---------------------------------------------------------------------- */

typedef struct wbuf
{
  int fd, err;
  size_t n;
  unsigned char b[1 << 16];
} wbuf;

static void
flush (wbuf *w)
{
  size_t done = 0;
  while (!w->err && done < w->n)
    {
      ssize_t k = write (w->fd, w->b + done, w->n - done);
      if (k < 0 && errno == EINTR)
        continue;
      if (k <= 0)
        w->err = 1;
      else
        done += (size_t) k;
    }
  w->n = 0;
}

static void
put (wbuf *w, const void *p, size_t n)
{
  const unsigned char *s = p;
  while (n > 0 && !w->err)
    {
      size_t k = sizeof w->b - w->n < n ? sizeof w->b - w->n : n;
      memcpy (w->b + w->n, s, k);
      w->n += k;
      s += k;
      n -= k;
      if (w->n == sizeof w->b)
        flush (w);
    }
}

static void
put_size (wbuf *w, size_t v)
{
  put (w, &v, sizeof v);
}

static void
put_int (wbuf *w, int v)
{
  put (w, &v, sizeof v);
}

static void
put_group (wbuf *w, const lac_group *G)
{
  size_t len = strlen (G->name), n = G->dim >= 0 ? G->n : 0;
  put_size (w, len);
  put (w, G->name, len);
  put_int (w, G->dim);
  put_int (w, G->tag);
  put_size (w, n);
  put (w, G->cell, n * sizeof *G->cell);
  put_int (w, G->face != NULL);
  if (G->face)
    put (w, G->face, n * sizeof *G->face);
  put_size (w, G->nnodes);
  put (w, G->node, G->nnodes * sizeof *G->node);
}

static void
put_mesh (wbuf *w, const lac_mesh *m)
{
  size_t nconn = m->ptr[m->ncells];
  put_int (w, m->dim);
  put_size (w, m->nnodes);
  put_size (w, m->ncells);
  put_size (w, nconn);
  put_size (w, m->ngroups);
  put_size (w, m->ndropped);
  put (w, m->x, m->nnodes * (size_t) m->dim * sizeof *m->x);
  put (w, m->node_tag, m->nnodes * sizeof *m->node_tag);
  for (size_t c = 0; c < m->ncells; c++)
    put_int (w, (int) m->type[c]);
  put (w, m->ptr, (m->ncells + 1) * sizeof *m->ptr);
  put (w, m->conn, nconn * sizeof *m->conn);
  put (w, m->cell_tag, m->ncells * sizeof *m->cell_tag);
  put (w, m->body, m->ncells * sizeof *m->body);
  for (size_t g = 0; g < m->ngroups; g++)
    put_group (w, &m->group[g]);
}

/* lac_mesh_wire_write: see lac_mesh_wire.h.  The buffer is on the stack:
 * the answer must get through even when the child is out of memory. */
int
lac_mesh_wire_write (int fd, int status, const char *msg, const lac_mesh *m)
{
  wbuf w;
  w.fd = fd;
  w.err = 0;
  w.n = 0;
  if (!msg)
    msg = "";
  put (&w, magic, sizeof magic);
  put_int (&w, m || status ? status : LAC_ESANITY);
  put_size (&w, strlen (msg));
  put (&w, msg, strlen (msg));
  if (status == LAC_SUCCESS && m)
    put_mesh (&w, m);
  put (&w, trailer, sizeof trailer);
  flush (&w);
  return w.err ? -1 : 0;
}

/* ---------------------------------------------------------------------- */
/* reading (parent side)                                                   */
/* ---------------------------------------------------------------------- */

typedef struct rbuf
{
  const unsigned char *p;
  size_t left;
  int bad;
} rbuf;

/* The next n*size bytes, or NULL (and bad) if fewer remain. */
static const void *
take (rbuf *r, size_t n, size_t size)
{
  const void *p = r->p;
  if (r->bad || (size && n > r->left / size))
    {
      r->bad = 1;
      return NULL;
    }
  r->p += n * size;
  r->left -= n * size;
  return p;
}

static int
take_copy (rbuf *r, void *dst, size_t n, size_t size)
{
  const void *p = take (r, n, size);
  if (p && n)
    memcpy (dst, p, n * size);
  return p != NULL;
}

static size_t
get_size (rbuf *r)
{
  size_t v = 0;
  take_copy (r, &v, 1, sizeof v);
  return v;
}

static int
get_int (rbuf *r)
{
  int v = 0;
  take_copy (r, &v, 1, sizeof v);
  return v;
}

static int
get_group (rbuf *r, lac_group *G)
{
  size_t len = get_size (r);
  const char *name = take (r, len, 1);
  if (!name || len > 4096)
    return r->bad = 1, LAC_SUCCESS;
  if (!(G->name = lac_malloc (len + 1)))
    return LAC_ENOMEM;
  memcpy (G->name, name, len);
  G->name[len] = '\0';
  G->dim = get_int (r);
  G->tag = get_int (r);
  G->n = get_size (r);
  if (G->n > r->left / sizeof *G->cell)
    return r->bad = 1, LAC_SUCCESS;
  if (!(G->cell = lac_malloc (G->n * sizeof *G->cell)))
    return LAC_ENOMEM;
  take_copy (r, G->cell, G->n, sizeof *G->cell);
  if (get_int (r))
    {
      if (!(G->face = lac_malloc (G->n * sizeof *G->face)))
        return LAC_ENOMEM;
      take_copy (r, G->face, G->n, sizeof *G->face);
    }
  G->nnodes = get_size (r);
  if (G->nnodes > r->left / sizeof *G->node)
    return r->bad = 1, LAC_SUCCESS;
  if (!(G->node = lac_malloc (G->nnodes * sizeof *G->node)))
    return LAC_ENOMEM;
  take_copy (r, G->node, G->nnodes, sizeof *G->node);
  return LAC_SUCCESS;
}

/* The arrays of m (allocated for the counts of the header). */
static int
get_arrays (rbuf *r, lac_mesh *m, size_t nconn)
{
  take_copy (r, m->x, m->nnodes * (size_t) m->dim, sizeof *m->x);
  take_copy (r, m->node_tag, m->nnodes, sizeof *m->node_tag);
  for (size_t c = 0; c < m->ncells && !r->bad; c++)
    m->type[c] = (lac_elem_type) get_int (r);
  take_copy (r, m->ptr, m->ncells + 1, sizeof *m->ptr);
  take_copy (r, m->conn, nconn, sizeof *m->conn);
  take_copy (r, m->cell_tag, m->ncells, sizeof *m->cell_tag);
  take_copy (r, m->body, m->ncells, sizeof *m->body);
  if (!r->bad && m->ptr[m->ncells] != nconn)
    r->bad = 1;
  if (!r->bad && m->ngroups && !(m->group = lac_calloc (m->ngroups,
                                                        sizeof *m->group)))
    return LAC_ENOMEM;
  for (size_t g = 0; g < m->ngroups && !r->bad; g++)
    {
      int status = get_group (r, &m->group[g]);
      if (status)
        return status;
    }
  return LAC_SUCCESS;
}

/* The mesh part of the stream; counts checked against what remains. */
static int
get_mesh (rbuf *r, lac_mesh **out)
{
  int dim = get_int (r);
  size_t nnodes = get_size (r), ncells = get_size (r), nconn = get_size (r);
  size_t ngroups = get_size (r), ndropped = get_size (r), per;
  lac_mesh *m;
  int status;
  per = (size_t) (dim == 3 ? 3 : 2) * sizeof (double) + sizeof (size_t);
  if (r->bad || nnodes > r->left / per || ncells > r->left / 16
      || nconn > r->left / sizeof (int) || ngroups > r->left / 16)
    return r->bad = 1, LAC_SUCCESS;
  if (!(m = lac_mesh_alloc (dim, nnodes, ncells, nconn)))
    return dim == 2 || dim == 3 ? LAC_ENOMEM : (r->bad = 1, LAC_SUCCESS);
  m->ngroups = ngroups;
  m->ndropped = ndropped;
  status = get_arrays (r, m, nconn);
  if (status || r->bad)
    {
      m->ngroups = m->group ? m->ngroups : 0;
      lac_mesh_free (m);
      return status;
    }
  *out = m;
  return LAC_SUCCESS;
}

/* lac_mesh_wire_read: see lac_mesh_wire.h. */
int
lac_mesh_wire_read (const void *buf, size_t len, int *status, char *msg,
                    size_t msgsize, lac_mesh **out)
{
  rbuf r = { buf, len, 0 };
  const void *mg = take (&r, sizeof magic, 1), *t;
  size_t mlen;
  const char *m;
  int st = LAC_SUCCESS;
  *out = NULL;
  *status = LAC_ESANITY;
  if (msgsize)
    msg[0] = '\0';
  if (!mg || memcmp (mg, magic, sizeof magic) != 0)
    LAC_ERROR (LAC_EIO, "no mesh came back (%zu bytes)", len);
  *status = get_int (&r);
  mlen = get_size (&r);
  if ((m = take (&r, mlen, 1)) && msgsize)
    snprintf (msg, msgsize, "%.*s", (int) (mlen < msgsize ? mlen
                                                : msgsize - 1), m);
  if (!r.bad && *status == LAC_SUCCESS)
    st = get_mesh (&r, out);
  t = take (&r, sizeof trailer, 1);
  if (!st && (r.bad || !t || memcmp (t, trailer, sizeof trailer) != 0
              || r.left != 0))
    st = LAC_ERRMSG (LAC_EIO, "the mesh came back cut short or malformed");
  if (st)
    {
      lac_mesh_free (*out);
      *out = NULL;
    }
  return st;
}
