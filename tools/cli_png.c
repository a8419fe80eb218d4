/* tools/cli_png: parsing of --png, --png-size, --checker (see cli_png.h).
 * --checker takes the next argument as its N only when that argument is
 * a number, so `--checker IN.obj` and `--checker 40` both work. */
#include "cli_png.h"

#include <stdio.h>
#include <string.h>

#include "cli_args.h"

void cli_png_init(cli_png *p, int unit_square)
{
    p->path = NULL;
    p->opt = uv_png_options_default();
    p->opt.unit_square = unit_square;
    p->size_given = 0;
    p->plain = 0;
}

int cli_png_option(const char *cmd, int argc, char **argv, int *i, cli_png *p)
{
    const char *a = argv[*i];
    const char *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (!strcmp(a, "--png")) {
        if (!v) {
            fprintf(stderr, "scaf %s: --png needs a file name (see --help)\n", cmd);
            return -1;
        }
        p->path = v;
        ++*i;
        return 1;
    }
    if (!strcmp(a, "--png-size")) {
        int n;
        if (!v) {
            fprintf(stderr, "scaf %s: --png-size needs a number of pixels (see --help)\n", cmd);
            return -1;
        }
        if (!cli_parse_int(v, &n) || n < UV_PNG_MIN_SIZE || n > UV_PNG_MAX_SIZE) {
            fprintf(stderr,
                    "scaf %s: --png-size '%s': give a whole number of pixels from %d to %d\n", cmd,
                    v, UV_PNG_MIN_SIZE, UV_PNG_MAX_SIZE);
            return -1;
        }
        p->opt.size = n;
        p->size_given = 1;
        ++*i;
        return 1;
    }
    if (!strcmp(a, "--png-plain")) {
        p->plain = 1;
        return 1;
    }
    if (!strcmp(a, "--checker")) {
        double n;
        p->opt.checker = CLI_PNG_DEFAULT_CHECKER;
        if (v && cli_parse_double(v, &n)) {
            if (!(n >= 1.0 && n <= 10000.0)) {
                fprintf(stderr,
                        "scaf %s: --checker %s: give from 1 to 10000 squares across the diagonal\n",
                        cmd, v);
                return -1;
            }
            p->opt.checker = n;
            ++*i;
        }
        return 1;
    }
    return 0;
}

int cli_png_size_take(const char *cmd, const cli_option *o, const char *value)
{
    cli_png *p = o->dest;
    cli_option e = *o;
    e.kind = CLI_OPT_INT;
    e.dest = &p->opt.size;
    int rc = cli_option_apply(cmd, &e, value);
    if (rc == 0) p->size_given = 1;
    return rc;
}

int cli_png_checker_take(const char *cmd, const cli_option *o, const char *value)
{
    cli_png *p = o->dest;
    p->opt.checker = CLI_PNG_DEFAULT_CHECKER;
    if (!value) return 0;
    cli_option e = *o;
    e.kind = CLI_OPT_DOUBLE;
    e.dest = &p->opt.checker;
    return cli_option_apply(cmd, &e, value);
}

int cli_png_finish(const char *cmd, const cli_png *p)
{
    if (!p->path && (p->opt.checker > 0.0 || p->size_given || p->plain)) {
        fprintf(stderr, "scaf %s: %s draws into the PNG picture: give --png FILE as well\n", cmd,
                p->opt.checker > 0.0 ? "--checker"
                    : p->size_given  ? "--png-size"
                                     : "--png-plain");
        return -1;
    }
    return 0;
}
