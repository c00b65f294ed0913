/* lac_cli.h -- helpers shared by the command-line glue (main.c and the
 * lac_cli_*.c subcommands): the only code besides them that prints.
 * Not part of the library interface.
 */
#ifndef LAC_CLI_H
#define LAC_CLI_H

#include <stddef.h>
#include "base/lac_number.h"

/* Exit statuses of lac and its subcommands besides 0, success. */
enum { LAC_CLI_FAILURE = 1, LAC_CLI_USAGE = 2 };

/* "lac: MESSAGE" on stderr, as one line (newlines become blanks). */
void lac_cli_print_error (const char *msg);

/* Flush stdout at the end of a subcommand: 0, or LAC_CLI_FAILURE after
 * "lac: cannot write to stdout: REASON" (a pipe whose reader is gone:
 * SIGPIPE is ignored by main, so the write fails with EPIPE; a full
 * disk). */
int lac_cli_flush_stdout (void);

/* The failure of a library call: "lac: PLACE: MESSAGE" when the stored
 * message names no place of its own (base/lac_status.h), else "lac:
 * MESSAGE"; what status means when the library left no message.  place
 * may be NULL. */
void lac_cli_print_failure (const char *place, int status);

/* A bad command line: "lac: CMD: WHAT ARG (try lac CMD --help)" on
 * stderr (cmd NULL: lac itself; arg may be NULL); returns LAC_CLI_USAGE. */
int lac_cli_usage_error (const char *cmd, const char *what, const char *arg);

/* The value of option `name` at argv[*k]: "--name VALUE" (then *k moves to
 * VALUE) or "--name=VALUE"; NULL if argv[*k] is not that option, or if
 * its value is missing (then *missing = 1). */
const char *lac_cli_option_value (int argc, char **argv, int *k,
                                  const char *name, int *missing);

/* A size in bytes: a number with an optional suffix k, M, G or T (powers
 * of 1000, as the messages print GB), at least min and at most max bytes.
 * 1 with *bytes, or 0 with the reason in why (base/lac_number.h: which
 * limit it broke). */
int lac_cli_bytes (const char *s, double min, double max, double *bytes,
                   char *why, size_t size);

/* The value of --max-memory (lac run, lac infsup): a size of
 * lac_cli_bytes from LAC_MESH_RUN_BYTES_MIN to LAC_MESH_MEMORY_MAX
 * (io/lac_mesh_opts.h).  1 with *bytes, or 0 after the usage error of
 * command cmd (NULL: lac run). */
int lac_cli_max_memory (const char *cmd, const char *s, double *bytes);

/* A number option (base/lac_number.h, within spec).  1 with *x, or 0
 * after the usage line "lac: CMD: OPTION 'VALUE': REASON (try ...)". */
int lac_cli_number (const char *cmd, const char *option, const char *s,
                    const lac_number_spec *spec, double *x);

#endif /* LAC_CLI_H */
