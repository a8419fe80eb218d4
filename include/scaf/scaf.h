/* scaf/scaf.h: the public C API of scaf.
 *
 * scaf computes bijective maps (UV parametrizations with no flipped triangle
 * and no overlap) with the Simplicial Complex Augmentation Framework
 * (Jiang, Schaefer, Panozzo 2017).
 *
 * Conventions: every function that can fail returns a scaf_status; on
 * failure a message a person can act on is available from the object that
 * failed (see each function). Indices are 0-based. Arrays are row-major:
 * "V #V by 3" means V[3*i+k] is coordinate k of vertex i.
 */
#ifndef SCAF_SCAF_H
#define SCAF_SCAF_H

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes. The command-line program maps them to exit codes
 * (see scaf_status_exit_code). */
typedef enum scaf_status {
    SCAF_OK = 0,
    SCAF_ERR_USAGE,      /* invalid argument or option value */
    SCAF_ERR_IO,         /* a file cannot be opened, read or written */
    SCAF_ERR_PARSE,      /* malformed input file (syntax, index, number) */
    SCAF_ERR_MESH,       /* the mesh is invalid for the operation (topology,
                            degenerate faces, NaN, wrong chart type) */
    SCAF_ERR_NUMERIC,    /* a numerical step failed (factorization, ...) */
    SCAF_ERR_NOMEM,      /* out of memory */
    SCAF_ERR_CANCELLED,  /* stopped by the caller's progress callback */
    SCAF_ERR_INTERNAL    /* a bug: an invariant of scaf itself broke */
} scaf_status;

/* A short, static English name of a status ("parse error", ...). */
const char *scaf_status_name(scaf_status status);

/* The version of the library, "MAJOR.MINOR.PATCH". */
const char *scaf_version(void);

#ifdef __cplusplus
}
#endif
#endif /* SCAF_SCAF_H */
