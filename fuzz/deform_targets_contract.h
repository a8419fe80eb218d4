/* fuzz/deform_targets_contract: what fuzz_deform_targets and
 * fuzz_deform_paths check on every text they give the reader of
 * `scaf deform --targets` (tools/deform_targets): no crash, overflow or
 * leak (the sanitizers), and abort() when a text the reader accepts
 * breaks the documented contract (a vertex < 0, a target or waypoint that
 * is not finite, a path length < 0, a weight that is not finite or < 0, a
 * hard flag not 0 or 1, a pin < 0),
 * when writing what was read and reading it back does not give the same
 * handles bit for bit, or when a refused text comes without a message
 * naming the input. */
#ifndef SCAF_FUZZ_DEFORM_TARGETS_CONTRACT_H
#define SCAF_FUZZ_DEFORM_TARGETS_CONTRACT_H

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "deform_targets.h"

static void round_trip(const deform_targets *t)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/fuzz_deform_targets.%ld.json", (long)getpid());
    scaf_error err;
    if (deform_targets_write(path, t->n, t->target, t->nframes, t->frames, &err) != SCAF_OK) {
        remove(path);
        return; /* no scratch space: nothing to compare */
    }
    deform_targets b;
    scaf_status st = deform_targets_read(path, &b, &err);
    remove(path);
    if (st != SCAF_OK) abort();
    if (b.n != t->n || b.nframes != t->nframes || b.has_weight) abort();
    for (int i = 0; i < t->n; i++)
        if (b.vertex[i] != i || memcmp(&b.target[2 * i], &t->target[2 * i], 2 * sizeof(double)))
            abort();
    size_t nf = 2 * (size_t)t->n * (size_t)t->nframes;
    if (nf && memcmp(b.frames, t->frames, nf * sizeof(double))) abort();
    deform_targets_free(&b);
}

/* Parse text[0..size) (text[size] == '\0') and check the contract. */
static void check_targets_contract(const char *text, size_t size)
{
    deform_targets t;
    scaf_error err;
    err_clear(&err);
    scaf_status st = deform_targets_parse(text, size, "fuzz.json", &t, &err);
    if (st != SCAF_OK) {
        /* malformed (3), a number beyond a double (4), out of memory */
        if (st != SCAF_ERR_PARSE && st != SCAF_ERR_MESH && st != SCAF_ERR_NOMEM) abort();
        if (st != SCAF_ERR_NOMEM && !strstr(err.message, "fuzz.json")) abort();
        return;
    }
    if (t.n < 0 || t.nframes < 0 || (t.nframes > 0 && !t.frames)) abort();
    for (int i = 0; i < t.n; i++)
        if (t.vertex[i] < 0 || !isfinite(t.target[2 * i]) || !isfinite(t.target[2 * i + 1]))
            abort();
    for (size_t k = 0; k < 2 * (size_t)t.n * (size_t)t.nframes; k++)
        if (!isfinite(t.frames[k])) abort();
    if (t.has_weight && (!isfinite(t.weight) || t.weight < 0.0)) abort();
    for (int i = 0; i < t.n; i++)
        if (t.hard[i] > 1) abort();
    if (t.npins < 0 || (t.npins > 0 && !t.pins)) abort();
    for (int i = 0; i < t.npins; i++)
        if (t.pins[i] < 0) abort();
    round_trip(&t);
    deform_targets_free(&t);
}

#endif /* SCAF_FUZZ_DEFORM_TARGETS_CONTRACT_H */
