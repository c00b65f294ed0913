/* lac_text.h -- text that can be read and shown: UTF-8, no control bytes
 *
 * A scene file is text, and so is every message lac prints.  Two helpers:
 *
 *   lac_text_check   the first byte of a text that is not what a text
 *                    file holds: NUL, a control character other than tab,
 *                    line feed and a carriage return before a line feed,
 *                    a carriage return alone (old Mac line ends), or bytes
 *                    that are not UTF-8 (RFC 3629: no overlong forms, no
 *                    surrogates, nothing above U+10FFFF);
 *   lac_text_escape  a copy in which every such byte is written \xNN, so
 *                    that a message never sends raw binary to a terminal;
 *   lac_text_fit     a copy cut to a buffer by shortening its longest
 *                    words (paths) in their middle, so that a message
 *                    keeps its place and its reason when long paths
 *                    quoted in it do not fit.
 */
#ifndef LAC_TEXT_H
#define LAC_TEXT_H

/* The text of a macro's value, e.g. "50" for LAC_NEWTON_MAXIT (help
 * texts quote the defaults defined once in code). */
#define LAC_STR_(x) #x
#define LAC_XSTR(x) LAC_STR_ (x)

#include <stddef.h>

/* The offset of the first bad byte of text[0 .. len-1], or len if none;
 * *what (may be NULL) says what it is, e.g. "a NUL byte". */
size_t lac_text_check (const char *text, size_t len, const char **what);

/* The line (1-based) of offset off in text: 1 + the line feeds before. */
long lac_text_line (const char *text, size_t off);

/* Copy the string src to dst (size > 0 bytes, always terminated, cut if
 * needed), with bad bytes as \xNN; tab and line feed are kept. */
void lac_text_escape (char *dst, size_t size, const char *src);
/* The same with the line feed too as \x0A, and every carriage return as
 * \x0D (the one before a line feed would otherwise stand alone): one line
 * (a stored message). */
void lac_text_escape_line (char *dst, size_t size, const char *src);

/* Copy the string src to dst (size > 0 bytes, always terminated); when
 * src does not fit, its words (runs without a blank) longer than some
 * length L are cut to their first third, "..." and their end, L as large
 * as fits; if that is not enough (L below 48), the middle of the whole
 * is replaced by " ... ".  Cuts fall between UTF-8 characters. */
void lac_text_fit (char *dst, size_t size, const char *src);

#endif /* LAC_TEXT_H */
