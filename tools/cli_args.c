/* tools/cli_args: see cli_args.h. */
#include "cli_args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "exit_codes.h"

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

int cli_take_input(const char *cmd, const char *a, const char **in)
{
    if (a[0] == '-' && a[1]) {
        fprintf(stderr, "scaf %s: unknown option '%s' (see --help)\n", cmd, a);
        return EXIT_USAGE;
    }
    if (*in) {
        fprintf(stderr, "scaf %s: one input only ('%s' and '%s' given)\n", cmd, *in, a);
        return EXIT_USAGE;
    }
    *in = a;
    return EXIT_OK;
}
