/* lac_cli_result.h -- the files of a result directory that `lac render`
 * reads besides the VTU: summary.txt (the title) and contact.csv (one row
 * per macro-element).  Command-line glue, not library API.
 */
#ifndef LAC_CLI_RESULT_H
#define LAC_CLI_RESULT_H

#include <stddef.h>

/* The rows of contact.csv of the admissible macro-elements. */
typedef struct macro_rows
{
  size_t n;                        /* admissible macro-elements          */
  double *x, *meas, *lam, *lex, *gap;  /* x: 3 per row                    */
} macro_rows;

/* The scene's title from DIR/summary.txt, else DIR's last name. */
void lac_cli_result_title (const char *dir, char *buf, size_t len);

/* The admissible rows of DIR/contact.csv into *r (an empty field is no
 * value: 0 for a coordinate, NaN for lambda_exact, also when the file has
 * no such column); LAC_EIO (no file, missing column),
 * LAC_EINVAL (no admissible row), LAC_ENOMEM.  Free with
 * lac_cli_result_contact_free, also after an error. */
int lac_cli_result_contact (const char *dir, macro_rows *r);
void lac_cli_result_contact_free (macro_rows *r);

#endif /* LAC_CLI_RESULT_H */
