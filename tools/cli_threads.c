/* tools/cli_threads: see cli_threads.h. */
#include "cli_threads.h"

#include <stdlib.h>

#include "scaf/scaf.h"

void cli_threads_apply(int requested)
{
    if (requested < 1) {
        const char *e = getenv("OPENBLAS_NUM_THREADS");
        if (e && *e) {
            /* OpenBLAS already follows it; scaf's own loops follow it too */
            char *end;
            long n = strtol(e, &end, 10);
            if (*end == '\0' && n >= 1 && n <= 4096) scaf_set_threads((int)n);
            return;
        }
    }
    scaf_set_threads(requested < 1 ? 0 : requested);
}
