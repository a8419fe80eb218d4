/* app/atlas_report: JSON report and SVG picture of an atlas (see
 * atlas_report.h). */
#include "app/atlas_report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/atomic_file.h"
#include "app/seam_report.h"
#include "base/json_write.h"

scaf_status atlas_report_write(const char *path, const atlas_report *r, scaf_error *err)
{
    const atlas *a = r->a;
    double *E = malloc(sizeof(double) * (size_t)(a->ncharts ? a->ncharts : 1));
    if (!E) return err_nomem(err, "atlas report");
    atlas_chart_energy(a, E);
    atomic_file af;
    scaf_status st = atomic_open(&af, path, err);
    if (st != SCAF_OK) {
        free(E);
        return st;
    }
    FILE *o = af.f;
    const atlas_options *op = &a->opt;
    json_write_report_head(o, "atlas");
    fputs(",\n  \"input\": ", o);
    json_write_string(o, r->input);
    fputs(",\n  \"output\": ", o);
    json_write_string(o, r->output);
    fputs(",\n  \"options\": {\"padding\": ", o);
    json_write_number(o, op->padding);
    fputs(", \"resolution\": ", o);
    json_write_number(o, r->resolution > 0 ? r->resolution : NAN);
    fprintf(o, ", \"init\": \"%s\", \"settle_iterations\": %d, \"settle_tolerance\": ",
            op->init_input ? "input"
                           : (op->base.init == SCAF_INIT_HARMONIC  ? "harmonic"
                                  : op->base.init == SCAF_INIT_MVC ? "mvc"
                                                                   : "tutte"),
            op->settle_iterations);
    json_write_number(o, op->settle_tolerance);
    fprintf(o, ", \"compact_iterations\": %d, \"compact_box_scale\": ", op->compact_iterations);
    json_write_number(o, op->compact_box_scale);
    fputs(", \"compact_fraction\": ", o);
    json_write_number(o, op->compact_fraction);
    fputs(", \"distortion_tolerance\": ", o);
    json_write_number(o, op->distortion_tolerance);
    fputs(", \"box_scale\": ", o);
    json_write_number(o, op->base.box_scale);
    fputs(", \"lambda_ratio\": ", o);
    json_write_number(o, op->base.lambda_ratio);
    fputs(", \"compact_lambda_ratio\": ", o);
    json_write_number(o, op->compact_lambda_ratio);
    fprintf(o,
            "},\n  \"mesh\": {\"vertices\": %d, \"faces\": %d, \"charts\": %d},\n  \"split_uvs\": "
            "%d,\n",
            a->nv, a->nf, a->ncharts, a->split_uvs);
    fputs("  \"setup_seconds\": ", o);
    json_write_number(o, r->setup_seconds);
    fputs(",\n  \"seconds\": ", o);
    json_write_number(o, r->total_seconds);
    fprintf(o,
            ",\n  \"iteration_count\": %d,\n  \"settle_iterations_run\": %d,\n"
            "  \"compact_iterations_run\": %d,\n",
            r->niterations, a->settle_done, a->compact_done);
    fprintf(o, "  \"compaction_kept_earlier_layout\": %s,\n",
            a->compact_restored ? "true" : "false");
    fprintf(o,
            "  \"stop_reason\": \"%s\",\n  \"phase_stop_reasons\": {\"settle\": \"%s\", "
            "\"compact\": \"%s\"},\n",
            scaf_stop_reason_name(atlas_stop_reason(a)), scaf_stop_reason_name(a->settle_stop),
            scaf_stop_reason_name(a->compact_stop));
    fputs("  \"settled_energy\": ", o);
    json_write_number(o, a->settled_energy);
    fputs(",\n  \"final_energy\": ", o);
    json_write_number(o, scaf_loop_energy(&a->loop));
    fputs(",\n  \"energy\": ", o);
    json_write_number(o, r->out_energy);
    fputs(",\n  \"packing_efficiency_before_compaction\": ", o);
    json_write_number(o, a->eff_before);
    fputs(",\n  \"packing_efficiency_after_repack\": ", o);
    json_write_number(o, a->eff_packed);
    fputs(",\n  \"packing_efficiency_after_compaction\": ", o);
    json_write_number(o, a->eff_after);
    fputs(",\n  \"min_chart_gap_before_compaction\": ", o);
    json_write_number(o, a->gap_before);
    fputs(",\n  \"min_chart_gap_after_compaction\": ", o);
    json_write_number(o, a->gap_after);
    fputs(",\n  \"min_chart_gap\": ", o);
    json_write_number(o, r->out_gap);
    fputs(",\n  \"packing_efficiency\": ", o);
    json_write_number(o, r->out_efficiency);
    fputs(",\n  \"chart_distortion\": [", o);
    for (int c = 0; c < a->ncharts; c++) {
        if (c) fputs(", ", o);
        json_write_number(o, E[c]);
    }
    fputc(']', o);
    seam_report_json(o, r->seams);
    fputs(",\n  \"iterations\": [", o);
    for (int i = 0; i < r->niterations; i++) {
        const atlas_iteration *it = &r->iterations[i];
        fprintf(o, "%s\n    {\"iteration\": %d, \"phase\": \"%s\", \"energy\": ", i ? "," : "",
                it->info.iteration, it->phase == ATLAS_COMPACT ? "compact" : "settle");
        json_write_number(o, it->info.energy);
        fputs(", \"total_before\": ", o);
        json_write_number(o, it->info.total_before);
        fputs(", \"total_after\": ", o);
        json_write_number(o, it->info.total_after);
        fputs(", \"step\": ", o);
        json_write_number(o, it->info.step);
        fputs(", \"seconds\": ", o);
        json_write_number(o, it->info.seconds);
        fprintf(o, ", \"scaffold_triangles\": %d, \"side\": ", it->info.scaffold_triangles);
        json_write_number(o, it->side);
        fputs(", \"min_chart_gap\": ", o);
        json_write_number(o, it->gap);
        fputs(", \"packing_efficiency\": ", o);
        json_write_number(o, it->efficiency);
        fputc('}', o);
    }
    fputs("\n  ]\n}\n", o);
    free(E);
    return atomic_commit(&af, err);
}

unsigned atlas_chart_colour(int c)
{
    double h = fmod(0.13 + 0.6180339887498949 * c, 1.0) * 6.0, s = 0.55, v = 0.92;
    int i = (int)h;
    double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    unsigned out = 0;
    for (int k = 0; k < 3; k++) out = (out << 8) | (unsigned)lround(rgb[i % 6][k] * 255.0);
    return out;
}

/* Each chart's number at the centroid of its largest triangle (a point
 * inside the chart), as SVG text of class "chart". */
static void chart_numbers(FILE *o, const atlas *a, const double *UV, double x0, double y0, double S)
{
    int nc = a->ncharts > 0 ? a->ncharts : 1;
    int *best = malloc(sizeof(int) * (size_t)nc);
    double *area = malloc(sizeof(double) * (size_t)nc);
    if (!best || !area) { /* the picture stays valid without them */
        free(best);
        free(area);
        return;
    }
    for (int c = 0; c < nc; c++) best[c] = -1, area[c] = -1.0;
    for (int f = 0; f < a->nf; f++) {
        int c = a->chart[f];
        if (c < 0 || c >= a->ncharts) continue;
        const double *p = UV + 2 * (size_t)a->Fw[3 * f], *q = UV + 2 * (size_t)a->Fw[3 * f + 1],
                     *r = UV + 2 * (size_t)a->Fw[3 * f + 2];
        double s = fabs((q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]));
        if (s > area[c]) area[c] = s, best[c] = f;
    }
    fputs("<g id=\"chart-numbers\" font-family=\"sans-serif\" font-size=\"12\" "
          "text-anchor=\"middle\" dominant-baseline=\"middle\">\n",
          o);
    for (int c = 0; c < a->ncharts; c++) {
        if (best[c] < 0) continue;
        double cx = 0, cy = 0;
        for (int j = 0; j < 3; j++) {
            cx += UV[2 * (size_t)a->Fw[3 * best[c] + j]] / 3.0;
            cy += UV[2 * (size_t)a->Fw[3 * best[c] + j] + 1] / 3.0;
        }
        fprintf(o, "<text class=\"chart\" x=\"%.2f\" y=\"%.2f\">%d</text>\n", x0 + cx * S,
                y0 + (1.0 - cy) * S, c);
    }
    fputs("</g>\n", o);
    free(best);
    free(area);
}

scaf_status atlas_svg_write(const char *path, const atlas *a, const double *UV, const char *title,
                            scaf_error *err)
{
    atomic_file af;
    scaf_status st = atomic_open(&af, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = af.f;
    const double S = 1000.0, M = 20.0;
    fprintf(o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(o,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 "
            "0 %.0f %.0f\">\n",
            S + 2 * M, S + 2 * M + 55, S + 2 * M, S + 2 * M + 55);
    fprintf(o, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    if (title) {
        fprintf(o, "<text x=\"%.0f\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">", M);
        for (const char *c = title; *c; c++) {
            if (*c == '<') fputs("&lt;", o);
            else if (*c == '>') fputs("&gt;", o);
            else if (*c == '&') fputs("&amp;", o);
            else fputc(*c, o);
        }
        fputs("</text>\n", o);
    }
    fprintf(o,
            "<rect id=\"unit-square\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" "
            "fill=\"none\" stroke=\"#888\"/>\n",
            M, M + 30, S, S);
    fprintf(o, "<g stroke-width=\"0.15\" stroke-linejoin=\"round\">\n");
    for (int f = 0; f < a->nf; f++) {
        unsigned col = atlas_chart_colour(a->chart[f]);
        fputs("<polygon points=\"", o);
        for (int j = 0; j < 3; j++) {
            const double *p = UV + 2 * (size_t)a->Fw[3 * f + j];
            fprintf(o, "%s%.2f,%.2f", j ? " " : "", M + p[0] * S, M + 30 + (1.0 - p[1]) * S);
        }
        fprintf(o, "\" fill=\"#%06x\" stroke=\"#%06x\"/>\n", col, col);
    }
    fputs("</g>\n", o);
    chart_numbers(o, a, UV, M, M + 30, S);
    /* the padding at the square's scale, below it */
    double py = M + 30 + S + 18, px = M + 60, len = a->opt.padding * S;
    fprintf(o,
            "<g id=\"padding\" font-family=\"sans-serif\" font-size=\"11\">\n<text x=\"%.1f\" "
            "y=\"%.1f\">padding</text>\n",
            M, py + 4);
    fprintf(o,
            "<line x1=\"%.2f\" y1=\"%.1f\" x2=\"%.2f\" y2=\"%.1f\" stroke=\"#202020\" "
            "stroke-width=\"2\" data-padding=\"%.6g\"/>\n",
            px, py, px + len, py, a->opt.padding);
    fprintf(o, "<text x=\"%.2f\" y=\"%.1f\">%g of the unit square</text>\n</g>\n", px + len + 6,
            py + 4, a->opt.padding);
    fputs("</svg>\n", o);
    return atomic_commit(&af, err);
}
