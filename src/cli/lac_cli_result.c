/* lac_cli_result.c -- summary.txt and contact.csv of a result directory
 * (see lac_cli_result.h), for `lac render`.
 */
#include "cli/lac_cli_result.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"

/* The value of `key` in DIR/summary.txt ("key = value"); 0 if absent. */
static int
summary_value (const char *dir, const char *key, char *buf, size_t len)
{
  char path[4096], line[1024];
  size_t n = strlen (key);
  FILE *fp;
  int found = 0;
  snprintf (path, sizeof path, "%s/summary.txt", dir);
  if (lac_input_check (path, HUGE_VAL, "", NULL) || !(fp = fopen (path, "r")))
    return 0;                    /* (a named pipe there would block) */
  while (!found && fgets (line, sizeof line, fp))
    if (!strncmp (line, key, n) && !strncmp (line + n, " = ", 3))
      {
        size_t l = strcspn (line + n + 3, "\r\n");
        l = l < len ? l : len - 1;
        memcpy (buf, line + n + 3, l);
        buf[l] = '\0';
        found = 1;
      }
  fclose (fp);
  return found;
}

/* The title of the run (summary.txt), or the directory's last name. */
void
lac_cli_result_title (const char *dir, char *buf, size_t len)
{
  size_t n = strlen (dir);
  const char *p;
  if (summary_value (dir, "title", buf, len))
    return;
  while (n > 1 && dir[n - 1] == '/')
    n--;
  for (p = dir + n; p > dir && p[-1] != '/'; p--)
    ;
  snprintf (buf, len, "%.*s", (int) (dir + n - p), p);
}

/* Free the arrays of r (not r). */
void
lac_cli_result_contact_free (macro_rows *r)
{
  lac_free (r->x);
  lac_free (r->meas);
  lac_free (r->lam);
  lac_free (r->lex);
  lac_free (r->gap);
}

/* Column index of each wanted name in the CSV header line. */
static int
csv_columns (char *head, const char *const *want, int nwant, int *col)
{
  int k = 0;
  for (int i = 0; i < nwant; i++)
    col[i] = -1;
  for (char *t = strtok (head, ",\r\n"); t; t = strtok (NULL, ",\r\n"), k++)
    for (int i = 0; i < nwant; i++)
      if (!strcmp (t, want[i]))
        col[i] = k;
  for (int i = 0; i < nwant; i++)
    if (col[i] < 0 && i != 6)                /* lambda_exact: optional */
      return i;
  return -1;
}

static int
rows_add (macro_rows *r, size_t *cap, const double *v)
{
  if (r->n == *cap)
    {
      size_t c = *cap ? 2 * *cap : 64;
      double **dst[5] = { &r->x, &r->meas, &r->lam, &r->lex, &r->gap };
      for (int i = 0; i < 5; i++)
        {
          double *p = lac_realloc (*dst[i], (i ? 1 : 3) * c * sizeof *p);
          if (!p)
            return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
          *dst[i] = p;
        }
      *cap = c;
    }
  memcpy (r->x + 3 * r->n, v, 3 * sizeof *v);
  r->meas[r->n] = v[3];
  r->lam[r->n] = v[5];
  r->lex[r->n] = v[6];
  r->gap[r->n++] = v[7];
  return LAC_SUCCESS;
}

/* The admissible rows of DIR/contact.csv. */
int
lac_cli_result_contact (const char *dir, macro_rows *r)
{
  static const char *const want[8] = { "x", "y", "z", "measure",
                                       "admissible", "lambda",
                                       "lambda_exact", "mean_gap" };
  char path[4096], line[4096];
  int col[8], miss, status = LAC_SUCCESS;
  size_t cap = 0;
  FILE *fp;
  memset (r, 0, sizeof *r);
  snprintf (path, sizeof path, "%s/contact.csv", dir);
  if ((status = lac_input_check (path, HUGE_VAL, "", NULL)))
    {
      const char *m = lac_error_message ();      /* "PATH: reason" */
      size_t n = strlen (path);
      if (!strncmp (m, path, n) && !strncmp (m + n, ": ", 2))
        m += n + 2;
      return lac_error_place (status, path, "%s; --contact needs the "
                              "contact.csv of a run with a [contact] "
                              "section", m);
    }
  if (!(fp = fopen (path, "r")))
    LAC_ERROR (LAC_EIO, "cannot open '%s' (%s): --contact needs the "
               "contact.csv of a run with a [contact] section", path,
               strerror (errno));
  if (!fgets (line, sizeof line, fp))
    {
      fclose (fp);
      LAC_ERROR (LAC_EIO, "'%s' is empty", path);
    }
  if ((miss = csv_columns (line, want, 8, col)) >= 0)
    {
      fclose (fp);
      LAC_ERROR (LAC_EIO, "'%s': no column '%s' in the header", path,
                 want[miss]);
    }
  while (!status && fgets (line, sizeof line, fp))
    {
      double v[8] = { 0, 0, 0, 0, 0, 0, NAN, 0 };
      int k = 0;
      for (char *t = line; t; k++)          /* empty fields: no value */
        {
          char *e = t + strcspn (t, ",\r\n");
          int last = *e != ',';
          *e = '\0';
          for (int i = 0; i < 8; i++)
            if (col[i] == k && *t)
              v[i] = strtod (t, NULL);
          t = last ? NULL : e + 1;
        }
      if (v[4] != 0)
        status = rows_add (r, &cap, v);
    }
  fclose (fp);
  if (!status && r->n == 0)
    status = LAC_ERRMSG (LAC_EINVAL, "'%s' has no admissible "
                         "macro-element", path);
  return status;
}

