/* lac_mesh_msh_check.c -- an ASCII .msh file, line by line
 * (see lac_mesh_msh_check.h)
 *
 * A cursor walks the text line by line; each section is a small function
 * that reads its count lines and checks the numbers on each.  The node
 * counts of gmsh element types 1 to 31 are those of the MSH format
 * (gmsh reference manual, "MSH file format", element types).
 */
#include "io/lac_mesh_msh_check.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_status.h"
#include "fem/lac_spaces.h"

/* Nodes of gmsh element types 0..31 (0: no such type). */
static const signed char type_nodes[32] = {
  0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13, 9, 10,
  12, 15, 15, 21, 4, 5, 6, 20, 35, 56
};

/* Their dimensions and names (gmsh reference manual, element types). */
static const signed char type_dim[32] = {
  -1, 1, 2, 2, 3, 3, 3, 3, 1, 2, 2, 3, 3, 3, 3, 0, 2, 3, 3, 3, 2, 2, 2, 2,
  2, 2, 1, 1, 1, 3, 3, 3
};
static const char *const type_name[32] = {
  "?", "seg2", "tri3", "quad4", "tet4", "hex8", "prism6", "pyramid5",
  "seg3", "tri6", "quad9", "tet10", "hex27", "prism18", "pyramid14",
  "point", "quad8", "hex20", "prism15", "pyramid13", "tri9", "tri10",
  "tri12", "tri15", "tri15i", "tri21", "seg4", "seg5", "seg6", "tet20",
  "tet35", "tet56"
};

#define MAXTOK 64      /* numbers of one line that we look at */
/* Integers beyond this are refused: every count and tag then fits a long
 * long once converted back from the double it is kept in. */
#define INT_TOO_LARGE 1e18

/* A node or element tag and the line that gave it. */
typedef struct tag_line
{
  double tag;
  long line;
  int element;         /* 0 a node tag, 1 an element tag */
} tag_line;

typedef struct cur
{
  const char *path, *p, *end;
  long line;
  const char *s;       /* the current line, n bytes, no line feed */
  size_t n;
  int ntok;            /* numbers on it (all counted, MAXTOK kept) */
  double tok[MAXTOK];
  tag_line *tags;      /* owned, ntags: every node and element tag    */
  size_t ntags, captags;
  double tag_max;      /* the largest tag the format's reader takes    */
  lac_msh_counts *counts;   /* borrowed, may be NULL                    */
} cur;

static int
bad (const cur *c, const char *fmt, ...)
{
  char msg[512];
  va_list ap;
  va_start (ap, fmt);
  vsnprintf (msg, sizeof msg, fmt, ap);
  va_end (ap);
  return lac_error_set (LAC_EIO, "lac_mesh_read", "'%s': not a valid mesh "
                        "file: line %ld: %s", c->path, c->line, msg);
}

/* The next line into c->s, c->n; 0 at the end of the text. */
static int
next_line (cur *c, int *status)
{
  const char *nl;
  *status = LAC_SUCCESS;
  if (c->p >= c->end)
    return 0;
  nl = memchr (c->p, '\n', (size_t) (c->end - c->p));
  c->s = c->p;
  c->n = nl ? (size_t) (nl - c->p) : (size_t) (c->end - c->p);
  c->p += c->n + (nl ? 1 : 0);
  c->line++;
  if (c->n && c->s[c->n - 1] == '\r')
    c->n--;
  if (memchr (c->s, '\0', c->n))
    *status = bad (c, "a NUL byte (a binary file?)");
  else if (memchr (c->s, '\r', c->n))
    *status = bad (c, "a carriage return inside a line (old Mac line ends?"
                   " use LF or CR LF)");
  return 1;
}

/* Split the line into numbers; returns 0 (message set) if a word is not a
 * number (ints: not an integer). */
static int
numbers (cur *c, int ints, int *status)
{
  const char *q = c->s, *e = c->s + c->n;
  c->ntok = 0;
  while (q < e)
    {
      char word[64], *endp;
      size_t len = 0;
      double v;
      while (q < e && (*q == ' ' || *q == '\t'))
        q++;
      while (q + len < e && q[len] != ' ' && q[len] != '\t')
        len++;
      if (len == 0)
        break;
      snprintf (word, sizeof word, "%.*s", (int) (len < 63 ? len : 63), q);
      v = ints ? (double) strtoll (word, &endp, 10) : strtod (word, &endp);
      if (len > 62 || *endp != '\0' || endp == word || (ints && errno == ERANGE))
        return *status = bad (c, "'%.20s' is not %s", word, ints
                              ? "an integer" : "a number"), 0;
      if (ints && (v > INT_TOO_LARGE || v < -INT_TOO_LARGE))
        return *status = bad (c, "the integer '%.20s' is too large", word),
               0;
      if (c->ntok < MAXTOK)
        c->tok[c->ntok] = v;
      c->ntok++;
      q += len;
    }
  return 1;
}

/* The next line, as numbers; 0 (message set) at the end or on an error. */
static int
number_line (cur *c, int ints, const char *where, int *status)
{
  if (!next_line (c, status))
    return *status = bad (c, "the file ends inside %s", where), 0;
  if (*status)
    return 0;
  if (c->n && c->s[0] == '$')
    return *status = bad (c, "%.*s before the end of the lines %s "
                          "declares", (int) (c->n < 40 ? c->n : 40), c->s,
                          where), 0;
  errno = 0;
  return numbers (c, ints, status);
}

static int
is_line (const cur *c, const char *word)
{
  size_t n = strlen (word);
  return c->n == n && memcmp (c->s, word, n) == 0;
}

static int
expect_end (cur *c, const char *name)
{
  int status;
  if (!next_line (c, &status))
    return bad (c, "the file ends before $End%s", name);
  if (!status && (c->n < 4 || memcmp (c->s, "$End", 4) != 0
                  || c->n - 4 != strlen (name)
                  || memcmp (c->s + 4, name, c->n - 4) != 0))
    status = bad (c, "expected $End%s after the declared count", name);
  return status;
}

/* ---------------------------------------------------------------------- */
/* node tags                                                               */
/* ---------------------------------------------------------------------- */

int
lac_msh_type_dim (int t)
{
  return t >= 1 && t < 32 ? type_dim[t] : -1;
}

const char *
lac_msh_type_name (int t)
{
  return t >= 1 && t < 32 ? type_name[t] : "?";
}

/* One more element of gmsh type t (known) in the counts. */
static void
count_type (cur *c, int t)
{
  if (c->counts)
    c->counts->by_type[t]++, c->counts->by_dim[type_dim[t]]++;
}

/* The node (element = 0) or element tag t of the current line: a
 * positive integer gmsh reads without wrapping (MSH 2: an int, a tag
 * 2^32 + 1 was read as 1), kept with its line for the check of tags
 * given twice. */
static int
add_tag (cur *c, double t, int element)
{
  const char *what = element ? "element" : "node";
  if (t != floor (t))
    return bad (c, "%s tag %g is not an integer", what, t);
  if (t < 1 || t > c->tag_max)
    return bad (c, "%s tag %.0f is %s: gmsh reads the tags of this format "
                "as integers from 1 to %.0f", what, t, t < 1 ? "not "
                "positive" : "too large", c->tag_max);
  if (lac_grow (&c->tags, c->ntags + 1, &c->captags, sizeof *c->tags, 1024))
    return lac_error_set (LAC_ENOMEM, "lac_mesh_read", "'%s': the tags of "
                          "%zu nodes and elements", c->path, c->ntags + 1);
  c->tags[c->ntags++] = (tag_line) { t, c->line, element };
  return LAC_SUCCESS;
}

static int
by_tag_line (const void *a, const void *b)
{
  const tag_line *x = a, *y = b;
  if (x->element != y->element)
    return x->element - y->element;
  return x->tag != y->tag ? (x->tag > y->tag) - (x->tag < y->tag)
                          : (x->line > y->line) - (x->line < y->line);
}

/* No tag twice: gmsh keeps the coordinates of the last node of a tag
 * (the cells of both then share a node) and one element of a tag (a
 * hole in the mesh), without a word. */
static int
tags_distinct (cur *c)
{
  if (c->ntags > 1)
    qsort (c->tags, c->ntags, sizeof *c->tags, by_tag_line);
  for (size_t k = 1; k < c->ntags; k++)
    if (c->tags[k].tag == c->tags[k - 1].tag
        && c->tags[k].element == c->tags[k - 1].element)
      {
        c->line = c->tags[k].line;
        return bad (c, "%s tag %.0f is given twice (first at line %ld)",
                    c->tags[k].element ? "element" : "node",
                    c->tags[k].tag, c->tags[k - 1].line);
      }
  return LAC_SUCCESS;
}

/* ---------------------------------------------------------------------- */
/* sections                                                                */
/* ---------------------------------------------------------------------- */

/* A count on a line of its own (or the first number of a header line). */
static int
count_of (cur *c, const char *where, int nwant, long long *v, int *status)
{
  if (!number_line (c, 1, where, status))
    return 0;
  if (c->ntok != nwant)
    return *status = bad (c, "%s: expected %d number%s, found %d", where,
                          nwant, nwant > 1 ? "s" : "", c->ntok), 0;
  for (int i = 0; i < nwant; i++)
    if (c->tok[i] < 0)
      return *status = bad (c, "%s: a negative count", where), 0;
  *v = (long long) c->tok[0];
  return 1;
}

/* t (a number read as an integer) is a gmsh element type of the table. */
static int
known_type (double t)
{
  return t >= 1 && t <= 31 && type_nodes[(int) t] != 0;
}

/* One element line: tag type ntags tags... then the nodes of type. */
static int
element_22 (cur *c)
{
  int status, type, ntags, want;
  if (!number_line (c, 1, "$Elements", &status))
    return status;
  if (c->ntok < 3)
    return bad (c, "an element line needs at least 3 numbers (tag, type, "
                "number of tags), found %d", c->ntok);
  if (!known_type (c->tok[1]))
    return bad (c, "element %.0f has type %.0f, which lac does not read",
                c->tok[0], c->tok[1]);
  if (c->tok[2] < 0 || c->tok[2] > MAXTOK)
    return bad (c, "element %.0f has %.0f tags", c->tok[0], c->tok[2]);
  type = (int) c->tok[1];
  ntags = (int) c->tok[2];
  want = 3 + ntags + type_nodes[type];
  if (c->ntok != want)
    return bad (c, "element %.0f (type %d) has %d nodes after its tags, a "
                "type %d element has %d", c->tok[0], type,
                c->ntok - 3 - ntags, type, type_nodes[type]);
  count_type (c, type);
  return add_tag (c, c->tok[0], 1);
}

static int
nodes_22 (cur *c)
{
  long long n;
  int status;
  if (!count_of (c, "$Nodes", 1, &n, &status))
    return status;
  for (long long k = 0; k < n; k++)
    {
      if (!number_line (c, 0, "$Nodes", &status))
        return status;
      if (c->ntok != 4)
        return bad (c, "a node line has 4 numbers (tag x y z), found %d "
                    "(%lld nodes declared, this is node line %lld)",
                    c->ntok, n, k + 1);
      if ((status = add_tag (c, c->tok[0], 0)))
        return status;
    }
  return expect_end (c, "Nodes");
}

static int
elements_22 (cur *c)
{
  long long n;
  int status;
  if (!count_of (c, "$Elements", 1, &n, &status))
    return status;
  for (long long k = 0; k < n; k++)
    if ((status = element_22 (c)))
      return status;
  return expect_end (c, "Elements");
}

/* 4.1 $Nodes: header, then blocks of tags and coordinates. */
static int
nodes_41 (cur *c)
{
  long long nb, total = 0;
  int status;
  if (!number_line (c, 1, "$Nodes", &status))
    return status;
  if (c->ntok != 4 || c->tok[0] < 0 || c->tok[1] < 0)
    return bad (c, "the $Nodes header has 4 numbers (blocks, nodes, min and"
                " max tag), found %d", c->ntok);
  nb = (long long) c->tok[0];
  total = (long long) c->tok[1];
  for (long long b = 0; b < nb; b++)
    {
      long long n;
      int param, per;
      if (!number_line (c, 1, "$Nodes", &status))
        return status;
      if (c->ntok != 4 || c->tok[3] < 0 || c->tok[0] < 0 || c->tok[0] > 3)
        return bad (c, "a node block header has 4 numbers (dimension, "
                    "entity, parametric, nodes), found %d", c->ntok);
      param = c->tok[2] != 0;
      per = 3 + (param ? (int) c->tok[0] : 0);
      n = (long long) c->tok[3];
      if ((total -= n) < 0)
        return bad (c, "the node blocks hold more nodes than the header "
                    "says");
      for (long long k = 0; k < n; k++)
        if (!number_line (c, 1, "$Nodes", &status) || c->ntok != 1
            || (status = add_tag (c, c->tok[0], 0)))
          return status ? status : bad (c, "a node tag line has 1 number, "
                                        "found %d", c->ntok);
      for (long long k = 0; k < n; k++)
        if (!number_line (c, 0, "$Nodes", &status) || c->ntok != per)
          return status ? status : bad (c, "a node line of this block has "
                                        "%d numbers, found %d", per,
                                        c->ntok);
    }
  if (total != 0)
    return bad (c, "the node blocks hold %lld nodes fewer than the header "
                "says", total);
  return expect_end (c, "Nodes");
}

/* 4.1 $Elements: header, then blocks of one type. */
static int
elements_41 (cur *c)
{
  long long nb, total;
  int status;
  if (!number_line (c, 1, "$Elements", &status))
    return status;
  if (c->ntok != 4 || c->tok[0] < 0 || c->tok[1] < 0)
    return bad (c, "the $Elements header has 4 numbers (blocks, elements, "
                "min and max tag), found %d", c->ntok);
  nb = (long long) c->tok[0];
  total = (long long) c->tok[1];
  for (long long b = 0; b < nb; b++)
    {
      long long n;
      int type;
      if (!number_line (c, 1, "$Elements", &status))
        return status;
      if (c->ntok != 4 || c->tok[3] < 0)
        return bad (c, "an element block header has 4 numbers (dimension, "
                    "entity, type, elements), found %d", c->ntok);
      if (!known_type (c->tok[2]))
        return bad (c, "element type %.0f, which lac does not read",
                    c->tok[2]);
      type = (int) c->tok[2];
      n = (long long) c->tok[3];
      if ((total -= n) < 0)
        return bad (c, "the element blocks hold more elements than the "
                    "header says");
      for (long long k = 0; k < n; k++)
        {
          if (!number_line (c, 1, "$Elements", &status))
            return status;
          if (c->ntok != 1 + type_nodes[type])
            return bad (c, "element %.0f (type %d) has %d nodes, expected "
                        "%d", c->tok[0], type, c->ntok - 1,
                        type_nodes[type]);
          count_type (c, type);
          if ((status = add_tag (c, c->tok[0], 1)))
            return status;
        }
    }
  if (total != 0)
    return bad (c, "the element blocks hold %lld elements fewer than the "
                "header says", total);
  return expect_end (c, "Elements");
}

/* Any other section: its lines up to its $End line. */
static int
skip_section (cur *c, const char *name, size_t len)
{
  int status;
  while (next_line (c, &status))
    {
      if (status)
        return status;
      if (c->n == len + 4 && memcmp (c->s, "$End", 4) == 0
          && memcmp (c->s + 4, name, len) == 0)
        return LAC_SUCCESS;
    }
  return bad (c, "the file ends before $End%.*s", (int) len, name);
}

/* $MeshFormat: version 2.x or 4.1, ASCII (0) or binary (1). */
static int
mesh_format (cur *c, int *v4, int *binary)
{
  int status;
  if (!number_line (c, 0, "$MeshFormat", &status))
    return status;
  if (c->ntok != 3)
    return bad (c, "the $MeshFormat line has 3 numbers (version, file type,"
                " data size), found %d", c->ntok);
  if (!((c->tok[0] >= 2 && c->tok[0] < 3) || c->tok[0] == 4.1))
    return bad (c, "MSH version %g; lac reads versions 2.2 and 4.1",
                c->tok[0]);
  *v4 = c->tok[0] == 4.1;
  *binary = c->tok[1] != 0;
  return *binary ? LAC_SUCCESS : expect_end (c, "MeshFormat");
}

/* The sections of the file, in any order, after the $MeshFormat. */
static int
sections (cur *c, int v4)
{
  int status, nodes = 0, elements = 0;
  while (next_line (c, &status))
    {
      if (status)
        return status;
      if (c->n == 0)
        continue;
      if (c->s[0] != '$')
        return bad (c, "expected a section ($Nodes, $Elements, ...)");
      if (is_line (c, "$Nodes"))
        status = v4 ? nodes_41 (c) : nodes_22 (c), nodes++;
      else if (is_line (c, "$Elements"))
        status = v4 ? elements_41 (c) : elements_22 (c), elements++;
      else
        status = skip_section (c, c->s + 1, c->n - 1);
      if (status)
        return status;
    }
  if (!nodes || !elements)
    return bad (c, "no $%s section", nodes ? "Elements" : "Nodes");
  return LAC_SUCCESS;
}

/* The check of text, the elements counted into counts (may be NULL). */
static int
check_text (const char *path, const char *text, size_t len,
            lac_msh_counts *counts)
{
  cur c = { 0 };
  int status, v4 = 0, binary = 0;
  c.path = path;
  c.p = text;
  c.end = text + len;
  c.counts = counts;
  if (counts)
    memset (counts, 0, sizeof *counts);
  if (!next_line (&c, &status) || status || !is_line (&c, "$MeshFormat"))
    return status ? status : bad (&c, "expected $MeshFormat (is this a "
                                  ".msh file?)");
  if ((status = mesh_format (&c, &v4, &binary)) || binary)
    return status;
  c.tag_max = v4 ? INT_TOO_LARGE : INT_MAX;
  status = sections (&c, v4);
  if (!status)
    status = tags_distinct (&c);
  lac_free (c.tags);
  if (status && counts)
    memset (counts, 0, sizeof *counts);
  return status;
}

/* lac_msh_check_text: see lac_mesh_msh_check.h. */
int
lac_msh_check_text (const char *path, const char *text, size_t len)
{
  return check_text (path, text, len, NULL);
}

/* lac_msh_check: see lac_mesh_msh_check.h. */
int
lac_msh_check (const char *path, double max_bytes, lac_msh_counts *counts)
{
  char *text = NULL;
  size_t len = 0;
  int status = lac_input_read (path, max_bytes, "--max-memory", &text, &len);
  if (counts)
    memset (counts, 0, sizeof *counts);
  if (!status)
    status = check_text (path, text, len, counts);
  lac_free (text);
  return status;
}
