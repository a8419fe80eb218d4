/* app/seam_report: the seams in a JSON report (see the header). */
#include "app/seam_report.h"

#include "app/seam_source.h"
#include "base/json_write.h"

void seam_report_json(FILE *o, const seam_report *s)
{
    if (!s) return;
    fputs(",\n  \"seams\": {\"source\": ", o);
    json_write_string(o, seam_source_name(s->used));
    fputs(", \"why\": ", o);
    json_write_string(o, s->why ? s->why : "");
    fprintf(o, ", \"charts\": %d", s->ncharts);
    if (s->edges) {
        fprintf(o, ", \"edges\": %d, \"length\": ", s->edges->n);
        json_write_number(o, s->edges->length);
        fputs(", \"area\": ", o);
        json_write_number(o, s->edges->area);
        fputs(", \"length_per_sqrt_area\": ", o);
        json_write_number(o, s->edges->normalized);
        fputs(",\n    \"seam_edges\": [", o);
        for (int i = 0; i < s->edges->n; i++)
            fprintf(o, "%s[%d, %d]", i ? (i % 16 ? ", " : ",\n      ") : "", s->edges->ab[2 * i],
                    s->edges->ab[2 * i + 1]);
        fputc(']', o);
    }
    fputc('}', o);
    if (s->face_chart) {
        fputs(",\n  \"face_chart\": [", o);
        for (int f = 0; f < s->nf; f++)
            fprintf(o, "%s%d", f ? (f % 32 ? ", " : ",\n    ") : "", s->face_chart[f]);
        fputc(']', o);
    }
}
