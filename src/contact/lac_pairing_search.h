/* lac_pairing_search.h -- the search of the pairing: pass 1    [LAC §4.6]
 *
 * Which (slave, master) pairs overlap (lac_pairing_search.c: the facet
 * lists, their adjacency, the bucket grid and the advancing front).  The
 * driver lac_pairing_build (lac_pairing.c) runs it, then computes the
 * points of the pairs it found, reading the two sides and the facets in
 * work of a lac_pairing_search.
 *
 * Ownership: a lac_pairing_search owns every array it points to
 * (lac_pairing_search_free), and borrows the facet lists, their meshes and
 * the options for its lifetime.
 */
#ifndef LAC_PAIRING_SEARCH_H
#define LAC_PAIRING_SEARCH_H

#include <stddef.h>
#include <stdint.h>

#include "contact/lac_pairing_geom.h"
#include "contact/lac_pairing_types.h"

#define LAC_PAIRING_NONE SIZE_MAX

typedef struct lac_pairing_side
{
  const lac_pairing_facets *f;  /* borrowed                                */
  int sdim;
  lac_elem_type *type;          /* owned, n                                */
  int *node;                    /* owned, n*LAC_MAX_FACE_NODES             */
  size_t *vid;                  /* owned, n*4: compressed vertex ids, NONE
                                   past the facet's vertices               */
  size_t nv;                    /* distinct vertices                       */
  size_t *vptr;                 /* owned, nv+1: facets of vertex v are     */
  size_t *vfac;                 /*   vfac[vptr[v] .. vptr[v+1]-1] (owned)  */
} lac_pairing_side;

typedef struct lac_pairing_grid
{
  int sdim;
  double lo[3], hg;   /* origin and cell size                            */
  size_t mask;        /* number of buckets - 1 (a power of 2 minus 1)     */
  size_t *bptr;       /* owned, mask+2: facets of bucket b are           */
  size_t *bfac;       /*   bfac[bptr[b] .. bptr[b+1]-1] (owned)           */
  double *box;        /* owned, 6n: facet bounding boxes                 */
  size_t nbig;        /* facets meeting more than LAC_PAIRING_BIG cells,  */
  size_t *big;        /*   kept apart, listed by every query (owned)      */
} lac_pairing_grid;

#define LAC_PAIRING_BIG 512

typedef struct lac_pairing_search
{
  const lac_pairing_opts *o;
  lac_pairing_side S, M;
  lac_pairing_grid G;
  size_t *mst;        /* owned, nm: the last slave facet m was tested with */
  size_t *gst;        /* owned, nm: the last query that listed m          */
  size_t nquery;
  size_t *mq;         /* owned, nm: the master front (a FIFO)              */
  size_t *cand;       /* owned, nm: candidates of a grid query             */
  size_t *sq;         /* owned, ns: the slave front (a FIFO)               */
  size_t sqh, sqt;    /* its head and tail                                 */
  size_t *donor;      /* owned, ns: slave facet whose masters seed it      */
  char *state;        /* owned, ns: 0 new, 1 queued, 2 done               */
  size_t *pbeg;       /* owned, ns: pairs of s are pm[pbeg[s] ..           */
  size_t *pcnt;       /*   pbeg[s]+pcnt[s]-1] (owned, ns)                  */
  size_t np, cap;     /* pairs found so far, capacity                     */
  size_t *pm;         /* owned, cap: master of each pair                  */
  lac_pairing_facet sf, mf;   /* the slave facet in work, a master facet  */
  double cov;         /* fraction of the slave facet in work covered so far
                         (in its chart)                                   */
  size_t ntests, nseeds, nfacing, nfar;
} lac_pairing_search;

/* construct / destroy (memset the struct to 0 before init) */
int lac_pairing_search_init (lac_pairing_search *W,
                             const lac_pairing_facets *slave,
                             const lac_pairing_facets *master,
                             const lac_pairing_opts *o);
void lac_pairing_search_free (lac_pairing_search *W);

/* compute: pass 1, the pairs found: masters of slave s are
 * W->pm[W->pbeg[s] .. W->pbeg[s] + W->pcnt[s] - 1] */
int lac_pairing_search_run (lac_pairing_search *W);

/* query */
int lac_pairing_side_facet (const lac_pairing_side *S, size_t i,
                            lac_pairing_facet *F, const char *what);
double lac_pairing_gap_bound (const lac_pairing_search *W); /* sf, mf */

#endif /* LAC_PAIRING_SEARCH_H */
