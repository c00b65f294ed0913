/* lac_cli_render_curves.h -- `lac render --contact` in 2D: lambda and the
 * mean gap along Gamma_C, and with friction the tangential traction,
 * drawn by gnuplot (see lac_cli_render_curves.c).  Command-line glue, not
 * library API.
 */
#ifndef LAC_CLI_RENDER_CURVES_H
#define LAC_CLI_RENDER_CURVES_H

#include "cli/lac_cli_result.h"
#include "render/lac_render.h"

/* What the curves add to the picture's options. */
typedef struct lac_cli_curves_opts
{
  const char *compare;      /* --compare FILE, or NULL                  */
  int srange;               /* 1: --srange S0:S1 given                  */
  double s0, s1;            /* its bounds, s0 < s1                      */
  double mu;                /* Coulomb's mu of the run, 0: not known    */
} lac_cli_curves_opts;

/* out = DIR/NAME.png: lambda and the mean gap along Gamma_C (2D) of the
 * rows, and the tangential traction when they have friction, against the
 * curvilinear abscissa, drawn by gnuplot from DIR/NAME.dat and DIR/NAME.gp
 * (kept next to the picture; DIR/NAME-compare.dat too with a --compare
 * curve); res gives the model and the mesh size, o the size, the title
 * and the units. */
int lac_cli_render_curves (const macro_rows *rows,
                           const lac_render_result *res,
                           const lac_render_opts *o,
                           const lac_cli_curves_opts *c, const char *out);

#endif /* LAC_CLI_RENDER_CURVES_H */
