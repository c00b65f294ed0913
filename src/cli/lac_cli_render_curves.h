/* lac_cli_render_curves.h -- `lac render --contact` in 2D: lambda and the
 * mean gap along Gamma_C, drawn by gnuplot (see lac_cli_render_curves.c).
 * Command-line glue, not library API.
 */
#ifndef LAC_CLI_RENDER_CURVES_H
#define LAC_CLI_RENDER_CURVES_H

#include "cli/lac_cli_result.h"
#include "render/lac_render.h"

/* out = DIR/NAME.png: lambda and the mean gap along Gamma_C (2D) of the
 * rows, against the curvilinear abscissa, drawn by gnuplot from
 * DIR/NAME.dat and DIR/NAME.gp (kept next to the picture); res gives the
 * model and the mesh size, o the size, the title and the units. */
int lac_cli_render_curves (const macro_rows *rows,
                           const lac_render_result *res,
                           const lac_render_opts *o, const char *out);

#endif /* LAC_CLI_RENDER_CURVES_H */
