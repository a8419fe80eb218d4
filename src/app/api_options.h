/* app/api_options: what the options structs of the public API share
 * (scaf_options_t, scaf_atlas_options_t, scaf_drag_options_t and the
 * options of scaf/volume.h): versioning by a leading struct_size, and
 * range checks whose message names the struct and the field.
 *
 * Versioning: the caller's struct starts with size_t struct_size, the
 * size it was compiled with, set by the struct's *_default() function.
 * This version of the library knows exactly one size per struct; any
 * other (0: a struct not started from *_default(), or one of another
 * version) is SCAF_ERR_USAGE naming the struct and both sizes. An option
 * out of range is SCAF_ERR_USAGE naming the field and its value. Options
 * are never silently replaced: a constructor given bad options fails.
 * Why one place: the public entry points of param, atlas, drag and volume
 * said the same things in four ways, two of them by falling back to the
 * defaults.
 */
#ifndef SCAF_APP_API_OPTIONS_H
#define SCAF_APP_API_OPTIONS_H

#include <stddef.h>

#include "base/error.h"

/* Copy the caller's options into out (size bytes: the library's struct):
 * in == NULL takes *def. type names the struct in the message
 * ("scaf_options_t"). SCAF_ERR_USAGE (out = *def) when in's struct_size
 * is not size. */
scaf_status api_options_take(void *out, const void *in, const void *def, size_t size,
                             const char *type, scaf_error *err);

/* The struct_size of options (which start with one). */
static inline size_t api_options_size(const void *options) { return *(const size_t *)options; }

/* Bounds of api_check_real: which ends are open. */
enum { API_CLOSED = 0, API_OPEN_LO = 1, API_OPEN_HI = 2 };

/* v finite and within [lo, hi] (ends open as `open` says): SCAF_OK; else
 * SCAF_ERR_USAGE "WHO: FIELD V must be in [LO, HI]" (who: the struct or
 * the function, e.g. "scaf_drag_options_t" or "inflate"). */
scaf_status api_check_real(scaf_error *err, const char *who, const char *field, double v, double lo,
                           double hi, int open);

/* lo <= v <= hi: SCAF_OK; else SCAF_ERR_USAGE "WHO: FIELD V must be in
 * [LO, HI]". */
scaf_status api_check_int(scaf_error *err, const char *who, const char *field, long v, long lo,
                          long hi);

#endif /* SCAF_APP_API_OPTIONS_H */
