/* app/atlas_report: the JSON report and the SVG picture of an atlas run.
 *
 * Report: one JSON object (docs/reports.md) with the schema and command,
 * the input/output names, options, mesh sizes and chart count, split UVs, why the run stopped (stop_reason: the last phase's
 * reason, phase_stop_reasons: each phase's), every iteration (phase, E, total energy before/after
 * the step, step, seconds, side, normalized smallest chart gap, packing
 * efficiency), packing efficiency and min_chart_gap before and after
 * compaction, the final ones of the output, the area-matched E of the
 * output (scaf_area_matched_energy) and per-chart distortion.
 * Picture: the normalized atlas in the unit square, each chart filled in
 * its own colour (golden-ratio hues), the unit square outlined. Both
 * written atomically
 * (app/atomic_file); fail only with SCAF_ERR_IO / SCAF_ERR_NOMEM.
 */
#ifndef SCAF_APP_ATLAS_REPORT_H
#define SCAF_APP_ATLAS_REPORT_H

#include "app/atlas.h"
#include "app/seam_report.h"

typedef struct atlas_report {
    const char *input, *output; /* may be NULL */
    const atlas *a;
    double resolution; /* texels (0: not given) */
    double setup_seconds, total_seconds;
    double out_gap, out_efficiency; /* of the written, normalized layout */
    double out_energy;              /* its area-matched E */
    int niterations;
    const atlas_iteration *iterations;
    const seam_report *seams; /* the seams and the chart of every face
                                        (NULL: none) */
} atlas_report;

scaf_status atlas_report_write(const char *path, const atlas_report *r, scaf_error *err);

/* UV nw by 2 normalized positions (faces a->Fw, charts a->chart). */
scaf_status atlas_svg_write(const char *path, const atlas *a, const double *UV, const char *title,
                            scaf_error *err);

/* The picture colour of chart c (>= 0), 0xRRGGBB: golden-ratio hues, so
 * neighbouring ids differ clearly (shared by the SVG and the PNG). */
unsigned atlas_chart_colour(int c);

#endif /* SCAF_APP_ATLAS_REPORT_H */
