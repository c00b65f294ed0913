/* lac_macro_list.c -- the macro-elements of T^M under construction
 *                                                      [LAC Hyp. 1, §4.4]
 *
 * The list that the steps of lac_macromesh_build pass on (see
 * lac_macro_list.h): its arrays, appending a macro-element (step 2), and
 * remapping the facet lists through one refinement round (step 3).
 */
#include "contact/lac_macro_list.h"

#include <string.h>

#include "base/lac_mem.h"

int
lac_macro_list_init (lac_macro_list *L, size_t nfacets)
{
  size_t n = nfacets;
  L->n = 0;
  L->ptr = lac_malloc ((n + 1) * sizeof *L->ptr);
  L->cell = lac_malloc (n * sizeof *L->cell);
  L->face = lac_malloc (n * sizeof *L->face);
  L->pending = lac_malloc (n * sizeof *L->pending);
  if (!L->ptr || !L->cell || !L->face || !L->pending)
    {
      lac_macro_list_free (L);
      LAC_MACRO_ERROR (LAC_ENOMEM, "macro-elements of %zu facets", n);
    }
  L->ptr[0] = 0;
  return LAC_SUCCESS;
}

void
lac_macro_list_free (lac_macro_list *L)
{
  lac_free (L->ptr);
  lac_free (L->cell);
  lac_free (L->face);
  lac_free (L->pending);
  memset (L, 0, sizeof *L);
}

void
lac_macro_list_push (lac_macro_list *L, const lac_group *G, const size_t *e,
                     size_t n, int pending)
{
  size_t j = L->ptr[L->n];
  for (size_t i = 0; i < n; i++, j++)
    {
      L->cell[j] = G->cell[e[i]];
      L->face[j] = G->face[e[i]];
    }
  L->pending[L->n] = (unsigned char) pending;
  L->ptr[++L->n] = j;
}

/* lac_macro_list_remap: count the pieces, then copy them macro-element by
 * macro-element (ptr is rewritten in place). */
int
lac_macro_list_remap (lac_macro_list *L, const lac_refine_map *map)
{
  size_t n = 0, *cell, *ptr = L->ptr;
  int *face;

  for (size_t j = 0; j < ptr[L->n]; j++)
    {
      size_t q = L->cell[j] * LAC_MAX_FACES + (size_t) L->face[j];
      n += map->fptr[q + 1] - map->fptr[q];
    }
  cell = lac_malloc (n * sizeof *cell);
  face = lac_malloc (n * sizeof *face);
  if (!cell || !face)
    {
      lac_free (cell);
      lac_free (face);
      LAC_MACRO_ERROR (LAC_ENOMEM, "macro-element facets (%zu)", n);
    }
  n = 0;
  for (size_t k = 0; k < L->n; k++)
    {
      size_t j0 = ptr[k], j1 = ptr[k + 1];
      ptr[k] = n;
      for (size_t j = j0; j < j1; j++)
        {
          size_t q = L->cell[j] * LAC_MAX_FACES + (size_t) L->face[j];
          for (size_t p = map->fptr[q]; p < map->fptr[q + 1]; p++, n++)
            {
              cell[n] = map->fcell[p];
              face[n] = map->fface[p];
            }
        }
    }
  ptr[L->n] = n;
  lac_free (L->cell);
  lac_free (L->face);
  L->cell = cell;
  L->face = face;
  return LAC_SUCCESS;
}
