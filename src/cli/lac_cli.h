/* lac_cli.h -- helpers shared by the command-line glue (main.c and the
 * lac_cli_*.c subcommands): the only code besides them that prints.
 * Not part of the library interface.
 */
#ifndef LAC_CLI_H
#define LAC_CLI_H

/* Exit statuses of lac and its subcommands besides 0, success. */
enum { LAC_CLI_FAILURE = 1, LAC_CLI_USAGE = 2 };

/* "lac: MESSAGE" on stderr, as one line (newlines become blanks). */
void lac_cli_print_error (const char *msg);

/* A bad command line: "lac: CMD: WHAT ARG (try lac CMD --help)" on
 * stderr (cmd NULL: lac itself; arg may be NULL); returns LAC_CLI_USAGE. */
int lac_cli_usage_error (const char *cmd, const char *what, const char *arg);

/* The value of option `name` at argv[*k]: "--name VALUE" (then *k moves to
 * VALUE) or "--name=VALUE"; NULL if argv[*k] is not that option, or if
 * its value is missing (then *missing = 1). */
const char *lac_cli_option_value (int argc, char **argv, int *k,
                                  const char *name, int *missing);

/* A size in bytes: a number with an optional suffix k, M, G or T (powers
 * of 1000, as the messages print GB); -1 if it is not one, or not > 0. */
double lac_cli_bytes (const char *s);

#endif /* LAC_CLI_H */
