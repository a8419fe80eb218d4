/* app/stop_reason: names and explanations of the stop reasons (see
 * stop_reason.h). One table, so the name and the text cannot drift apart. */
#include "app/stop_reason.h"

#include <stddef.h>

typedef struct stop_reason_entry {
    scaf_stop_reason reason;
    const char *name, *text;
} stop_reason_entry;

static const stop_reason_entry TABLE[] = {
    {SCAF_STOP_NONE, "not_run", "did not run"},
    {SCAF_STOP_ITERATIONS, "iteration_limit", "the iteration cap was reached"},
    {SCAF_STOP_TOLERANCE, "tolerance",
     "the energy decreased by less than the tolerance in one iteration"},
    {SCAF_STOP_ZERO_STEP, "zero_step",
     "no step lowers the energy any more: converged to floating-point precision"},
    {SCAF_STOP_CANCELLED, "cancelled", "cancelled"},
    {SCAF_STOP_ERROR, "error", "an iteration failed"},
    {SCAF_STOP_DISTORTION, "distortion_limit", "E exceeded the distortion tolerance"},
    {SCAF_STOP_PACKING_STALLED, "packing_stalled", "the layout stopped shrinking"},
    {SCAF_STOP_CONVERGED, "converged",
     "the estimated relative distance to the minimum (Newton decrement, linear tail) fell below "
     "the tolerance"},
    {SCAF_STOP_NOISE_FLOOR, "noise_floor",
     "E found no new low in the last 10 iterations: it only moves in its last digits (the "
     "loop's noise floor)"},
};

static const stop_reason_entry *find(scaf_stop_reason reason)
{
    for (unsigned i = 0; i < sizeof TABLE / sizeof TABLE[0]; i++)
        if (TABLE[i].reason == reason) return &TABLE[i];
    return NULL;
}

const char *scaf_stop_reason_name(scaf_stop_reason reason)
{
    const stop_reason_entry *e = find(reason);
    return e ? e->name : "unknown";
}

const char *stop_reason_explained(scaf_stop_reason reason)
{
    const stop_reason_entry *e = find(reason);
    return e ? e->text : "unknown reason";
}
