/* tools/cli_args: strict parsing of numeric option values.
 * The whole string must be a number: "12x", "" and "nan" are refused, so
 * a typo is a usage error rather than a silent default. */
#ifndef SCAF_TOOLS_CLI_ARGS_H
#define SCAF_TOOLS_CLI_ARGS_H

/* A whole decimal integer in [0, 1e8]: 1 and *out set, or 0. */
int cli_parse_int(const char *s, int *out);

/* A whole finite floating-point number: 1 and *out set, or 0. */
int cli_parse_double(const char *s, double *out);

#endif
