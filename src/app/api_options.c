/* app/api_options: see api_options.h. */
#include "app/api_options.h"

#include <math.h>
#include <string.h>

scaf_status api_options_take(void *out, const void *in, const void *def, size_t size,
                             const char *type, scaf_error *err)
{
    memcpy(out, def, size);
    if (!in) return SCAF_OK;
    size_t given = api_options_size(in);
    if (given != size)
        return err_set(err, SCAF_ERR_USAGE,
                       "%s.struct_size is %zu, but this library's %s has %zu bytes: start from "
                       "its _default() function",
                       type, given, type, size);
    memcpy(out, in, size);
    return SCAF_OK;
}

scaf_status api_check_real(scaf_error *err, const char *who, const char *field, double v, double lo,
                           double hi, int open)
{
    int ok = isfinite(v) && ((open & API_OPEN_LO) ? v > lo : v >= lo) &&
        ((open & API_OPEN_HI) ? v < hi : v <= hi);
    if (ok) return SCAF_OK;
    return err_set(err, SCAF_ERR_USAGE, "%s: %s %g must be in %c%g, %g%c", who, field, v,
                   (open & API_OPEN_LO) ? '(' : '[', lo, hi, (open & API_OPEN_HI) ? ')' : ']');
}

scaf_status api_check_int(scaf_error *err, const char *who, const char *field, long v, long lo,
                          long hi)
{
    if (v >= lo && v <= hi) return SCAF_OK;
    return err_set(err, SCAF_ERR_USAGE, "%s: %s %ld must be in [%ld, %ld]", who, field, v, lo, hi);
}
