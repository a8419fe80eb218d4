/* tools/exit_codes: the exit statuses of the `scaf` program.
 * Documented in docs/cli.md; scripts depend on them, never renumber. */
#ifndef SCAF_TOOLS_EXIT_CODES_H
#define SCAF_TOOLS_EXIT_CODES_H

#include <stdio.h>

#include "scaf/scaf.h"

enum {
    EXIT_OK = 0,
    EXIT_NOT_BIJECTIVE = 1, /* `scaf check`: the map is not bijective */
    EXIT_USAGE = 2,         /* bad command line */
    EXIT_INPUT = 3,         /* input file missing, unreadable or malformed */
    EXIT_MESH = 4,          /* input readable but invalid for the command */
    EXIT_OUTPUT = 5,        /* output could not be written */
    EXIT_NUMERIC = 6,       /* numerical failure */
    EXIT_NOMEM = 7,         /* out of memory */
    EXIT_CANCELLED = 8,     /* interrupted */
    EXIT_INFEASIBLE = 9,    /* `scaf deform`: pins / hard targets not met */
    EXIT_INTERNAL = 70      /* a bug in scaf */
};

/* Every exit status and what it means, in one table: the help texts print
 * it (exit_codes_print), so a code added to the enum above and here shows
 * up in every help at once (tests/docs/test_help.py compares the enum, this
 * list and docs/cli.md's table). */
typedef struct exit_code_meaning {
    int code;
    const char *meaning;
} exit_code_meaning;

static inline const exit_code_meaning *exit_code_meanings(int *count)
{
    static const exit_code_meaning table[] = {
        {EXIT_OK, "success (`scaf check`: the map is bijective)"},
        {EXIT_NOT_BIJECTIVE,
         "`scaf check`: the map is not bijective (a 3D surface intersects itself,\n"
         "a tet mesh has a tet that is not positive)"},
        {EXIT_USAGE, "bad command line (unknown option, value out of range, missing file)"},
        {EXIT_INPUT, "input file missing, unreadable or malformed"},
        {EXIT_MESH,
         "input readable but invalid for the command (a chart that is not a disk,\n"
         "a degenerate face, input UVs not bijective with --init input; check: no UVs)"},
        {EXIT_OUTPUT, "output could not be written (nothing partial is left behind)"},
        {EXIT_NUMERIC, "numerical failure"},
        {EXIT_NOMEM, "out of memory"},
        {EXIT_CANCELLED, "interrupted (SIGINT, SIGTERM, SIGHUP): nothing partial is left behind"},
        {EXIT_INFEASIBLE,
         "`scaf deform`: the pins and hard targets cannot all be met by a bijective\n"
         "map (found before any work, or hard targets still missing when the run\n"
         "stalled or stopped); nothing is written"},
        {EXIT_INTERNAL, "internal error (a bug: please report it)"},
    };
    *count = (int)(sizeof table / sizeof table[0]);
    return table;
}

/* "Exit status:" and one line per code (continuation lines indented). */
static inline void exit_codes_print(FILE *o)
{
    int n;
    const exit_code_meaning *t = exit_code_meanings(&n);
    fputs("Exit status:\n", o);
    for (int i = 0; i < n; i++) {
        fprintf(o, "  %-3d ", t[i].code);
        for (const char *c = t[i].meaning; *c; c++) {
            fputc(*c, o);
            if (*c == '\n') fputs("      ", o);
        }
        fputc('\n', o);
    }
}

/* Map a library status to the program's exit status. Output-side I/O
 * failures are told apart by the caller (EXIT_OUTPUT). */
static inline int exit_code_for(scaf_status s)
{
    switch (s) {
    case SCAF_OK: return EXIT_OK;
    case SCAF_ERR_USAGE: return EXIT_USAGE;
    case SCAF_ERR_IO: return EXIT_INPUT;
    case SCAF_ERR_PARSE: return EXIT_INPUT;
    case SCAF_ERR_MESH: return EXIT_MESH;
    case SCAF_ERR_NUMERIC: return EXIT_NUMERIC;
    case SCAF_ERR_NOMEM: return EXIT_NOMEM;
    case SCAF_ERR_CANCELLED: return EXIT_CANCELLED;
    case SCAF_ERR_INTERNAL: return EXIT_INTERNAL;
    }
    return EXIT_INTERNAL;
}

#endif
