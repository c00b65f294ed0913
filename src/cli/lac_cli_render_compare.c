/* lac_cli_render_compare.c -- the curve of --compare FILE (see the
 * header): every line is checked before the picture is drawn, so that a
 * bad file leaves the earlier picture, data and script as they were.
 */
#include "cli/lac_cli_render_compare.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "base/lac_file.h"
#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_number.h"
#include "base/lac_status.h"

void
lac_cli_render_compare_free (render_compare *c)
{
  lac_free (c->s);
  lac_free (c->v);
  c->s = c->v = NULL;
  c->n = 0;
}

/* The title: the comment's text after '#' and the spaces, control bytes
 * as spaces (it goes into a gnuplot string on one line). */
static void
set_title (render_compare *c, const char *text, size_t len)
{
  size_t k = 0;
  while (len > 0 && (*text == ' ' || *text == '\t'))
    text++, len--;
  for (; k < len && k + 1 < sizeof c->title; k++)
    c->title[k] = (unsigned char) text[k] < 0x20 ? ' ' : text[k];
  c->title[k] = '\0';
}

static int
add_point (render_compare *c, size_t *cap, double s, double v)
{
  if (c->n == *cap)
    {
      size_t n = *cap ? 2 * *cap : 256;
      double *ps = lac_realloc (c->s, n * sizeof *ps), *pv;
      if (!ps)
        return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
      c->s = ps;
      if (!(pv = lac_realloc (c->v, n * sizeof *pv)))
        return LAC_ERRMSG (LAC_ENOMEM, "out of memory");
      c->v = pv;
      *cap = n;
    }
  c->s[c->n] = s;
  c->v[c->n++] = v;
  return LAC_SUCCESS;
}

/* One data line (NUL-terminated, no line feed): two finite numbers. */
static int
parse_point (char *line, const char *where, render_compare *c, size_t *cap)
{
  char *save = NULL, *tok[3] = { NULL, NULL, NULL }, why[200];
  double x[2];
  int n = 0;
  for (char *t = strtok_r (line, " \t", &save); t && n < 3;
       t = strtok_r (NULL, " \t", &save))
    tok[n++] = t;
  if (n != 2)
    return lac_error_place (LAC_EINVAL, where, "expected two numbers "
                            "(s and the value), found %s", n < 2
                            ? "one" : "more");
  for (int i = 0; i < 2; i++)
    if (!lac_number_parse (tok[i], NULL, &x[i], why, sizeof why))
      return lac_error_place (LAC_EINVAL, where, "%s %s", i ? "the value:"
                              : "s:", why);
  return add_point (c, cap, x[0], x[1]);
}

int
lac_cli_render_compare_read (const char *path, render_compare *c)
{
  char *text = NULL, *line, where[4200];
  size_t len = 0, cap = 0, lineno = 0;
  int status, titled = 0;
  memset (c, 0, sizeof *c);
  if ((status = lac_input_read (path, HUGE_VAL, "", &text, &len)))
    return status;
  for (line = text; !status && line < text + len; )
    {
      size_t n = strcspn (line, "\n");
      char *next = line + n + (line[n] == '\n');
      const char *p = line;
      line[n] = '\0';
      if (n > 0 && line[n - 1] == '\r')
        line[n - 1] = '\0';
      lineno++;
      snprintf (where, sizeof where, "%s:%zu", path, lineno);
      p += strspn (p, " \t");
      if (*p == '#' && !titled)
        titled = 1, set_title (c, p + 1, strlen (p + 1));
      else if (*p && *p != '#')
        status = parse_point (line, where, c, &cap);
      line = next;
    }
  lac_free (text);
  if (!status && c->n == 0)
    status = lac_error_place (LAC_EINVAL, path, "no point (expected lines "
                              "of two numbers, s and the value)");
  if (!status && !c->title[0])
    {
      const char *b = strrchr (path, '/');
      set_title (c, b ? b + 1 : path, strlen (b ? b + 1 : path));
    }
  return status;
}

int
lac_cli_render_compare_write (const char *path, const render_compare *c)
{
  FILE *fp;
  int status = lac_file_create (path, "w", &fp);
  if (status)
    return status;
  fprintf (fp, "# %s\n", c->title);
  for (size_t k = 0; k < c->n; k++)
    fprintf (fp, "%.10e %.10e\n", c->s[k], c->v[k]);
  return lac_file_close (fp, path);
}
