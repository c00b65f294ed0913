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
  if (s->n == s->cap)
    {
      size_t cap = s->cap ? 2 * s->cap : 32;
      char **k = lac_realloc (s->key, cap * sizeof *k);
      char **v = k ? lac_realloc (s->val, cap * sizeof *v) : NULL;
      if (k)
        s->key = k;
      if (!v)
        LAC_ERROR (LAC_ENOMEM, "out of memory");
      s->val = v;
      s->cap = cap;
    }
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
