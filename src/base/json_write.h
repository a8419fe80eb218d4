/* base/json_write: the two JSON leaf writers every report needs.
 * Reports are written field by field with fprintf; these cover the cases
 * fprintf gets wrong: escaping strings and non-finite numbers. */
#ifndef SCAF_BASE_JSON_WRITE_H
#define SCAF_BASE_JSON_WRITE_H

#include <stdio.h>

/* A quoted, escaped JSON string; NULL writes `null`. */
void json_write_string(FILE *out, const char *s);

/* A number that reads back to the same double (%.17g); NaN and infinities
 * (which JSON cannot hold) write `null`. */
void json_write_number(FILE *out, double x);

#endif
