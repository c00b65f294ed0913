/* lac_status.h -- status codes and error messages
 *
 * Nothing in src/ prints, exits or aborts.  A function that fails stores a
 * one-line message (retrieved with lac_error_message) and returns one of the
 * codes below; only main() decides to stop.  The message buffer is
 * thread-local, like errno: it is the library's only mutable state outside
 * the objects the caller owns.
 *
 * A message is for the user: it names the file, line, option or entity
 * (node, cell, group) it is about and says what is wrong in words; it
 * never names a function of lac, which the user cannot act on.  The
 * function that stored it (LAC_ERRMSG passes __func__) is kept apart, for
 * a developer: lac_error_origin.  Whether the message names its place is
 * kept too (lac_error_placed), so that the code that knows the place --
 * the scene line, the mesh file, the result directory -- adds it to a
 * message from deep inside that does not.
 *
 * A message stored with LAC_ENOMEM always says "out of memory".
 * Messages hold one line of text only: control bytes and bytes that are
 * not UTF-8 are stored as \xNN (base/lac_text.h); a line feed quoted
 * from a file (a group name, gmsh's words) is stored as \x0A.  A message
 * longer than the buffer loses its middle, not its end: the reason, last,
 * survives a long path quoted before it.
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
/* The function that stored the last message ("" if unknown): for a
 * developer, never part of the message. */
const char *lac_error_origin (void);
/* 1 if the last message names its place (stored by lac_error_place, or
 * by lac_error_set with a place). */
int lac_error_placed (void);

/* Store a message and return status.  where: a place the user knows (a
 * file, "FILE:LINE", an option such as "--set"), written in front of the
 * message as "where: message"; NULL for none.  A C identifier is not a
 * place but the name of a function (LAC_ERRMSG passes __func__): it is
 * kept as the origin and not shown.  Use through the macros, or
 * lac_error_place for a place that must be shown whatever it looks like
 * (a file name without a dot or a slash). */
int lac_error_set (int status, const char *where, const char *fmt, ...)
  __attribute__ ((format (printf, 3, 4)));
/* Store "place: message" (place shown as it is) and return status. */
int lac_error_place (int status, const char *place, const char *fmt, ...)
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
