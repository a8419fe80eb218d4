/* tools/cli_options: see cli_options.h.
 *
 * getopt_long runs in "+" mode (stop at the first positional) with its own
 * messages off (":" and opterr = 0); positionals are taken here one by one
 * and parsing resumes after each, so options may follow the input as
 * before. The token getopt_long just read is argv[prev] (prev = optind
 * before the call), which tells a long option from a grouped short one,
 * lets a long name be required whole (getopt_long accepts prefixes) and
 * tells the "--" that ends the options from a "--" given as a value. */
#include "cli_options.h"

#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "exit_codes.h"

enum { LONG_VAL_BASE = 256, TEXT_WIDTH = 80, DEFAULT_COLUMN = 25 };

static int takes_value(const cli_option *o)
{
    switch (o->kind) {
    case CLI_OPT_INT:
    case CLI_OPT_DOUBLE:
    case CLI_OPT_STRING:
    case CLI_OPT_ENUM: return 1;
    case CLI_OPT_CALLBACK: return o->metavar != NULL;
    default: return 0;
    }
}

static int count_options(const cli_option *t)
{
    int n = 0;
    while (t[n].kind != CLI_OPT_END) n++;
    return n;
}

int cli_edit_distance(const char *a, int na, const char *b, int nb)
{
    int row[64];
    if (na > 63) na = 63;
    if (nb > 63) nb = 63;
    for (int j = 0; j <= nb; j++) row[j] = j;
    for (int i = 1; i <= na; i++) {
        int diag = row[0];
        row[0] = i;
        for (int j = 1; j <= nb; j++) {
            int up = row[j];
            int best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[nb];
}

const char *cli_options_suggest(const cli_option *options, const char *text)
{
    static char best_name[80];
    while (*text == '-') text++;
    int len = (int)strcspn(text, "=");
    int limit = len <= 4 ? 1 : len <= 8 ? 2 : 3, best = limit + 1;
    for (const cli_option *o = options; o->kind != CLI_OPT_END; o++) {
        const char *names[2] = {o->name, o->alias};
        for (int k = 0; k < 2; k++) {
            if (!names[k]) continue;
            int d = cli_edit_distance(text, len, names[k], (int)strlen(names[k]));
            if (d < best) {
                best = d;
                snprintf(best_name, sizeof best_name, "--%s", names[k]);
            }
        }
    }
    if (best <= limit) return best_name;
    /* the start of exactly one name ("--verb" for --verbose) */
    int found = 0;
    for (const cli_option *o = options; o->kind != CLI_OPT_END; o++)
        if (o->name && len > 1 && !strncmp(o->name, text, (size_t)len)) {
            snprintf(best_name, sizeof best_name, "--%s", o->name);
            found++;
        }
    return found == 1 ? best_name : NULL;
}

/* "--name" as the user wrote it (up to '='), or "-x" */
static void option_text(const char *token, const cli_option *o, char *buf, size_t size)
{
    if (token && token[0] == '-' && token[1] == '-')
        snprintf(buf, size, "%.*s", (int)strcspn(token, "="), token);
    else if (o && o->letter) snprintf(buf, size, "-%c", o->letter);
    else snprintf(buf, size, "--%s", o && o->name ? o->name : "?");
}

static void range_text(const cli_option *o, char *buf, size_t size)
{
    if (o->kind == CLI_OPT_INT) {
        if (o->max >= (double)INT_MAX) snprintf(buf, size, ">= %.0f", o->min);
        else snprintf(buf, size, "from %.0f to %.0f", o->min, o->max);
    } else if (isinf(o->max)) {
        snprintf(buf, size, "%s %g", o->open_min ? ">" : ">=", o->min);
    } else if (o->open_min) {
        snprintf(buf, size, "> %g and <= %g", o->min, o->max);
    } else {
        snprintf(buf, size, "from %g to %g", o->min, o->max);
    }
}

static int has_range(const cli_option *o) { return o->min != 0.0 || o->max != 0.0; }

static int parse_long(const char *s, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (!*s || *end || errno || v < INT_MIN || v > INT_MAX) return 0;
    *out = v;
    return 1;
}

static int parse_finite(const char *s, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (!*s || *end || !isfinite(v)) return 0;
    *out = v;
    return 1;
}

/* Store value into o->dest; print the error and return EXIT_USAGE when it
 * is not one the option takes. */
static int apply(const char *who, const char *cmd, const cli_option *o, const char *opt,
                 const char *value)
{
    char range[96];
    switch (o->kind) {
    case CLI_OPT_FLAG: *(int *)o->dest = o->set ? o->set : 1; return EXIT_OK;
    case CLI_OPT_STRING: *(const char **)o->dest = value; return EXIT_OK;
    case CLI_OPT_CALLBACK: return o->take(cmd, o, value);
    case CLI_OPT_INT:
    case CLI_OPT_DOUBLE: {
        double v = 0.0;
        long l = 0;
        if (!value) {
            v = o->implicit;
        } else if (o->kind == CLI_OPT_INT ? !parse_long(value, &l) : !parse_finite(value, &v)) {
            fprintf(stderr, "%s: invalid value '%s' for %s: give %s (see --help)\n", who, value,
                    opt, o->kind == CLI_OPT_INT ? "a whole number" : "a number");
            return EXIT_USAGE;
        } else if (o->kind == CLI_OPT_INT) {
            v = (double)l;
        }
        if (value && has_range(o) &&
            (o->open_min ? !(v > o->min) : !(v >= o->min) || !(v <= o->max))) {
            range_text(o, range, sizeof range);
            fprintf(stderr, "%s: %s %s is out of range: it must be %s (see --help)\n", who, opt,
                    value, range);
            return EXIT_USAGE;
        }
        if (o->kind == CLI_OPT_INT) *(int *)o->dest = (int)v;
        else *(double *)o->dest = v;
        return EXIT_OK;
    }
    case CLI_OPT_ENUM:
        for (int k = 0; o->choices[k]; k++)
            if (!strcmp(value, o->choices[k])) {
                *(int *)o->dest = o->values ? o->values[k] : k;
                return EXIT_OK;
            }
        fprintf(stderr, "%s: invalid value '%s' for %s: give one of ", who, value, opt);
        for (int k = 0; o->choices[k]; k++) fprintf(stderr, "%s%s", k ? ", " : "", o->choices[k]);
        fprintf(stderr, " (see --help)\n");
        return EXIT_USAGE;
    default: return EXIT_INTERNAL;
    }
}

static int looks_numeric(const cli_option *o, const char *s)
{
    long l;
    double d;
    return o->kind == CLI_OPT_INT ? parse_long(s, &l) : parse_finite(s, &d);
}

static int take_positional(const cli_command_options *c, const char *who, int *n, const char *a)
{
    if (*n >= c->max_positionals) {
        const char *what = c->positional_name ? c->positional_name : "argument";
        if (c->max_positionals == 1)
            fprintf(stderr, "%s: one %s only ('%s' and '%s' given)\n", who, what, c->positionals[0],
                    a);
        else if (c->max_positionals == 0)
            fprintf(stderr, "%s: unexpected argument '%s' (see --help)\n", who, a);
        else
            fprintf(stderr, "%s: at most %d %ss ('%s' is one too many)\n", who, c->max_positionals,
                    what, a);
        return EXIT_USAGE;
    }
    c->positionals[(*n)++] = a;
    return EXIT_OK;
}

static void unknown_option(const cli_command_options *c, const char *who, const char *token,
                           int letter)
{
    if (letter) {
        fprintf(stderr, "%s: unknown option -%c (see --help)\n", who, letter);
        return;
    }
    const char *near = cli_options_suggest(c->options, token);
    int len = (int)strcspn(token, "=");
    if (near)
        fprintf(stderr, "%s: unknown option %.*s; did you mean %s? (see --help)\n", who, len, token,
                near);
    else fprintf(stderr, "%s: unknown option %.*s (see --help)\n", who, len, token);
}

static const cli_option *by_letter(const cli_option *t, int letter)
{
    for (; t->kind != CLI_OPT_END; t++)
        if (t->letter && t->letter == letter) return t;
    return NULL;
}

/* SCAF_LIST_OPTIONS=1: the table, one option a line, for tests/docs/test_options.py:
 * --name TAB -x TAB kind TAB min TAB max TAB alias */
static void list_options(const cli_command_options *c)
{
    static const char *kinds[] = {"end",    "group", "flag",     "int", "double",
                                  "string", "enum",  "callback", "help"};
    for (const cli_option *o = c->options; o->kind != CLI_OPT_END; o++) {
        if (o->kind == CLI_OPT_GROUP) continue;
        printf("%s%s\t%s%c\t%s\t", o->name ? "--" : "", o->name ? o->name : "-",
               o->letter ? "-" : "", o->letter ? o->letter : '-', kinds[o->kind]);
        if ((o->kind == CLI_OPT_INT || o->kind == CLI_OPT_DOUBLE) && has_range(o))
            printf("%s%.17g\t%.17g", o->open_min ? ">" : "", o->min, o->max);
        else printf("-\t-");
        printf("\t%s%s\n", o->alias ? "--" : "", o->alias ? o->alias : "-");
    }
}

int cli_options_parse(const cli_command_options *c, int argc, char **argv)
{
    const char *listing = getenv("SCAF_LIST_OPTIONS");
    if (listing && !strcmp(listing, "1")) {
        list_options(c);
        return CLI_OPTIONS_LISTED;
    }
    char who[64]; /* "scaf param", or "scaf" for the global options */
    snprintf(who, sizeof who, "scaf%s%s", c->cmd[0] ? " " : "", c->cmd);
    int n = count_options(c->options), npos = 0, rc = EXIT_OK;
    struct option *longs = calloc((size_t)(2 * n + 1), sizeof *longs);
    char *shorts = malloc((size_t)(3 * n + 3));
    if (!longs || !shorts) {
        free(longs);
        free(shorts);
        fprintf(stderr, "%s: out of memory\n", who);
        return EXIT_NOMEM;
    }
    int nl = 0, ns = 0;
    shorts[ns++] = '+';
    shorts[ns++] = ':';
    for (int i = 0; i < n; i++) {
        const cli_option *o = &c->options[i];
        if (o->kind == CLI_OPT_GROUP) continue;
        int has_arg = o->optional ? optional_argument
            : takes_value(o)      ? required_argument
                                  : no_argument;
        int val = o->letter ? o->letter : LONG_VAL_BASE + i;
        const char *names[2] = {o->name, o->alias};
        for (int k = 0; k < 2; k++)
            if (names[k]) longs[nl++] = (struct option){names[k], has_arg, NULL, val};
        if (o->letter) {
            shorts[ns++] = o->letter;
            if (has_arg != no_argument) shorts[ns++] = ':';
            if (has_arg == optional_argument) shorts[ns++] = ':';
        }
    }
    shorts[ns] = '\0';
    optind = 0; /* glibc: start afresh */
    opterr = 0;
    for (;;) {
        int prev = optind ? optind : 1;
        int ch = getopt_long(argc, argv, shorts, longs, NULL);
        if (ch == -1) {
            if (optind == prev + 1 && !strcmp(argv[prev], "--")) {
                while (rc == EXIT_OK && optind < argc)
                    rc = take_positional(c, who, &npos, argv[optind++]);
                break;
            }
            if (optind >= argc) break;
            rc = take_positional(c, who, &npos, argv[optind++]);
            if (rc != EXIT_OK) break;
            continue;
        }
        const char *token = argv[prev];
        int is_long = token[0] == '-' && token[1] == '-';
        const cli_option *o = NULL;
        if (ch == '?' || ch == ':') {
            int v = optopt;
            o = v >= LONG_VAL_BASE ? &c->options[v - LONG_VAL_BASE]
                : v                ? by_letter(c->options, v)
                                   : NULL;
        } else {
            o = ch >= LONG_VAL_BASE ? &c->options[ch - LONG_VAL_BASE] : by_letter(c->options, ch);
        }
        char text[96];
        option_text(is_long ? token : NULL, o, text, sizeof text);
        if (ch == '?') {
            if (o && is_long) /* a known long option given "=value" it does not take */
                fprintf(stderr, "%s: %s takes no value (see --help)\n", who, text);
            else unknown_option(c, who, is_long ? token : "", is_long ? 0 : optopt);
            rc = EXIT_USAGE;
            break;
        }
        if (ch == ':') {
            fprintf(stderr, "%s: %s needs a value (see --help)\n", who, text);
            rc = EXIT_USAGE;
            break;
        }
        if (is_long) { /* whole names only: getopt_long also takes a prefix */
            size_t len = strcspn(token + 2, "=");
            int whole = (o->name && strlen(o->name) == len && !strncmp(token + 2, o->name, len)) ||
                (o->alias && strlen(o->alias) == len && !strncmp(token + 2, o->alias, len));
            if (!whole) {
                unknown_option(c, who, token, 0);
                rc = EXIT_USAGE;
                break;
            }
        }
        if (o->kind == CLI_OPT_HELP) {
            rc = CLI_OPTIONS_HELP;
            break;
        }
        const char *value = optarg;
        if (o->optional && !value && optind < argc && looks_numeric(o, argv[optind]))
            value = argv[optind++];
        rc = apply(who, c->cmd, o, text, value);
        if (rc != EXIT_OK) break;
    }
    if (c->positional_count) *c->positional_count = npos;
    free(longs);
    free(shorts);
    return rc;
}

/* Print text wrapped at TEXT_WIDTH, continuation lines indented to
 * column; the first line starts at column `at`. '\n' breaks a line. */
static void print_wrapped(FILE *out, const char *text, int column, int at)
{
    const char *p = text;
    while (*p) {
        int room = TEXT_WIDTH - at, len = 0, brk = -1;
        while (p[len] && p[len] != '\n') {
            if (p[len] == ' ') brk = len;
            if (len >= room && brk > 0) break;
            len++;
        }
        int take = p[len] && p[len] != '\n' ? brk : len;
        fprintf(out, "%.*s\n", take, p);
        p += take;
        if (*p == '\n' || *p == ' ') p++;
        if (*p) {
            fprintf(out, "%*s", column, "");
            at = column;
        }
    }
}

void cli_options_help(const cli_command_options *c, FILE *out)
{
    int column = c->help_column > 0 ? c->help_column : DEFAULT_COLUMN, groups = 0;
    fputs(c->usage, out);
    if (c->about) c->about(out);
    for (const cli_option *o = c->options; o->kind != CLI_OPT_END; o++) {
        if (o->kind == CLI_OPT_GROUP) {
            fprintf(out, "%s%s\n", groups++ ? "\n" : "", o->help);
            continue;
        }
        char left[160];
        int len = snprintf(left, sizeof left, "  ");
        if (o->letter)
            len += snprintf(left + len, sizeof left - (size_t)len, "-%c%s", o->letter,
                            o->name ? ", " : "");
        if (o->name) len += snprintf(left + len, sizeof left - (size_t)len, "--%s", o->name);
        if (o->alias) len += snprintf(left + len, sizeof left - (size_t)len, ", --%s", o->alias);
        if (o->metavar)
            len += snprintf(left + len, sizeof left - (size_t)len, o->optional ? " [%s]" : " %s",
                            o->metavar);
        fputs(left, out);
        if (len > column - 2) {
            fprintf(out, "\n%*s", column, "");
        } else {
            fprintf(out, "%*s", column - len, "");
        }
        print_wrapped(out, o->help ? o->help : "", column, column);
    }
    if (c->after) c->after(out);
}

int cli_options_done(const cli_command_options *c, int rc)
{
    if (rc == CLI_OPTIONS_HELP) cli_options_help(c, stdout);
    return rc == CLI_OPTIONS_HELP || rc == CLI_OPTIONS_LISTED ? EXIT_OK : rc;
}

int cli_option_apply(const char *cmd, const cli_option *o, const char *value)
{
    char who[64], opt[80];
    snprintf(who, sizeof who, "scaf%s%s", cmd[0] ? " " : "", cmd);
    snprintf(opt, sizeof opt, "--%s", o->name ? o->name : "?");
    return apply(who, cmd, o, opt, value);
}
