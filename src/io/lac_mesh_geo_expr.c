/* lac_mesh_geo_expr.c -- the value of a .geo expression
 * (see lac_mesh_geo_expr.h)
 *
 * A recursive-descent reader of gmsh's expressions with the precedence of
 * gmsh's grammar (Gmsh.y), lowest first: ?:, ||, &&, == !=, < > <= >=,
 * + -, * / %, unary - + !, ^.  Each level returns a value and clears
 * e->ok when it meets what it cannot follow; the caller then ignores the
 * value.  Nesting is bounded (LAC_GEO_DEPTH), so that no script, however
 * deep its parentheses, can overflow the stack.
 */
#include "io/lac_mesh_geo_expr.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LAC_GEO_DEPTH 64

int
lac_geo_ident_char (char c)
{
  return c == '_' || isalnum ((unsigned char) c);
}

void
lac_geo_skip (lac_geo_scan *c)
{
  while (c->p < c->end)
    {
      if (*c->p == '\n')
        c->line++, c->p++;
      else if (*c->p == ' ' || *c->p == '\t' || *c->p == '\r')
        c->p++;
      else if (c->p + 1 < c->end && c->p[0] == '/' && c->p[1] == '/')
        while (c->p < c->end && *c->p != '\n')
          c->p++;
      else if (c->p + 1 < c->end && c->p[0] == '/' && c->p[1] == '*')
        {
          for (c->p += 2; c->p + 1 < c->end
               && !(c->p[0] == '*' && c->p[1] == '/'); c->p++)
            c->line += *c->p == '\n';
          c->p = c->p + 2 <= c->end ? c->p + 2 : c->end;
        }
      else if (*c->p == '"')
        {
          for (c->p++; c->p < c->end && *c->p != '"'; c->p++)
            c->line += *c->p == '\n';
          c->p += c->p < c->end;
        }
      else
        break;
    }
}

lac_geo_var *
lac_geo_vars_find (lac_geo_vars *v, const char *name, size_t len)
{
  for (size_t k = 0; k < v->n; k++)
    if (strlen (v->v[k].name) == len && !memcmp (v->v[k].name, name, len))
      return &v->v[k];
  return NULL;
}

void
lac_geo_vars_set (lac_geo_vars *v, const char *name, size_t len,
                  double value, int known, int scene)
{
  lac_geo_var *x = lac_geo_vars_find (v, name, len);
  if (!x && (len > LAC_GEO_NAME_MAX || v->n == LAC_GEO_MAX_VARS))
    {
      v->full = 1;                 /* not stored: unknown when read */
      return;
    }
  if (!x)
    {
      x = &v->v[v->n++];
      memcpy (x->name, name, len);
      x->name[len] = '\0';
    }
  x->value = value;
  x->known = known;
  x->scene = scene;
}

/* ---- the reader ------------------------------------------------------- */

typedef struct ev
{
  lac_geo_scan *c;
  lac_geo_vars *v;
  int depth, ok;
} ev;

static double ternary (ev *e);

static double
fail (ev *e)
{
  e->ok = 0;
  return 0;
}

/* Is the operator op next (skipping blanks)?  Moves past it if so. */
static int
take (ev *e, const char *op)
{
  size_t n = strlen (op);
  lac_geo_skip (e->c);
  if ((size_t) (e->c->end - e->c->p) < n || memcmp (e->c->p, op, n))
    return 0;
  e->c->p += n;
  return 1;
}

/* Is the operator op next, and not the start of any of the longer ones
 * in `not` (e.g. "<" but not "<=")? */
static int
take_only (ev *e, const char *op, const char *not1, const char *not2)
{
  lac_geo_scan save = *e->c;
  if ((not1 && take (e, not1)) || (not2 && take (e, not2)))
    {
      *e->c = save;
      return 0;
    }
  return take (e, op);
}

/* A decimal number as gmsh reads it: digits, a point, an exponent. */
static double
number (ev *e)
{
  lac_geo_scan *c = e->c;
  const char *s = c->p;
  char buf[64];
  while (c->p < c->end && (isdigit ((unsigned char) *c->p) || *c->p == '.'))
    c->p++;
  if (c->p < c->end && (*c->p == 'e' || *c->p == 'E'))
    {
      const char *q = c->p + 1;
      if (q < c->end && (*q == '+' || *q == '-'))
        q++;
      if (q < c->end && isdigit ((unsigned char) *q))
        for (c->p = q; c->p < c->end && isdigit ((unsigned char) *c->p);)
          c->p++;
    }
  if ((size_t) (c->p - s) >= sizeof buf)
    return fail (e);
  snprintf (buf, sizeof buf, "%.*s", (int) (c->p - s), s);
  return strtod (buf, NULL);
}

/* Name(x) for the functions of one argument lac knows. */
static double
function (ev *e, const char *name, size_t len, double x)
{
  static const struct { const char *name; double (*f) (double); } fn[] = {
    { "Floor", floor }, { "Ceil", ceil }, { "Round", round },
    { "Fabs", fabs }, { "Abs", fabs }, { "Sqrt", sqrt }, { "Exp", exp },
    { "Log", log }, { "Sin", sin }, { "Cos", cos }, { "Tan", tan } };
  for (size_t k = 0; k < sizeof fn / sizeof fn[0]; k++)
    if (strlen (fn[k].name) == len && !memcmp (fn[k].name, name, len))
      return fn[k].f (x);
  return fail (e);
}

/* A name: Pi, a known variable, or a function of one argument. */
static double
name (ev *e)
{
  lac_geo_scan *c = e->c;
  const char *s = c->p;
  size_t len;
  lac_geo_var *x;
  while (c->p < c->end && lac_geo_ident_char (*c->p))
    c->p++;
  len = (size_t) (c->p - s);
  if (take (e, "("))
    {
      double a = ternary (e);
      return take (e, ")") ? function (e, s, len, a) : fail (e);
    }
  if (c->p < c->end && strchr ("[.~#{", *c->p))      /* lists, options */
    return fail (e);
  if (len == 2 && !memcmp (s, "Pi", 2))
    return 3.14159265358979323846;
  x = lac_geo_vars_find (e->v, s, len);
  return x && x->known ? x->value : fail (e);
}

static double
primary (ev *e)
{
  lac_geo_scan *c = e->c;
  double x;
  lac_geo_skip (c);
  if (c->p >= c->end)
    return fail (e);
  if (take (e, "("))
    {
      x = ternary (e);
      return take (e, ")") ? x : fail (e);
    }
  if (isdigit ((unsigned char) *c->p)
      || (*c->p == '.' && c->p + 1 < c->end
          && isdigit ((unsigned char) c->p[1])))
    return number (e);
  if (lac_geo_ident_char (*c->p))
    return name (e);
  return fail (e);
}

static double unary (ev *e);

/* a ^ b (right-associative, above the unary minus: -2^2 = -4). */
static double
power (ev *e)
{
  double a = primary (e);
  return take (e, "^") ? pow (a, unary (e)) : a;
}

static double
unary (ev *e)
{
  if (take_only (e, "!", "!=", NULL))
    return !unary (e);
  if (take (e, "-"))
    return -unary (e);
  if (take (e, "+"))
    return unary (e);
  return power (e);
}

static double
product (ev *e)
{
  double a = unary (e);
  for (;;)
    if (take (e, "*"))
      a *= unary (e);
    else if (take (e, "/"))
      a /= unary (e);
    else if (take (e, "%"))
      a = fmod (a, unary (e));
    else
      return a;
}

static double
sum (ev *e)
{
  double a = product (e);
  for (;;)
    if (take_only (e, "+", "+=", "++"))
      a += product (e);
    else if (take_only (e, "-", "-=", "--"))
      a -= product (e);
    else
      return a;
}

static double
compare (ev *e)
{
  double a = sum (e);
  for (;;)
    if (take (e, "<="))
      a = a <= sum (e);
    else if (take (e, ">="))
      a = a >= sum (e);
    else if (take (e, "<"))
      a = a < sum (e);
    else if (take (e, ">"))
      a = a > sum (e);
    else
      return a;
}

static double
equality (ev *e)
{
  double a = compare (e);
  for (;;)
    if (take (e, "=="))
      a = a == compare (e);
    else if (take (e, "!="))
      a = a != compare (e);
    else
      return a;
}

static double
conjunction (ev *e)
{
  double a = equality (e);
  while (take (e, "&&"))
    {
      double b = equality (e);            /* both read: no side effects */
      a = a != 0 && b != 0;
    }
  return a;
}

static double
disjunction (ev *e)
{
  double a = conjunction (e);
  while (take (e, "||"))
    {
      double b = conjunction (e);
      a = a != 0 || b != 0;
    }
  return a;
}

static double
ternary (ev *e)
{
  double a, b, x;
  if (++e->depth > LAC_GEO_DEPTH)
    return fail (e);
  x = disjunction (e);
  if (e->ok && take (e, "?"))
    {
      a = ternary (e);
      b = take (e, ":") ? ternary (e) : fail (e);
      x = x != 0 ? a : b;
    }
  e->depth--;
  return x;
}

int
lac_geo_expr (lac_geo_scan *c, lac_geo_vars *v, double *x)
{
  ev e = { c, v, 0, 1 };
  double y = ternary (&e);
  if (e.ok)
    *x = y;
  return e.ok;
}
