/* lac_cli_result.h -- the files of a result directory that `lac render`
 * reads besides the VTU: summary.txt (the title) and contact.csv (one row
 * per macro-element).  Command-line glue, not library API.
 */
#ifndef LAC_CLI_RESULT_H
#define LAC_CLI_RESULT_H

#include <stddef.h>

/* The status of a macro-element of a frictional run (contact.csv's
 * column status); LAC_CLI_NO_STATUS without friction. */
enum { LAC_CLI_NO_STATUS, LAC_CLI_INACTIVE, LAC_CLI_STICK, LAC_CLI_SLIP };

/* The rows of contact.csv of the admissible macro-elements. */
typedef struct macro_rows
{
  size_t n;                        /* admissible macro-elements          */
  double *x, *meas, *lam, *lex, *gap;  /* x: 3 per row                    */
  int friction;                    /* 1: the file has lambda_t (2D) or
                                      lambda_t1, lambda_t2 (3D), status */
  double *lt;                      /* lambda_t in 2D, |(lambda_t1,
                                      lambda_t2)| in 3D; NaN without     */
  signed char *status;             /* LAC_CLI_STICK, ...                 */
  double *sc;                      /* column s (2D): the abscissa of the
                                      centroid along the slave curve, over
                                      every macro-element; NaN without   */
} macro_rows;

/* The scene's title from DIR/summary.txt, else DIR's last name. */
void lac_cli_result_title (const char *dir, char *buf, size_t len);

/* Coulomb's mu of the run: the "mu = " of the effects line of
 * DIR/summary.txt ("Coulomb friction (LAC; mu = 0.3)"); 1 with *mu, 0 if
 * there is none (no summary, a run without friction). */
int lac_cli_result_mu (const char *dir, double *mu);

/* The admissible rows of DIR/contact.csv into *r (an empty field is no
 * value: 0 for a coordinate, NaN for lambda_exact, also when the file has
 * no such column; lambda_t NaN and the status LAC_CLI_NO_STATUS without
 * friction); LAC_EIO (no file, missing column),
 * LAC_EINVAL (no admissible row), LAC_ENOMEM.  Free with
 * lac_cli_result_contact_free, also after an error. */
int lac_cli_result_contact (const char *dir, macro_rows *r);
void lac_cli_result_contact_free (macro_rows *r);

#endif /* LAC_CLI_RESULT_H */
