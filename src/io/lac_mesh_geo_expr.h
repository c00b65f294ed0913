/* lac_mesh_geo_expr.h -- the value of a .geo expression, where lac can
 * tell it                                                        [LAC §2]
 *
 * The pre-check of a .geo script (lac_mesh_geo_check.h) must know the
 * counts the script computes (Transfinite Curve {...} = 2 * n + 1):
 * gmsh 4.8 turns a count beyond 32-bit integers into 2 without a word.
 * This module reads the script as gmsh's parser does, without running it:
 *
 *   lac_geo_skip      blanks, line ends (counted), comments and strings;
 *   lac_geo_expr      the arithmetic of gmsh's expressions on numbers and
 *                     known variables: + - * / % ^, comparisons, && || !,
 *                     ?:, parentheses, Pi and the functions Floor, Ceil,
 *                     Round, Fabs, Abs, Sqrt, Exp, Log, Sin, Cos, Tan.  A
 *                     list, a string, an unknown name or function makes
 *                     the value unknown (the caller then leaves it to
 *                     gmsh): never a wrong value, sometimes none;
 *   lac_geo_vars      the variables: the scene's numbers (level, [mesh]
 *                     numbers), then each assignment NAME = EXPR of the
 *                     script, in order.  One outside any block is known
 *                     when its value is; one inside If, For, Macro or
 *                     DefineConstant makes its variable unknown, unless
 *                     the scene gives that variable (the book's scripts
 *                     set defaults with If (!Exists(level)) ... EndIf,
 *                     which does not run then).
 */
#ifndef LAC_MESH_GEO_EXPR_H
#define LAC_MESH_GEO_EXPR_H

#include <stddef.h>

/* A position in the text of a script. */
typedef struct lac_geo_scan
{
  const char *p, *end;     /* borrowed: the next character, the end      */
  long line;               /* the line of p (1-based)                    */
} lac_geo_scan;

#define LAC_GEO_MAX_VARS 256
#define LAC_GEO_NAME_MAX 63

typedef struct lac_geo_var
{
  char name[LAC_GEO_NAME_MAX + 1];
  double value;
  int known;               /* 0: assigned in a way lac cannot follow      */
  int scene;               /* given by the scene (level, [mesh] numbers)  */
} lac_geo_var;

/* The variables of a script; zero-initialised: none. */
typedef struct lac_geo_vars
{
  size_t n;
  int full;                /* more names than LAC_GEO_MAX_VARS: every
                              name not stored is unknown                 */
  lac_geo_var v[LAC_GEO_MAX_VARS];
} lac_geo_vars;

/* 1 if c may be part of an identifier (letters, digits, _). */
int lac_geo_ident_char (char c);

/* Skip blanks, line ends, comments and strings. */
void lac_geo_skip (lac_geo_scan *c);

/* The variable of that name (len characters), NULL if none. */
lac_geo_var *lac_geo_vars_find (lac_geo_vars *v, const char *name,
                                size_t len);
/* Set (or add) a variable; known = 0: its value is unknown. */
void lac_geo_vars_set (lac_geo_vars *v, const char *name, size_t len,
                       double value, int known, int scene);

/* Evaluate the expression at c->p (c moves past what was read): 1 with
 * *x if its value is known, 0 if not (then c is anywhere in it). */
int lac_geo_expr (lac_geo_scan *c, lac_geo_vars *v, double *x);

#endif /* LAC_MESH_GEO_EXPR_H */
