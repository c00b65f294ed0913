/* lac_cli.h -- helpers shared by the command-line glue (main.c and the
 * lac_cli_*.c subcommands): the only code besides them that prints.
 * Not part of the library interface.
 */
#ifndef LAC_CLI_H
#define LAC_CLI_H

/* "lac: MESSAGE" on stderr, as one line (newlines become blanks). */
void lac_cli_print_error (const char *msg);

/* The value of option `name` at argv[*k]: "--name VALUE" (then *k moves to
 * VALUE) or "--name=VALUE"; NULL if argv[*k] is not that option, or if
 * its value is missing (then *missing = 1). */
const char *lac_cli_option_value (int argc, char **argv, int *k,
                                  const char *name, int *missing);

#endif /* LAC_CLI_H */
