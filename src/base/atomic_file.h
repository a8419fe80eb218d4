/* base/atomic_file: writing a file so that it appears whole or not at all.
 *
 * atomic_open creates a hidden temporary file next to the target
 * (".NAME.tmpXXXXXX" in the same folder, so the final rename is atomic);
 * atomic_commit flushes, syncs, closes and renames it over the target;
 * atomic_abort closes and removes it. A failed write leaves the target
 * untouched and no temporary file behind. Used for every file scaf
 * writes (meshes, reports, pictures).
 */
#ifndef SCAF_BASE_ATOMIC_FILE_H
#define SCAF_BASE_ATOMIC_FILE_H

#include <stdio.h>

#include "base/error.h"

typedef struct atomic_file {
    FILE *f;
    char tmp[4096];
    char path[4096];
} atomic_file;

/* Open; SCAF_ERR_IO naming the path when the folder is not writable. */
scaf_status atomic_open(atomic_file *a, const char *path, scaf_error *err);

/* Flush, sync, close and rename; SCAF_ERR_IO (target untouched) when any
 * write failed. */
scaf_status atomic_commit(atomic_file *a, scaf_error *err);

/* Close and delete the temporary file. Safe after a failed open. */
void atomic_abort(atomic_file *a);

#endif /* SCAF_BASE_ATOMIC_FILE_H */
