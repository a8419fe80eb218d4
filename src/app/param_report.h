/* app/param_report: the JSON report of a parametrization run.
 *
 * One JSON object (docs/reports.md): schema and command, input/output names, status, why the run stopped
 * (stop_reason: scaf_stop_reason_name), the options, mesh sizes, initial and
 * final energy, every iteration (energy, total energy before/after the
 * step, lambda, step, scaffold size, seconds and phase split), the summed
 * phase split with fractions, and the median seconds per iteration.
 * Written atomically (app/atomic_file); fails only with SCAF_ERR_IO.
 */
#ifndef SCAF_APP_PARAM_REPORT_H
#define SCAF_APP_PARAM_REPORT_H

#include "app/seam_report.h"
#include "base/error.h"

typedef struct param_report {
    const char *input;  /* may be NULL */
    const char *output; /* may be NULL */
    const scaf_options_t *options;
    int vertices, faces, charts;
    double setup_seconds; /* reading + charts + initial embedding */
    double initial_energy;
    double final_energy;          /* the optimizer's, at the layout's scale */
    double energy;                /* area-matched E of the output (scaf.h:
                                     scaf_area_matched_energy) */
    const char *status;           /* "ok", "cancelled", ... */
    scaf_stop_reason stop_reason; /* why the run stopped */
    int niterations;
    const scaf_iteration_info_t *iterations; /* niterations entries */
    const seam_report *seams;                /* the seams and the chart of
                                                every face (NULL: none) */
} param_report;

scaf_status param_report_write(const char *path, const param_report *r, scaf_error *err);

/* Median of the iterations' seconds (0 when none). */
double param_report_median_seconds(const scaf_iteration_info_t *it, int n);

#endif /* SCAF_APP_PARAM_REPORT_H */
