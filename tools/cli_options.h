/* tools/cli_options: one option table per command drives parsing, range
 * checks and --help.
 *
 * A command lists its options once, as an array of cli_option (long name,
 * short letter, kind of value and its range or allowed names, where the
 * value goes, help text, group heading); cli_options_parse reads argv with
 * getopt_long from the C library and cli_options_help prints the help from
 * the same array, so the two cannot drift. What every command gets:
 *   --name=VALUE and --name VALUE; grouped short flags (-qo out.obj);
 *   "--" ends the options (later arguments are positionals, even "-x");
 *   "-" alone is a positional (the standard input / output);
 *   long names are matched whole, never abbreviated (so a new option
 *   cannot break a script using a prefix);
 *   an unknown option names the closest known one (edit distance):
 *     "scaf param: unknown option --iteratoins; did you mean --iterations?";
 *   one wording for every bad value, all exit 2 (EXIT_USAGE):
 *     "scaf CMD: --NAME needs a value (see --help)"
 *     "scaf CMD: invalid value 'V' for --NAME: give a whole number (see --help)"
 *     "scaf CMD: --NAME V is out of range: it must be from 1 to 64 (see --help)"
 *     "scaf CMD: invalid value 'V' for --NAME: give one of a, b, c (see --help)"
 *     "scaf CMD: --NAME takes no value (see --help)".
 * Help: the usage lines, the command's text, then each group heading and
 * its options as "  -s, --name META   help" with the help text wrapped at 80
 * columns (a '\n' in it starts a new line), then the command's closing text.
 * Everything is generated piecewise: no literal needs more than the 4095
 * characters C17 guarantees.
 *
 * The table may be a local array: its dest pointers then point at the
 * command's own locals. Declaring an option is docs/ARCHITECTURE.md (CLI). */
#ifndef SCAF_TOOLS_CLI_OPTIONS_H
#define SCAF_TOOLS_CLI_OPTIONS_H

#include <stdio.h>

typedef enum cli_option_kind {
    CLI_OPT_END = 0,  /* ends the table ({0}) */
    CLI_OPT_GROUP,    /* a heading in --help ("options:", "pictures:"); help = heading */
    CLI_OPT_FLAG,     /* no value: *(int *)dest = 1 (or .set when nonzero) */
    CLI_OPT_INT,      /* whole number in [min, max]: *(int *)dest */
    CLI_OPT_DOUBLE,   /* finite number in [min, max] (see open_min): *(double *)dest */
    CLI_OPT_STRING,   /* any text: *(const char **)dest points into argv */
    CLI_OPT_ENUM,     /* one of choices: *(int *)dest = its index, or values[index] */
    CLI_OPT_CALLBACK, /* the value (or NULL for a flag) handed to take() */
    CLI_OPT_HELP      /* -h / --help: cli_options_parse returns CLI_OPTIONS_HELP */
} cli_option_kind;

typedef struct cli_option cli_option;

/* A CALLBACK option's value is given to take(cmd, opt, value): return 0 to
 * accept, or print "scaf CMD: ..." and return EXIT_USAGE (or another exit
 * status) to stop. value is NULL for a CALLBACK without a metavar. */
typedef int (*cli_option_take)(const char *cmd, const cli_option *opt, const char *value);

struct cli_option {
    const char *name; /* long name without "--"; NULL: short only */
    char letter;      /* short option letter, or 0 */
    cli_option_kind kind;
    void *dest;                 /* where the value goes (see the kinds) */
    const char *metavar;        /* "N", "FILE" in --help; NULL for a flag */
    const char *help;           /* the help text (wrapped; '\n' breaks a line) */
    double min, max;            /* INT and DOUBLE: the range (both 0: any value) */
    int open_min;               /* DOUBLE: min itself excluded ("> min") */
    const char *const *choices; /* ENUM: allowed names, NULL-terminated */
    const int *values;          /* ENUM: the value of each name (NULL: its index) */
    const char *alias;          /* a second long name, the same option */
    int set;                    /* FLAG: the value stored (0 means 1) */
    int optional;               /* INT / DOUBLE: the value may be left out (implicit
                            is stored); a following argument is taken as the
                            value only when it is a number */
    double implicit;
    cli_option_take take; /* CALLBACK */
};

/* Table entries. The last argument is the help text, optionally followed
 * by designated fields: CLI_DOUBLE("box-scale", 0, &s, "S", 1, 1e6, "box
 * size", .open_min = 1). Ranges are inclusive; INT_MAX (or INFINITY) as
 * max: no upper bound. */
#define CLI_GROUP(heading)                                                                         \
    {                                                                                              \
        .kind = CLI_OPT_GROUP, .help = (heading)                                                   \
    }
#define CLI_FLAG(nm, ch, dst, ...)                                                                 \
    {                                                                                              \
        .name = (nm), .letter = (ch), .kind = CLI_OPT_FLAG, .dest = (dst), .help = __VA_ARGS__     \
    }
#define CLI_INT(nm, ch, dst, meta, lo, hi, ...)                                                    \
    {                                                                                              \
        .name = (nm), .letter = (ch), .kind = CLI_OPT_INT, .dest = (dst), .metavar = (meta),       \
        .min = (lo), .max = (hi), .help = __VA_ARGS__                                              \
    }
#define CLI_DOUBLE(nm, ch, dst, meta, lo, hi, ...)                                                 \
    {                                                                                              \
        .name = (nm), .letter = (ch), .kind = CLI_OPT_DOUBLE, .dest = (dst), .metavar = (meta),    \
        .min = (lo), .max = (hi), .help = __VA_ARGS__                                              \
    }
#define CLI_STRING(nm, ch, dst, meta, ...)                                                         \
    {                                                                                              \
        .name = (nm), .letter = (ch), .kind = CLI_OPT_STRING, .dest = (dst), .metavar = (meta),    \
        .help = __VA_ARGS__                                                                        \
    }
#define CLI_ENUM(nm, ch, dst, meta, names, ...)                                                    \
    {                                                                                              \
        .name = (nm), .letter = (ch), .kind = CLI_OPT_ENUM, .dest = (dst), .metavar = (meta),      \
        .choices = (names), .help = __VA_ARGS__                                                    \
    }
#define CLI_CALLBACK(nm, ch, fn, dst, meta, ...)                                                   \
    {                                                                                              \
        .name = (nm), .letter = (ch), .kind = CLI_OPT_CALLBACK, .take = (fn), .dest = (dst),       \
        .metavar = (meta), .help = __VA_ARGS__                                                     \
    }
/* The -h, --help entry every table has. */
#define CLI_OPTION_HELP                                                                            \
    {                                                                                              \
        .name = "help", .letter = 'h', .kind = CLI_OPT_HELP, .help = "this text"                   \
    }

/* A command's whole command line. */
typedef struct cli_command_options {
    const char *cmd;             /* "param" in "scaf param: ..." */
    const char *usage;           /* the usage line(s), "usage: scaf param IN -o OUT [options]\n" */
    void (*about)(FILE *out);    /* the text between the usage and the options, or NULL */
    void (*after)(FILE *out);    /* the text after the options (exit codes ...), or NULL */
    const cli_option *options;   /* the table, ended by {0} */
    int help_column;             /* where help texts start (default 25) */
    const char **positionals;    /* filled in order (NULL when unused) */
    int max_positionals;         /* more: a usage error */
    const char *positional_name; /* "input" in "one input only (...)" */
    int *positional_count;       /* set to how many were given (may be NULL) */
} cli_command_options;

enum { CLI_OPTIONS_OK = 0, CLI_OPTIONS_HELP = -1, CLI_OPTIONS_LISTED = -2 };

/* Parse argv[1 .. argc-1] (argv[0] is the command name). Returns
 * CLI_OPTIONS_OK with every dest set that was given; CLI_OPTIONS_HELP
 * when -h / --help came (nothing printed: call cli_options_help); or an
 * exit status (EXIT_USAGE) after printing the error on stderr.
 * With the environment variable SCAF_LIST_OPTIONS=1 it prints the table
 * instead (one option a line: --name, -x, kind, min, max, alias; for
 * tests/docs/test_options.py) and returns CLI_OPTIONS_LISTED. */
int cli_options_parse(const cli_command_options *c, int argc, char **argv);

/* After a parse that did not return CLI_OPTIONS_OK: print the help for
 * CLI_OPTIONS_HELP, and return the command's exit status (0 for help and
 * the SCAF_LIST_OPTIONS=1 listing, else rc). The usual lines:
 *   int rc = cli_options_parse(&c, argc, argv);
 *   if (rc != CLI_OPTIONS_OK) return cli_options_done(&c, rc); */
int cli_options_done(const cli_command_options *c, int rc);

/* Store value as option o says (its kind, range, choices, dest), with the
 * parser's error messages: for a CALLBACK that parses its value as another
 * kind would (a copy of its entry with .kind and .dest changed) before
 * acting on it. EXIT_OK, or EXIT_USAGE after the message. */
int cli_option_apply(const char *cmd, const cli_option *o, const char *value);

/* The whole --help text of the command. */
void cli_options_help(const cli_command_options *c, FILE *out);

/* The closest long name (with "--") to text (an unknown option, with or
 * without "--" and "=value"), or NULL when none is close: edit distance at
 * most 1 for names up to 4 letters, 2 up to 8, 3 above; failing that, the
 * one name text begins ("--verb": --verbose). */
const char *cli_options_suggest(const cli_option *options, const char *text);

/* Levenshtein distance of a[0..na) and b[0..nb) (na, nb < 64; longer
 * strings are compared on their first 63 characters). */
int cli_edit_distance(const char *a, int na, const char *b, int nb);

#endif
