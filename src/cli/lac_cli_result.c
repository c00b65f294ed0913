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

/* Coulomb's mu from the effects line of DIR/summary.txt. */
int
lac_cli_result_mu (const char *dir, double *mu)
{
  char effects[1024], *p, *end;
  if (!summary_value (dir, "effects", effects, sizeof effects)
      || !(p = strstr (effects, "mu = ")))
    return 0;
  *mu = strtod (p + 5, &end);
  return end != p + 5 && isfinite (*mu) && *mu > 0;
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
  lac_free (r->lt);
  lac_free (r->status);
  lac_free (r->sc);
}

/* The columns of contact.csv that render reads; the required ones first. */
enum { C_X, C_Y, C_Z, C_MEAS, C_ADM, C_LAM, C_GAP, NREQUIRED = C_GAP + 1,
       C_LEX = NREQUIRED, C_LT, C_LT1, C_LT2, C_STATUS, C_S, NCOLS };
static const char *const column_names[NCOLS] = {
  "x", "y", "z", "measure", "admissible", "lambda", "mean_gap",
  "lambda_exact", "lambda_t", "lambda_t1", "lambda_t2", "status", "s" };

/* Column index of each wanted name in the CSV header line; the first
 * required one missing, or -1. */
static int
csv_columns (char *head, int *col)
{
  int k = 0;
  for (int i = 0; i < NCOLS; i++)
    col[i] = -1;
  for (char *t = strtok (head, ",\r\n"); t; t = strtok (NULL, ",\r\n"), k++)
    for (int i = 0; i < NCOLS; i++)
      if (!strcmp (t, column_names[i]))
        col[i] = k;
  for (int i = 0; i < NREQUIRED; i++)
    if (col[i] < 0)
      return i;
  return -1;
}

/* One row: the numbers by column (NaN: empty or no such column) and the
 * status. */
typedef struct csv_row
{
  double v[NCOLS];
  signed char status;
} csv_row;

static int
rows_add (macro_rows *r, size_t *cap, const csv_row *w)
{
  if (r->n == *cap)
    {
      size_t c = *cap ? 2 * *cap : 64;
      double **dst[7] = { &r->x, &r->meas, &r->lam, &r->lex, &r->gap,
                          &r->lt, &r->sc };
      signed char *st = lac_realloc (r->status, c);
      if (!st)
        return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
      r->status = st;
      for (int i = 0; i < 7; i++)
        {
          double *p = lac_realloc (*dst[i], (i ? 1 : 3) * c * sizeof *p);
          if (!p)
            return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
          *dst[i] = p;
        }
      *cap = c;
    }
  for (int i = 0; i < 3; i++)                    /* no coordinate: 0 */
    r->x[3 * r->n + (size_t) i] = isnan (w->v[C_X + i]) ? 0 : w->v[C_X + i];
  r->meas[r->n] = isnan (w->v[C_MEAS]) ? 0 : w->v[C_MEAS];
  r->lam[r->n] = isnan (w->v[C_LAM]) ? 0 : w->v[C_LAM];
  r->lex[r->n] = w->v[C_LEX];
  r->gap[r->n] = isnan (w->v[C_GAP]) ? 0 : w->v[C_GAP];
  r->lt[r->n] = r->friction && isnan (w->v[C_LT])   /* 3D: the modulus */
                ? hypot (w->v[C_LT1], w->v[C_LT2]) : w->v[C_LT];
  r->sc[r->n] = w->v[C_S];
  r->status[r->n++] = w->status;
  return LAC_SUCCESS;
}

/* The fields of one line of contact.csv (modified in place) into *w; 0,
 * or 1 if the status is none of stick, slip, inactive (then *bad points to
 * it). */
static int
csv_row_read (char *line, const int *col, csv_row *w, const char **bad)
{
  int k = 0, wrong = 0;
  for (int i = 0; i < NCOLS; i++)
    w->v[i] = NAN;
  w->status = LAC_CLI_NO_STATUS;
  for (char *t = line; t; k++)          /* empty fields: no value */
    {
      char *e = t + strcspn (t, ",\r\n");
      int last = *e != ',';
      *e = '\0';
      for (int i = 0; i < NCOLS; i++)
        if (col[i] == k && *t && i != C_STATUS)
          w->v[i] = strtod (t, NULL);
        else if (col[i] == k && *t)
          {
            w->status = !strcmp (t, "stick") ? LAC_CLI_STICK
                        : !strcmp (t, "slip") ? LAC_CLI_SLIP
                        : !strcmp (t, "inactive") ? LAC_CLI_INACTIVE
                        : LAC_CLI_NO_STATUS;
            if (w->status == LAC_CLI_NO_STATUS && !wrong)
              wrong = 1, *bad = t;
          }
      t = last ? NULL : e + 1;
    }
  return wrong;
}

/* The admissible rows of DIR/contact.csv. */
int
lac_cli_result_contact (const char *dir, macro_rows *r)
{
  char path[4096], line[4096];
  int col[NCOLS], miss, status = LAC_SUCCESS;
  size_t cap = 0, lineno = 1;
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
  if ((miss = csv_columns (line, col)) >= 0)
    {
      fclose (fp);
      LAC_ERROR (LAC_EIO, "'%s': no column '%s' in the header", path,
                 column_names[miss]);
    }
  r->friction = col[C_STATUS] >= 0
                && (col[C_LT] >= 0 || (col[C_LT1] >= 0 && col[C_LT2] >= 0));
  while (!status && fgets (line, sizeof line, fp))
    {
      csv_row w;
      const char *bad = NULL;
      lineno++;
      if (csv_row_read (line, col, &w, &bad))
        {
          char where[4200];
          snprintf (where, sizeof where, "%s:%zu", path, lineno);
          status = lac_error_place (LAC_EIO, where, "status '%.40s': "
                                    "expected stick, slip or inactive",
                                    bad);
        }
      else if (!isnan (w.v[C_ADM]) && w.v[C_ADM] != 0)
        status = rows_add (r, &cap, &w);
    }
  fclose (fp);
  if (!status && r->n == 0)
    status = LAC_ERRMSG (LAC_EINVAL, "'%s' has no admissible "
                         "macro-element", path);
  return status;
}
