/* lac_status.c -- status codes and the stored error message. */
#include "base/lac_status.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_errno.h>

#include "base/lac_text.h"

static _Thread_local char last_message[1024];
static _Thread_local char last_origin[64];
static _Thread_local int last_placed;
static _Thread_local gsl_error_handler_t *saved_gsl_handler;

/* Room to format a message before it is escaped and fitted: long enough
 * for two paths of PATH_MAX and the words around them. */
#define MSG_ROOM 12288

int
lac_status_errno (int e)
{
  return e == ENOMEM ? LAC_ENOMEM : LAC_EIO;
}

const char *
lac_strerror (int status)
{
  switch (status)
    {
    case LAC_SUCCESS: return "success";
    case LAC_CONTINUE: return "iteration not finished";
    case LAC_EINVAL: return "invalid input";
    case LAC_EBADLEN: return "sizes do not conform";
    case LAC_ENOMEM: return "out of memory";
    case LAC_EIO: return "input/output error";
    case LAC_EDEP: return "a library dependency failed";
    case LAC_ESING: return "singular system";
    case LAC_EMAXITER: return "no convergence";
    case LAC_EADMISS: return "not admissible";
    case LAC_ESANITY: return "internal error (a bug in lac)";
    default: return "unknown status";
    }
}

const char *
lac_error_message (void)
{
  return last_message;
}

const char *
lac_error_origin (void)
{
  return last_origin;
}

int
lac_error_placed (void)
{
  return last_placed;
}

void
lac_error_clear (void)
{
  last_message[0] = last_origin[0] = '\0';
  last_placed = 0;
}

/* A C identifier: the name of a function, not a place. */
static int
identifier (const char *s)
{
  if (!(*s == '_' || isalpha ((unsigned char) *s)))
    return 0;
  while (*s == '_' || isalnum ((unsigned char) *s))
    s++;
  return *s == '\0';
}

/* Store "place: message" (place NULL: the message alone).  The message
 * is formatted into a local buffer first, so an argument may be the
 * previous message (lac_error_message ()) to wrap it; what the caller
 * quotes from a file may be binary, so bytes that are not text are
 * stored as \xNN (lac_text.h); the result is fitted into the buffer by
 * its middle (lac_text_fit). */
static int
store (int status, const char *place, const char *origin, const char *fmt,
       va_list ap)
{
  char buf[MSG_ROOM], esc[MSG_ROOM];
  size_t n = 0;
  if (place && *place)
    n = (size_t) snprintf (buf, sizeof buf, "%.4096s: ", place);
  vsnprintf (buf + n, sizeof buf - n, fmt, ap);
  if (status == LAC_ENOMEM && !strstr (buf + n, "out of memory"))
    {
      memmove (buf + n + 15, buf + n, strnlen (buf + n, sizeof buf - n - 16)
               + 1);
      memcpy (buf + n, "out of memory: ", 15);   /* every such message */
      buf[sizeof buf - 1] = '\0';
    }
  lac_text_escape_line (esc, sizeof esc, buf);
  lac_text_fit (last_message, sizeof last_message, esc);
  snprintf (last_origin, sizeof last_origin, "%s", origin ? origin : "");
  last_placed = place && *place;
  return status;
}

int
lac_error_set (int status, const char *where, const char *fmt, ...)
{
  int func = where && identifier (where);
  va_list ap;
  va_start (ap, fmt);
  store (status, func ? NULL : where, func ? where : NULL, fmt, ap);
  va_end (ap);
  return status;
}

int
lac_error_place (int status, const char *place, const char *fmt, ...)
{
  va_list ap;
  va_start (ap, fmt);
  store (status, place, NULL, fmt, ap);
  va_end (ap);
  return status;
}

int
lac_error_restore (int status, const char *message)
{
  snprintf (last_message, sizeof last_message, "%s", message);
  last_origin[0] = '\0';
  last_placed = 0;
  return status;
}

void
lac_init (void)
{
  saved_gsl_handler = gsl_set_error_handler_off ();
}

void
lac_finalize (void)
{
  gsl_set_error_handler (saved_gsl_handler);
}
