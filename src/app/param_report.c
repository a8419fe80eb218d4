/* app/param_report: JSON report of a parametrization run (see param_report.h). */
#include "app/param_report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/atomic_file.h"
#include "app/seam_report.h"
#include "base/json_write.h"
#include "opt/energy.h"

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double param_report_median_seconds(const scaf_iteration_info_t *it, int n)
{
    if (n <= 0) return 0.0;
    double *s = malloc(sizeof(double) * (size_t)n);
    if (!s) return it[0].seconds;
    for (int i = 0; i < n; i++) s[i] = it[i].seconds;
    qsort(s, (size_t)n, sizeof *s, cmp_double);
    double m = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    free(s);
    return m;
}

static const char *solver_name(int s)
{
    return s == SCAF_SOLVER_NEWTON ? "newton" : s == SCAF_SOLVER_SLIM ? "slim" : "auto";
}

/* The energy's identifier with '-' for '_' (the spelling of the
 * program's --energy): "symmetric-dirichlet", "arap", ... */
static const char *energy_name(scaf_energy e, char *buf, size_t size)
{
    const char *id = opt_energy_name((opt_energy)e);
    size_t k = 0;
    for (; id[k] && k + 1 < size; k++) buf[k] = id[k] == '_' ? '-' : id[k];
    buf[k] = 0;
    return buf;
}

scaf_status param_report_write(const char *path, const param_report *r, scaf_error *err)
{
    atomic_file a;
    scaf_status st = atomic_open(&a, path, err);
    if (st != SCAF_OK) return st;
    FILE *o = a.f;
    const scaf_options_t *op = r->options;
    json_write_report_head(o, "param");
    fputs(",\n  \"input\": ", o);
    json_write_string(o, r->input);
    fputs(",\n  \"output\": ", o);
    json_write_string(o, r->output);
    fputs(",\n  \"status\": ", o);
    json_write_string(o, r->status);
    fputs(",\n  \"stop_reason\": ", o);
    json_write_string(o, scaf_stop_reason_name(r->stop_reason));
    if (op) {
        char ename[64];
        fprintf(o,
                ",\n  \"options\": {\"energy\": \"%s\", \"init\": \"%s\", \"max_iterations\": %d, "
                "\"tolerance\": ",
                energy_name(op->energy, ename, sizeof ename),
                op->init == SCAF_INIT_HARMONIC  ? "harmonic"
                    : op->init == SCAF_INIT_MVC ? "mvc"
                                                : "tutte",
                op->max_iterations);
        json_write_number(o, op->tolerance);
        fputs(", \"box_scale\": ", o);
        json_write_number(o, op->box_scale);
        fprintf(o, ", \"box_square\": %s, \"box_points_per_side\": %d, \"lambda_ratio\": ",
                op->box_square ? "true" : "false", op->box_points_per_side);
        json_write_number(o, op->lambda_ratio);
        fputs(", \"min_angle_deg\": ", o);
        json_write_number(o, op->min_angle_deg);
        fputs(", \"step_fraction\": ", o);
        json_write_number(o, op->step_fraction);
        fprintf(o, ", \"solver\": \"%s\"}", solver_name(op->solver));
    }
    fprintf(o, ",\n  \"mesh\": {\"vertices\": %d, \"faces\": %d, \"charts\": %d}", r->vertices,
            r->faces, r->charts);
    fputs(",\n  \"setup_seconds\": ", o);
    json_write_number(o, r->setup_seconds);
    fputs(",\n  \"initial_energy\": ", o);
    json_write_number(o, r->initial_energy);
    fputs(",\n  \"final_energy\": ", o);
    json_write_number(o, r->final_energy);
    fputs(",\n  \"energy\": ", o);
    json_write_number(o, r->energy);
    fprintf(o, ",\n  \"iteration_count\": %d", r->niterations);
    /* the convergence criterion of the last step (see scaf_options_t) and
     * its Newton part */
    const scaf_iteration_info_t *last =
        r->niterations > 0 ? &r->iterations[r->niterations - 1] : NULL;
    fputs(",\n  \"final_criterion\": ", o);
    json_write_number(o, last ? last->criterion : INFINITY);
    fputs(",\n  \"final_decrement\": ", o);
    json_write_number(o, last ? last->decrement : 0.0);
    fputs(",\n  \"median_seconds_per_iteration\": ", o);
    json_write_number(o, param_report_median_seconds(r->iterations, r->niterations));

    double sum[SCAF_PHASE_COUNT] = {0}, total = 0.0;
    for (int i = 0; i < r->niterations; i++) {
        total += r->iterations[i].seconds;
        for (int k = 0; k < SCAF_PHASE_COUNT; k++) sum[k] += r->iterations[i].phase_seconds[k];
    }
    fputs(",\n  \"seconds\": ", o);
    json_write_number(o, total);
    fputs(",\n  \"phase_seconds\": {", o);
    for (int k = 0; k < SCAF_PHASE_COUNT; k++) {
        fprintf(o, "%s\"%s\": ", k ? ", " : "", scaf_phase_name((scaf_phase)k));
        json_write_number(o, sum[k]);
    }
    fputs("},\n  \"phase_fraction\": {", o);
    for (int k = 0; k < SCAF_PHASE_COUNT; k++) {
        fprintf(o, "%s\"%s\": ", k ? ", " : "", scaf_phase_name((scaf_phase)k));
        json_write_number(o, total > 0.0 ? sum[k] / total : 0.0);
    }
    fputc('}', o);
    seam_report_json(o, r->seams);
    fputs(",\n  \"iterations\": [", o);
    for (int i = 0; i < r->niterations; i++) {
        const scaf_iteration_info_t *it = &r->iterations[i];
        fprintf(o, "%s\n    {\"iteration\": %d, \"energy\": ", i ? "," : "", it->iteration);
        json_write_number(o, it->energy);
        fputs(", \"energy_before\": ", o);
        json_write_number(o, it->energy_before);
        fputs(", \"total_before\": ", o);
        json_write_number(o, it->total_before);
        fputs(", \"total_after\": ", o);
        json_write_number(o, it->total_after);
        fputs(", \"lambda\": ", o);
        json_write_number(o, it->lambda);
        fputs(", \"step\": ", o);
        json_write_number(o, it->step);
        fprintf(o, ", \"solver\": \"%s\", \"decrement\": ", solver_name(it->solver));
        json_write_number(o, it->decrement);
        fputs(", \"criterion\": ", o);
        json_write_number(o, it->criterion);
        fprintf(o, ", \"scaffold_triangles\": %d, \"scaffold_vertices\": %d, \"seconds\": ",
                it->scaffold_triangles, it->scaffold_vertices);
        json_write_number(o, it->seconds);
        fputs(", \"phase_seconds\": {", o);
        for (int k = 0; k < SCAF_PHASE_COUNT; k++) {
            fprintf(o, "%s\"%s\": ", k ? ", " : "", scaf_phase_name((scaf_phase)k));
            json_write_number(o, it->phase_seconds[k]);
        }
        fputs("}}", o);
    }
    fputs("\n  ]\n}\n", o);
    return atomic_commit(&a, err);
}
