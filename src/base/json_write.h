/* base/json_write: the JSON pieces every report needs.
 * Reports are written field by field with fprintf; these cover the cases
 * fprintf gets wrong (escaping strings, non-finite numbers) and the head
 * every report starts with: its schema version and its command. */
#ifndef SCAF_BASE_JSON_WRITE_H
#define SCAF_BASE_JSON_WRITE_H

#include <stdio.h>

/* A quoted, escaped JSON string; NULL writes `null`. */
void json_write_string(FILE *out, const char *s);

/* A number that reads back to the same double (%.17g); NaN and infinities
 * (which JSON cannot hold) write `null`. */
void json_write_number(FILE *out, double x);

/* The version of the report format (docs/reports.md): N grows when a key
 * is renamed or removed or changes meaning; new keys keep N. */
#define SCAF_REPORT_SCHEMA "scaf-report/1"

/* `{` and the first two keys of a report: "schema" and "command" (e.g.
 * "param", "check"), each on its own line; the caller goes on with
 * `,\n  "key": ...`. */
void json_write_report_head(FILE *out, const char *command);

#endif
