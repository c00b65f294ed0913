/* lac_cli_render_compare.h -- `lac render --contact --compare FILE`: a
 * curve to draw with the contact curves (a closed form, another code's
 * result), read and checked before anything is written.  Command-line
 * glue, not library API.
 *
 * FILE is text: lines "s value" (two numbers as C writes them, separated
 * by spaces or tabs), blank lines, and comment lines starting with '#';
 * the text of the first comment line (after "# ") is the curve's title,
 * the file's name when there is none.
 */
#ifndef LAC_CLI_RENDER_COMPARE_H
#define LAC_CLI_RENDER_COMPARE_H

#include <stddef.h>

typedef struct render_compare
{
  size_t n;                 /* points                                    */
  double *s, *v;            /* owned: abscissa and value of each point   */
  char title[256];          /* one line, printable                       */
} render_compare;

/* Read FILE into *c; LAC_EIO (cannot read it), LAC_EINVAL ("FILE:LINE:
 * ..." for a line that is not two finite numbers, or a file without
 * points), LAC_ENOMEM.  Free with lac_cli_render_compare_free, also after
 * an error. */
int lac_cli_render_compare_read (const char *path, render_compare *c);

/* The points as "s value" lines under "# TITLE", to path. */
int lac_cli_render_compare_write (const char *path, const render_compare *c);

void lac_cli_render_compare_free (render_compare *c);

#endif /* LAC_CLI_RENDER_COMPARE_H */
