/* lac_cli_render_internal.h -- internal: shared by lac_cli_render.c (the
 * command, its options, the pictures) and lac_cli_render_curves.c (the 2D
 * contact curves through gnuplot).  Command-line glue, not library API.
 */
#ifndef LAC_CLI_RENDER_INTERNAL_H
#define LAC_CLI_RENDER_INTERNAL_H

#include <stddef.h>
#include "render/lac_render.h"

typedef struct render_args
{
  const char *dir, *field, *out, *title, *units;
  const char *vtu;          /* --vtu FILE, NULL: solution.vtu               */
  int fixed_box;            /* --box given                                  */
  double box[6];            /* --box: x0 x1 y0 y1 z0 z1                      */
  double scale, az, el, vmin, vmax;
  int auto_scale, edges, contact, list, width, height, fixed_range;
} render_args;

/* The rows of contact.csv of the admissible macro-elements. */
typedef struct macro_rows
{
  size_t n;                        /* admissible macro-elements          */
  double *x, *meas, *lam, *lex, *gap;  /* x: 3 per row                    */
} macro_rows;

/* The scene's title from DIR/summary.txt, else DIR's last name. */
void lac_cli_render_scene_title (const char *dir, char *buf, size_t len);

/* out = DIR/NAME.png: lambda and the mean gap along Gamma_C (2D) drawn by
 * gnuplot from DIR/NAME.dat and DIR/NAME.gp (kept next to the picture). */
int lac_cli_render_curves (const render_args *a, const lac_render_result *res,
                           const macro_rows *rows, const char *out);

#endif /* LAC_CLI_RENDER_INTERNAL_H */
