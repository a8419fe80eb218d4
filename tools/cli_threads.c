/* tools/cli_threads: see cli_threads.h. */
#include "cli_threads.h"

#include <stdlib.h>

#include "scaf/scaf.h"

void cli_threads_apply(int requested)
{
    if (requested < 1) {
        const char *e = getenv("OPENBLAS_NUM_THREADS");
        if (e && *e) return; /* OpenBLAS already follows it */
    }
    scaf_set_threads(requested < 1 ? 0 : requested);
}
