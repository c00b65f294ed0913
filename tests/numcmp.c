/* numcmp.c -- compare two text files, numbers within a tolerance
 *
 *   numcmp [--rtol R] [--atol A] [--int exact|K|K%] [--as-written]
 *          EXPECTED ACTUAL
 *
 * Both files are cut into tokens at blanks and at the separators
 * = , : ; ( ) [ ] { } < > | (SUNDIALS testRunner, deal.II numdiff).  Tokens
 * are compared in order:
 *   - words must be equal;
 *   - two integers ([+-]digits) must be equal, or within K (--int K) or
 *     within K percent of the expected one (--int K%);
 *   - other numbers pass when |a - b| <= atol + rtol |b|, b the expected;
 *     an actual number a written with more significant digits than the
 *     expected one is first rounded to as many: a golden file written
 *     when lac printed 4 digits (3.581e-04) asserts those 4 digits, and a
 *     run that prints 17 (3.5814496508567589e-04) passes it exactly when
 *     the same run printing 4 digits would have.  --as-written: no
 *     rounding (the book's tables and output blocks, printed by the
 *     command that checks them: a digit more is a change).
 * Tolerances come from the command line, else from a first line of either
 * file "# numcmp: rtol=1e-8 atol=1e-12 int=exact" (that line is not
 * compared), else rtol = 1e-8, atol = 1e-12, int = exact.
 *
 * Silent when the files match (exit 0); otherwise prints the first
 * differences with their line numbers (exit 1).  Exit 2: bad usage or
 * unreadable file.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SEPARATORS " \t\r\n=,:;()[]{}<>|"
#define MAXSHOW 10

typedef struct token
{
  char *s;
  int line;
} token;

typedef struct tol
{
  double rtol, atol, ival;   /* ival: allowed integer difference       */
  int iperc;                 /* ival is a percentage                    */
  int have_r, have_a, have_i;
  int as_written;            /* 1: no rounding to the expected digits   */
} tol;

/* Read a whole file; NULL on error. */
static char *
slurp (const char *path)
{
  FILE *f = fopen (path, "rb");
  char *buf = NULL, *p;
  size_t len = 0, cap = 0, n;
  if (!f)
    return NULL;
  do
    {
      if (cap - len < 4096)
        {
          cap = cap ? 2 * cap : 65536;
          if (!(p = realloc (buf, cap)))
            {
              free (buf);
              fclose (f);
              return NULL;
            }
          buf = p;
        }
      n = fread (buf + len, 1, cap - len - 1, f);
      len += n;
    }
  while (n > 0);
  fclose (f);
  buf[len] = '\0';
  return buf;
}

/* "int=exact", "int=3", "int=10%" */
static int
parse_int_tol (const char *s, tol *t)
{
  char *end;
  if (strcmp (s, "exact") == 0)
    {
      t->ival = 0, t->iperc = 0;
      return 1;
    }
  if (*s == '+' || (s[0] == '-' && s[1] != '-'))   /* "+-3", "±" is UTF-8 */
    s++;
  if (strncmp (s, "-", 1) == 0)
    s++;
  t->ival = strtod (s, &end);
  t->iperc = *end == '%';
  return end != s && (*end == '\0' || (*end == '%' && end[1] == '\0'));
}

/* A first line "# numcmp: key=value ..." sets what the command line did
 * not; returns 1 if the first line is such a header. */
static int
read_header (const char *text, tol *t)
{
  char line[256], *tok, *save = NULL;
  const char *nl = strchr (text, '\n');
  size_t n = nl ? (size_t) (nl - text) : strlen (text);
  if (strncmp (text, "# numcmp:", 9) != 0 || n >= sizeof line)
    return 0;
  memcpy (line, text + 9, n - 9);
  line[n - 9] = '\0';
  for (tok = strtok_r (line, " \t", &save); tok;
       tok = strtok_r (NULL, " \t", &save))
    {
      if (strncmp (tok, "rtol=", 5) == 0 && !t->have_r)
        t->rtol = atof (tok + 5), t->have_r = 1;
      else if (strncmp (tok, "atol=", 5) == 0 && !t->have_a)
        t->atol = atof (tok + 5), t->have_a = 1;
      else if (strncmp (tok, "int=", 4) == 0 && !t->have_i)
        t->have_i = parse_int_tol (tok + 4, t);
    }
  return 1;
}

/* Cut text (after an optional header line) into tokens; *n tokens. */
static token *
tokenize (char *text, int skip_first, size_t *n)
{
  size_t cap = 1024;
  token *t = malloc (cap * sizeof *t);
  int line = 1;
  char *p = text;
  *n = 0;
  if (!t)
    return NULL;
  if (skip_first)
    {
      while (*p && *p != '\n')
        p++;
    }
  while (*p)
    {
      if (strchr (SEPARATORS, *p))
        {
          if (*p == '\n')
            line++;
          *p++ = '\0';
          continue;
        }
      if (*n == cap)
        {
          token *q = realloc (t, 2 * cap * sizeof *t);
          if (!q)
            {
              free (t);
              return NULL;
            }
          t = q, cap *= 2;
        }
      t[*n].s = p;
      t[(*n)++].line = line;
      while (*p && !strchr (SEPARATORS, *p))
        p++;
    }
  return t;
}

static int
is_int (const char *s)
{
  if (*s == '+' || *s == '-')
    s++;
  if (!isdigit ((unsigned char) *s))
    return 0;
  while (isdigit ((unsigned char) *s))
    s++;
  return *s == '\0';
}

static int
is_number (const char *s, double *x)
{
  char *end;
  const char *q = (*s == '+' || *s == '-') ? s + 1 : s;
  if (!isdigit ((unsigned char) *q) && *q != '.')
    return 0;                       /* "nan", "inf", words */
  *x = strtod (s, &end);
  return end != s && *end == '\0';
}

/* The significant digits of a number as written: the digits of its
 * mantissa after the leading zeros (0 for a zero). */
static int
sig_digits (const char *s)
{
  int n = 0, lead = 1;
  for (; *s && *s != 'e' && *s != 'E'; s++)
    if (isdigit ((unsigned char) *s))
      {
        lead = lead && *s == '0';
        n += !lead;
      }
  return n;
}

/* 1 if the tokens match under the tolerances. */
static int
match (const char *want, const char *got, const tol *t)
{
  double a, b;
  if (strcmp (want, got) == 0)
    return 1;
  if (!is_number (want, &b) || !is_number (got, &a))
    return 0;
  if (is_int (want) && is_int (got))
    {
      double lim = t->iperc ? t->ival / 100 * fabs (b) : t->ival;
      return fabs (a - b) <= lim;
    }
  int dw = sig_digits (want), dg = sig_digits (got);
  if (!t->as_written && dw > 0 && dg > dw)   /* a to b's printed digits */
    {
      char buf[64];
      snprintf (buf, sizeof buf, "%.*e", dw - 1, a);
      a = strtod (buf, NULL);
    }
  return fabs (a - b) <= t->atol + t->rtol * fabs (b);
}

static int
usage (void)
{
  fprintf (stderr, "usage: numcmp [--rtol R] [--atol A] [--int exact|K|K%%]"
           " [--as-written] EXPECTED ACTUAL\n");
  return 2;
}

int
main (int argc, char **argv)
{
  tol t = { 1e-8, 1e-12, 0, 0, 0, 0, 0, 0 };
  const char *path[2] = { NULL, NULL };
  char *text[2];
  token *tok[2];
  size_t n[2], bad = 0, np = 0;
  int hdr[2];
  for (int k = 1; k < argc; k++)
    {
      if (strcmp (argv[k], "--rtol") == 0 && k + 1 < argc)
        t.rtol = atof (argv[++k]), t.have_r = 1;
      else if (strcmp (argv[k], "--atol") == 0 && k + 1 < argc)
        t.atol = atof (argv[++k]), t.have_a = 1;
      else if (strcmp (argv[k], "--int") == 0 && k + 1 < argc)
        {
          if (!parse_int_tol (argv[++k], &t))
            return usage ();
          t.have_i = 1;
        }
      else if (strcmp (argv[k], "--as-written") == 0)
        t.as_written = 1;
      else if (argv[k][0] == '-' && argv[k][1] != '\0')
        return usage ();
      else if (np < 2)
        path[np++] = argv[k];
      else
        return usage ();
    }
  if (np != 2)
    return usage ();
  for (int f = 0; f < 2; f++)
    if (!(text[f] = slurp (path[f])))
      {
        fprintf (stderr, "numcmp: cannot read %s\n", path[f]);
        return 2;
      }
  for (int f = 0; f < 2; f++)
    hdr[f] = read_header (text[f], &t);
  for (int f = 0; f < 2; f++)
    if (!(tok[f] = tokenize (text[f], hdr[f], &n[f])))
      {
        fprintf (stderr, "numcmp: out of memory\n");
        return 2;
      }
  for (size_t k = 0; k < n[0] && k < n[1]; k++)
    if (!match (tok[0][k].s, tok[1][k].s, &t) && bad++ < MAXSHOW)
      printf ("numcmp: %s:%d: expected '%s', %s:%d: got '%s'\n", path[0],
              tok[0][k].line, tok[0][k].s, path[1], tok[1][k].line,
              tok[1][k].s);
  if (n[0] != n[1])
    {
      printf ("numcmp: %s has %zu tokens, %s has %zu\n", path[0], n[0],
              path[1], n[1]);
      bad++;
    }
  if (bad)
    printf ("numcmp: %zu difference%s (rtol=%g atol=%g)\n", bad,
            bad > 1 ? "s" : "", t.rtol, t.atol);
  for (int f = 0; f < 2; f++)
    free (tok[f]), free (text[f]);
  return bad ? 1 : 0;
}
