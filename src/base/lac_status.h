/* lac_status.h -- status codes and error messages
 *
 * Nothing in src/ prints, exits or aborts.  A function that fails stores a
 * one-line message (retrieved with lac_error_message) and returns one of the
 * codes below; only main() decides to stop.  The message buffer is
 * thread-local, like errno: it is the library's only mutable state outside
 * the objects the caller owns.
 *
 * A message stored with LAC_ENOMEM always says "out of memory".
 * Messages hold one line of text only: control bytes and bytes that are
 * not UTF-8 are stored as \xNN (base/lac_text.h); a line feed quoted
 * from a file (a group name, gmsh's words) is stored as \x01.
 *
 * lac_init switches GSL's aborting error handler off (GSL would otherwise
 * abort on a singular matrix); lac_finalize restores it.
 */
#ifndef LAC_STATUS_H
#define LAC_STATUS_H

enum
{
  LAC_SUCCESS = 0,
  LAC_CONTINUE = -2,  /* iteration not finished: not an error               */
  LAC_EINVAL = 1,     /* invalid argument or input value                     */
  LAC_EBADLEN = 2,    /* sizes do not conform                                */
  LAC_ENOMEM = 3,     /* allocation failed                                   */
  LAC_EIO = 4,        /* file could not be read or written                   */
  LAC_EDEP = 5,       /* a dependency (GSL, SuiteSparse, gmsh, OSMesa) failed */
  LAC_ESING = 6,      /* singular or not positive definite                   */
  LAC_EMAXITER = 7,   /* iteration did not converge                          */
  LAC_EADMISS = 8,    /* macro-mesh or contact data not admissible           */
  LAC_ESANITY = 9     /* internal invariant broken: a bug in lac             */
};

const char *lac_strerror (int status);
/* The status of a failed system call from its errno: LAC_ENOMEM for
 * ENOMEM (fopen, opendir need memory), LAC_EIO otherwise. */
int lac_status_errno (int e);
const char *lac_error_message (void);   /* last message, "" if none */
void lac_error_clear (void);

/* Store "func: message" and return status.  Use through the macros. */
int lac_error_set (int status, const char *func, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));

/* Store a message as it is, one taken with lac_error_message in another
 * thread (the buffer is thread-local), and return status. */
int lac_error_restore (int status, const char *message);

#define LAC_ERRMSG(status, ...) lac_error_set ((status), __func__, __VA_ARGS__)
#define LAC_ERROR(status, ...) return LAC_ERRMSG ((status), __VA_ARGS__)
#define LAC_ERROR_NULL(status, ...) \
  do { LAC_ERRMSG ((status), __VA_ARGS__); return NULL; } while (0)

void lac_init (void);      /* GSL handler off, SuiteSparse quiet */
void lac_finalize (void);  /* restore the GSL handler             */

#endif /* LAC_STATUS_H */
