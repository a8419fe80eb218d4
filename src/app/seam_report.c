/* app/seam_report: the seams in a JSON report (see the header). */
#include "app/seam_report.h"

#include <stdlib.h>
#include <string.h>

#include "app/seam_source.h"
#include "base/json_write.h"

/* The primitive -> charts table (charts as a sorted list of ids). */
static void gltf_primitives_json(FILE *o, const seam_report *s)
{
    char *seen = calloc((size_t)(s->ncharts > 0 ? s->ncharts : 1), 1);
    fputs(",\n  \"gltf_primitives\": [", o);
    for (int k = 0; k < s->npieces; k++) {
        const gltf_piece *p = &s->pieces[k];
        fprintf(o, "%s\n    {\"mesh\": %d, \"mesh_name\": ", k ? "," : "", p->mesh);
        json_write_string(o, p->mesh_name);
        fprintf(o, ", \"primitive\": %d, \"first_face\": %d, \"faces\": %d, \"charts\": [",
                p->primitive, p->first_face, p->faces);
        if (seen) {
            memset(seen, 0, (size_t)(s->ncharts > 0 ? s->ncharts : 1));
            for (int f = p->first_face; f < p->first_face + p->faces && f < s->nf; f++) {
                int c = s->face_chart[f];
                if (c >= 0 && c < s->ncharts) seen[c] = 1;
            }
            for (int c = 0, first = 1; c < s->ncharts; c++)
                if (seen[c]) {
                    fprintf(o, "%s%d", first ? "" : ", ", c);
                    first = 0;
                }
        }
        fputs("]}", o);
    }
    fputs("\n  ]", o);
    free(seen);
}

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
    if (s->face_chart && s->pieces) gltf_primitives_json(o, s);
}
