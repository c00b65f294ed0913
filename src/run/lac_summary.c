/* lac_summary.c -- "name = value" lines (see lac_summary.h) */
#include "run/lac_summary.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_mem.h"
#include "base/lac_status.h"

int
lac_summary_add (lac_summary *s, const char *key, const char *fmt, ...)
{
  char buf[512];
  va_list ap;
  size_t cap = s->cap;                   /* key and val share it */
  if (lac_grow (&s->key, s->n + 1, &cap, sizeof *s->key, 32)
      || lac_grow (&s->val, s->n + 1, &s->cap, sizeof *s->val, 32))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  va_start (ap, fmt);
  vsnprintf (buf, sizeof buf, fmt, ap);
  va_end (ap);
  s->key[s->n] = lac_strdup (key);
  s->val[s->n] = lac_strdup (buf);
  if (!s->key[s->n] || !s->val[s->n])
    {
      lac_free (s->key[s->n]);
      lac_free (s->val[s->n]);
      LAC_ERROR (LAC_ENOMEM, "out of memory");
    }
  s->n++;
  return LAC_SUCCESS;
}

int
lac_summary_add_vector (lac_summary *s, const char *key, const double *v,
                        int dim)
{
  if (dim == 3)                                   /* -0 + 0 = +0 */
    return lac_summary_add (s, key, LAC_SUMMARY_REAL " " LAC_SUMMARY_REAL " "
                            LAC_SUMMARY_REAL, v[0] + 0.0, v[1] + 0.0,
                            v[2] + 0.0);
  return lac_summary_add (s, key, LAC_SUMMARY_REAL " " LAC_SUMMARY_REAL,
                          v[0] + 0.0, v[1] + 0.0);
}

const char *
lac_summary_get (const lac_summary *s, const char *key)
{
  for (size_t k = 0; k < s->n; k++)
    if (strcmp (s->key[k], key) == 0)
      return s->val[k];
  return NULL;
}

void
lac_summary_clear (lac_summary *s)
{
  for (size_t k = 0; k < s->n; k++)
    lac_free (s->key[k]), lac_free (s->val[k]);
  lac_free (s->key);
  lac_free (s->val);
  memset (s, 0, sizeof *s);
}
