/* tools/exit_codes: the exit statuses of the `scaf` program.
 * Documented in README.md; scripts depend on them, never renumber. */
#ifndef SCAF_TOOLS_EXIT_CODES_H
#define SCAF_TOOLS_EXIT_CODES_H

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
    EXIT_INTERNAL = 70      /* a bug in scaf */
};

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
