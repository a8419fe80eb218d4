/* base/atomic_file: writing a file so that it appears whole or not at all.
 *
 * atomic_open creates a hidden temporary file next to the target
 * (".NAME.tmpXXXXXX" in the same folder, so the final rename is atomic);
 * atomic_commit flushes, syncs, closes and renames it over the target;
 * atomic_abort closes and removes it. A failed write leaves the target
 * untouched and no temporary file behind. Used for every file scaf
 * writes (meshes, reports, pictures).
 *
 * What "the target" is (atomic_resolve): a symbolic link is written
 * through (the file it points to is replaced, the link is kept, also when
 * it dangles); an existing directory, FIFO, device or socket is refused
 * (SCAF_ERR_IO, nothing created), never replaced by a regular file. An
 * existing target keeps its permission bits.
 *
 * Several files committed together (all or none): atomic_finish each one
 * (everything written and synced, still under its temporary name), and
 * only when all succeeded atomic_rename each one; otherwise atomic_abort
 * them all.
 */
#ifndef SCAF_BASE_ATOMIC_FILE_H
#define SCAF_BASE_ATOMIC_FILE_H

#include <stdio.h>

#include "base/error.h"

typedef struct atomic_file {
    FILE *f;
    char tmp[4096];   /* the temporary file, "" when there is none */
    char path[4096];  /* the resolved target: absolute, links followed */
    const char *name; /* the path as given, for messages */
    int finished;     /* closed and synced, waiting for atomic_rename */
} atomic_file;

/* The file that writing `path` replaces, written into out (size bytes):
 * symbolic links followed, the folder made absolute and canonical
 * (realpath), the last name kept. SCAF_ERR_IO naming the path when the
 * folder does not exist, the links loop, or the target exists and is not
 * a regular file (directory, FIFO, device, socket). *exists (may be NULL)
 * says whether the target exists. */
scaf_status atomic_resolve(const char *path, char *out, size_t size, int *exists, scaf_error *err);

/* Open; SCAF_ERR_IO naming the path when the target is refused by
 * atomic_resolve or its folder is not writable. a->name keeps `path`
 * (the caller keeps it alive until commit or abort). */
scaf_status atomic_open(atomic_file *a, const char *path, scaf_error *err);

/* Flush, sync, close and rename; SCAF_ERR_IO (target untouched) when any
 * write failed. */
scaf_status atomic_commit(atomic_file *a, scaf_error *err);

/* The first half of atomic_commit: flush, sync and close; the data stays
 * under the temporary name. SCAF_ERR_IO (temporary file removed) when any
 * write failed. */
scaf_status atomic_finish(atomic_file *a, scaf_error *err);

/* The second half: rename a finished temporary file over the target. */
scaf_status atomic_rename(atomic_file *a, scaf_error *err);

/* Close and delete the temporary file. Safe after a failed open, after
 * atomic_finish and after a commit (then it does nothing). */
void atomic_abort(atomic_file *a);

#endif /* SCAF_BASE_ATOMIC_FILE_H */
