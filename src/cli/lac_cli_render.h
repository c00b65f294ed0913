/* lac_cli_render.h -- the `lac render` command (command-line glue)
 *
 * lac_cli_render reads a result directory written by `lac run`
 * (solution.vtu, and summary.txt, contact.csv when present) and draws a
 * PNG picture with lac_render, or the contact curves with gnuplot.  Unlike
 * the library, it prints (errors as one line "lac: ..." on stderr, the
 * paths written on stdout) and runs gnuplot; it never exits.
 *
 * main() calls it for `lac render ...` with argv[0] = "render" (that is,
 * main's argc - 1 and argv + 1) and returns what it returns: 0 success,
 * 1 failure, 2 bad command line.  lac_cli_render_help is the text for
 * `lac --help` (and `lac render --help`).
 */
#ifndef LAC_CLI_RENDER_H
#define LAC_CLI_RENDER_H

extern const char lac_cli_render_help[];

int lac_cli_render (int argc, char **argv);

#endif /* LAC_CLI_RENDER_H */
