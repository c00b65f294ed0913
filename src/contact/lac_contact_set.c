/* lac_contact_set.c -- several contact pairs as one contact problem
 *                      (see lac_contact_set.h)
 *                                  [LAC §4.3, §4.6, Def. 1, (16)-(18)]
 */
#include "contact/lac_contact_set.h"

#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

int
lac_contact_set_init (lac_contact_set *s, lac_contact_pair *pair, size_t n)
{
  memset (s, 0, sizeof *s);
  if (n == 0 || !pair)
    LAC_ERROR (LAC_EINVAL, "a contact set of no pair");
  for (size_t p = 0; p < n; p++)
    {
      if (!pair[p].M || !pair[p].mesh)
        LAC_ERROR (LAC_EINVAL, "contact pair %zu has no macro-mesh", p);
      if (pair[p].nts && n > 1)
        LAC_ERROR (LAC_EINVAL, "contact pair %zu: node-to-segment is "
                   "compared on one pair only, not among %zu", p, n);
    }
  if (!(s->offset = lac_malloc ((n + 1) * sizeof *s->offset)))
    LAC_ERROR (LAC_ENOMEM, "offsets of %zu contact pairs", n);
  s->n = n;
  s->pair = pair;
  s->offset[0] = 0;
  for (size_t p = 0; p < n; p++)
    s->offset[p + 1] = s->offset[p] + pair[p].M->n;   /* slots of p */
  return LAC_SUCCESS;
}

void
lac_contact_set_clear (lac_contact_set *s)
{
  lac_free (s->offset);
  memset (s, 0, sizeof *s);
}

void
lac_contact_set_data_clear (lac_contact_set_data *d)
{
  if (d->n > 1)
    lac_contact_free (d->all);
  for (size_t p = 0; p < d->n; p++)
    {
      lac_pairing_free (d->P ? d->P[p] : NULL);
      lac_contact_free (d->c ? d->c[p] : NULL);
    }
  lac_free (d->P);
  lac_free (d->c);
  lac_free (d->col);
  memset (d, 0, sizeof *d);
}

size_t
lac_contact_set_nslot (const lac_contact_set *s)
{
  return s->offset ? s->offset[s->n] : 0;
}

size_t
lac_contact_set_pair_of (const lac_contact_set *s, size_t slot)
{
  size_t lo = 0, hi = s->n;            /* offset is increasing: bisection */
  if (slot >= lac_contact_set_nslot (s))
    return s->n;
  while (hi - lo > 1)
    {
      size_t mid = (lo + hi) / 2;
      if (s->offset[mid] <= slot)
        lo = mid;
      else
        hi = mid;
    }
  return lo;
}

/* d emptied and sized for the n pairs of s. */
static int
data_alloc (const lac_contact_set *s, lac_contact_set_data *d)
{
  lac_contact_set_data_clear (d);
  d->P = lac_calloc (s->n, sizeof *d->P);
  d->c = lac_calloc (s->n, sizeof *d->c);
  d->col = lac_calloc (s->n + 1, sizeof *d->col);
  if (!d->P || !d->c || !d->col)
    {
      lac_contact_set_data_clear (d);
      LAC_ERROR (LAC_ENOMEM, "contact data of %zu pairs", s->n);
    }
  d->n = s->n;
  return LAC_SUCCESS;
}

/* An error of pair p: d->failed says which (the caller names it). */
static int
pair_error (size_t p, lac_contact_set_data *d, int status)
{
  d->failed = p;
  return status;
}

/* Does pairing P of pair p give it anything to constrain? */
static int
has_pairs (const lac_contact_pair *p, const lac_pairing *P)
{
  return !p->master || (P && P->npairs > 0);    /* an obstacle: always */
}

/* Pair p found nothing within its reach (with allow_apart): an error
 * (its pairing's own) unless the pairing may be empty anyway, or the
 * pair's surfaces face each other farther away (they start apart). */
static int
check_apart (const lac_contact_set *s, const double *x, size_t p, int any,
             lac_contact_set_data *d)
{
  int facing = 0, status;
  if (s->pair[p].popts.allow_empty)
    return LAC_SUCCESS;
  if (any && (status = lac_contact_pair_facing (&s->pair[p], x, &facing)))
    return pair_error (p, d, status);
  if (any && facing)
    return LAC_SUCCESS;
  lac_pairing *P = NULL;          /* again, for the message of its pairing */
  status = lac_contact_pair_pairing (&s->pair[p], x, &P);
  lac_pairing_free (P);
  return pair_error (p, d, status ? status
                     : LAC_ERRMSG (LAC_ESANITY, "contact pair %zu: no pair, "
                                   "then pairs", p));
}

/* With several pairs, a pair whose surfaces start apart (nothing within
 * its reach, but they face each other farther away) is paired to
 * nothing, as the far part of one pair's surface is: the loop pairs it
 * again when the solution closes the gap (solve/lac_newton.h).  All of
 * them apart, or a pair whose surfaces never face: its pairing's error. */
int
lac_contact_set_pairing (const lac_contact_set *s, const double *x,
                         lac_contact_set_data *d)
{
  int status = data_alloc (s, d), any = 0;
  for (size_t p = 0; p < s->n && !status; p++)
    {
      lac_contact_pair q = s->pair[p];
      q.popts.allow_apart = s->n > 1;
      if ((status = lac_contact_pair_pairing (&q, x, &d->P[p])))
        return pair_error (p, d, status);
      any |= has_pairs (&q, d->P[p]);
    }
  for (size_t p = 0; p < s->n && !status; p++)
    if (!has_pairs (&s->pair[p], d->P[p]))
      status = check_apart (s, x, p, any, d);
  return status;
}

/* Pair p's per-macro-element arrays into the slots of all. */
static void
cat_macros (const lac_contact_set *s, size_t p, const lac_contact *c,
            size_t col0, lac_contact *all)
{
  const lac_macro *M = s->pair[p].M;
  for (size_t m = 0; m < M->n; m++)
    {
      size_t q = s->offset[p] + m;
      all->inode[q] = c ? c->inode[m] : M->inode[m];
      all->mult[q] = c && c->mult[m] >= 0 ? (long) col0 + c->mult[m] : -1;
      if (!c)
        continue;
      all->meas[q] = c->meas[m];
      all->covered[q] = c->covered[m];
      all->phiint[q] = c->phiint[m];
      all->crit[q] = c->crit[m];
      all->admissible[q] = c->admissible[m];
    }
}

/* Pair p's columns into all, from column col0 (C's column pointers
 * too: entries from nnz0). */
static void
cat_columns (const lac_contact_set *s, size_t p, const lac_contact *c,
             size_t col0, int nnz0, lac_contact *all)
{
  const lac_csc *C = c->C;
  for (size_t i = 0; i < c->k; i++)
    {
      size_t j = col0 + i;
      all->macro[j] = s->offset[p] + c->macro[i];
      all->G[j] = c->G[i];
      all->area[j] = c->area[i];
      all->size[j] = c->size[i];
      all->lost[j] = c->lost[i];
      all->C->p[j + 1] = nnz0 + C->p[i + 1];
    }
  memcpy (all->C->i + nnz0, C->i, (size_t) C->p[c->k] * sizeof *C->i);
  memcpy (all->C->x + nnz0, C->x, (size_t) C->p[c->k] * sizeof *C->x);
}

/* Pair p's tangential columns (friction) into all, from multiplier
 * col0 (entries from nnz0). */
static void
cat_tangential (const lac_contact *c, size_t col0, int nnz0,
                lac_contact *all)
{
  const lac_csc *T = c->Ct;
  size_t nt = (size_t) all->ntan, j0 = col0 * nt;
  for (size_t j = 0; j < c->k * nt; j++)
    {
      all->Ct->p[j0 + j + 1] = nnz0 + T->p[j + 1];
      all->sfix[j0 + j] = c->sfix[j];
    }
  for (size_t i = 0; i < c->k; i++)
    all->mu[col0 + i] = c->mu[i];
  memcpy (all->Ct->i + nnz0, T->i, (size_t) T->p[c->k * nt] * sizeof *T->i);
  memcpy (all->Ct->x + nnz0, T->x, (size_t) T->p[c->k * nt] * sizeof *T->x);
}

/* all->Ct, sfix, mu of the pairs (every pair has them, or none). */
static int
concatenate_tangential (const lac_contact_set *s, lac_contact_set_data *d)
{
  lac_contact *all = d->all;
  size_t nnz = 0, nt = 0;
  for (size_t p = 0; p < s->n; p++)
    if (d->c[p] && d->c[p]->Ct)
      {
        nt = (size_t) d->c[p]->ntan;
        nnz += (size_t) d->c[p]->Ct->p[d->c[p]->Ct->ncol];
      }
  if (nt == 0)
    return LAC_SUCCESS;
  all->ntan = (int) nt;
  all->Ct = lac_csc_alloc (all->C->nrow, all->k * nt, nnz ? nnz : 1);
  all->sfix = lac_calloc (all->k * nt, sizeof *all->sfix);
  all->mu = lac_calloc (all->k, sizeof *all->mu);
  if (!all->Ct || !all->sfix || !all->mu)
    LAC_ERROR (LAC_ENOMEM, "tangential columns of %zu multipliers", all->k);
  all->Ct->p[0] = 0;
  for (size_t p = 0; p < s->n; p++)
    if (d->c[p])
      cat_tangential (d->c[p], d->col[p], all->Ct->p[d->col[p] * nt], all);
  return LAC_SUCCESS;
}

/* all = the contact data of the n > 1 pairs side by side. */
static int
concatenate (const lac_contact_set *s, lac_contact_set_data *d)
{
  size_t k = 0, nnz = 0, ndof = 0;
  for (size_t p = 0; p < s->n; p++)
    {
      const lac_contact *c = d->c[p];
      d->col[p] = k;
      k += c ? c->k : 0;
      nnz += c ? (size_t) c->C->p[c->k] : 0;
      ndof = c ? c->C->nrow : ndof;
    }
  d->col[s->n] = k;
  if (k == 0)
    return LAC_SUCCESS;                          /* no column: all NULL */
  lac_contact *all = lac_contact_alloc (lac_contact_set_nslot (s));
  if (!all || !(all->C = lac_csc_alloc (ndof, k, nnz ? nnz : 1)))
    {
      lac_contact_free (all);
      LAC_ERROR (LAC_ENOMEM, "contact data of %zu multipliers", k);
    }
  all->k = k;
  all->C->p[0] = 0;
  for (size_t p = 0; p < s->n; p++)
    {
      cat_macros (s, p, d->c[p], d->col[p], all);
      if (d->c[p])
        cat_columns (s, p, d->c[p], d->col[p], all->C->p[d->col[p]], all);
    }
  d->all = all;
  return concatenate_tangential (s, d);
}

int
lac_contact_set_assemble (const lac_contact_set *s, const double *x,
                          lac_contact_set_data *d)
{
  int status;
  if (d->n != s->n)
    LAC_ERROR (LAC_ESANITY, "contact data of %zu pairs for a set of %zu",
               d->n, s->n);
  if (d->n > 1)
    lac_contact_free (d->all);
  d->all = NULL;
  for (size_t p = 0; p < s->n; p++)
    {
      lac_contact_free (d->c[p]);
      d->c[p] = NULL;
      if ((status = lac_contact_pair_contact (&s->pair[p], x, d->P[p],
                                              &d->c[p])))
        return pair_error (p, d, status);
    }
  if (s->n > 1)
    return concatenate (s, d);
  d->all = d->c[0];                              /* one pair: itself */
  d->col[1] = d->all ? d->all->k : 0;
  return LAC_SUCCESS;
}

int
lac_contact_set_build (const lac_contact_set *s, const double *x,
                       lac_contact_set_data *d)
{
  int status = lac_contact_set_pairing (s, x, d);
  return status ? status : lac_contact_set_assemble (s, x, d);
}

int
lac_contact_set_uncovered (const lac_contact_set *s, const double *x,
                           const lac_contact_set_data *d, double reach,
                           double tol, lac_contact_uncovered *u)
{
  memset (u, 0, sizeof *u);
  for (size_t p = 0; p < s->n; p++)
    {
      lac_contact_uncovered up;
      int status;
      if ((status = lac_contact_pair_uncovered (&s->pair[p], x,
                                                d->n ? d->c[p] : NULL, reach,
                                                tol, &up)))
        return status;
      size_t count = u->count + up.count;
      if (up.depth > 0 && (u->depth <= 0 || up.depth / up.h > u->depth / u->h))
        {
          *u = up;
          u->macro = s->offset[p] + up.macro;
        }
      u->count = count;
    }
  return LAC_SUCCESS;
}

size_t
lac_contact_set_dropped (const lac_contact_set_data *d, double *lost)
{
  size_t nfail = 0;
  *lost = 0;
  for (size_t p = 0; p < d->n; p++)
    {
      const lac_pairing *P = d->P[p];
      if (!P || !P->nfail)
        continue;
      nfail += P->nfail;
      for (size_t j = 0; j < P->nslave; j++)
        *lost += P->lost[j];
    }
  return nfail;
}
