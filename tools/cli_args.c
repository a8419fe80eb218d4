/* tools/cli_args: see cli_args.h. */
#include "cli_args.h"

#include <math.h>
#include <stdlib.h>

int cli_parse_int(const char *s, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (!*s || *end || v < 0 || v > 100000000) return 0;
    *out = (int)v;
    return 1;
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (!*s || *end || !isfinite(v)) return 0;
    *out = v;
    return 1;
}
