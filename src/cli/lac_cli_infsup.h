/* lac_cli_infsup.h -- the `lac infsup` subcommand               [LAC (10)]
 *
 *   lac infsup SCENE [--set KEY=VALUE]... [--dense|--sparse]
 *                    [--norm h1|energy] [--vector] [--quiet]
 *
 * Runs the stages mesh .. assemble of a contact scene (lac_run.h), then
 * estimates the inf-sup constant beta_h of [LAC (10)] (lac_infsup.h) and
 * prints "name = value" lines on stdout: beta_h, lambda_min, multipliers,
 * ndof, h, the norm and path used, the least stable multiplier.
 *
 * Part of the command line, like main.c: it prints (stdout: results,
 * stderr: progress and "lac: message" errors) and returns an exit status
 * (0 success, 1 the estimate failed, 2 bad command line); it never exits.
 * main.c calls it as  lac_cli_infsup (argc - 1, argv + 1)  when argv[1] is
 * "infsup", so that argv[0] is "infsup".
 */
#ifndef LAC_CLI_INFSUP_H
#define LAC_CLI_INFSUP_H

/* The help text of `lac infsup --help` (also printed by it). */
extern const char lac_cli_infsup_help[];

/* The subcommand; argv[0] = "infsup", argv[1..] its arguments.  Call
 * between lac_init () and lac_finalize () (it does not call them). */
int lac_cli_infsup (int argc, char **argv);

#endif /* LAC_CLI_INFSUP_H */
