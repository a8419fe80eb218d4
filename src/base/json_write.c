/* base/json_write: see json_write.h. */
#include "base/json_write.h"

#include <math.h>

void json_write_string(FILE *out, const char *s)
{
    if (!s) {
        fputs("null", out);
        return;
    }
    fputc('"', out);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\') fprintf(out, "\\%c", *c);
        else if (*c < 0x20) fprintf(out, "\\u%04x", *c);
        else fputc(*c, out);
    }
    fputc('"', out);
}

void json_write_number(FILE *out, double x)
{
    if (isfinite(x)) fprintf(out, "%.17g", x);
    else fputs("null", out);
}

void json_write_report_head(FILE *out, const char *command)
{
    fputs("{\n  \"schema\": \"" SCAF_REPORT_SCHEMA "\",\n  \"command\": ", out);
    json_write_string(out, command);
}
