/* tools/cli_args: strict parsing of numeric option values.
 * The whole string must be a number: "12x", "" and "nan" are refused, so
 * a typo is a usage error rather than a silent default. */
#ifndef SCAF_TOOLS_CLI_ARGS_H
#define SCAF_TOOLS_CLI_ARGS_H

/* A whole decimal integer in [0, 1e8]: 1 and *out set, or 0. */
int cli_parse_int(const char *s, int *out);

/* A whole finite floating-point number: 1 and *out set, or 0. */
int cli_parse_double(const char *s, double *out);

/* An argument that is no known option of command CMD: the input path when
 * it is the first such and not an option ("-" alone is a path); otherwise
 * a usage error naming it. Returns EXIT_OK (and *in set) or EXIT_USAGE. */
int cli_take_input(const char *cmd, const char *a, const char **in);

/* Inside an argument loop `for (i ...) { const char *a = argv[i], *v =
 * i + 1 < argc ? argv[i + 1] : NULL; ... }` of command CMD: take the
 * option's value (or fail with a usage error naming the option), and
 * refuse a value that does not parse. Both return EXIT_USAGE from the
 * enclosing function on failure (needs <stdio.h> and exit_codes.h). */
#define CLI_NEED_VALUE(cmd)                                                                        \
    do {                                                                                           \
        if (!v) {                                                                                  \
            fprintf(stderr, "scaf %s: %s needs a value (see --help)\n", (cmd), a);                 \
            return EXIT_USAGE;                                                                     \
        }                                                                                          \
        i++;                                                                                       \
    } while (0)
#define CLI_BAD_VALUE(cmd)                                                                         \
    do {                                                                                           \
        fprintf(stderr, "scaf %s: invalid value '%s' for %s (see --help)\n", (cmd), v, a);         \
        return EXIT_USAGE;                                                                         \
    } while (0)

/* A value that parsed but lies outside RANGE (text such as ">= 1"): a
 * usage error that says the allowed range. Ranges the library checks
 * (param_options_check, atlas_options_check) are left to it, so each
 * range is written once; this is for options only the program has. */
#define CLI_OUT_OF_RANGE(cmd, range)                                                               \
    do {                                                                                           \
        fprintf(stderr, "scaf %s: %s %s is out of range: it must be %s\n", (cmd), a, v, (range));  \
        return EXIT_USAGE;                                                                         \
    } while (0)

#endif
