/* fuzz/fuzz_deform_targets: libFuzzer target for the handle file of
 * `scaf deform --targets` (tools/deform_targets).
 *
 * Input: the file's bytes (NUL bytes included: the reader must refuse
 * them). Beyond the sanitizers' checks (no crash, overflow, leak) it
 * aborts when a text the reader accepts breaks the documented contract:
 * handles with a vertex < 0, a target or waypoint that is not finite, a
 * path length < 0, a weight that is not finite or < 0; and when writing
 * what was read (deform_targets_write, into a scratch file) and reading it
 * back does not give the same handles bit for bit (the writer numbers the
 * vertices 0..n-1; %.17g round-trips every double). A rejected text must
 * come with a message naming the input.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "deform_targets.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > (1u << 20)) return 0;
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    deform_targets t;
    scaf_error err;
    err_clear(&err);
    scaf_status st = deform_targets_parse(text, size, "fuzz.json", &t, &err);
    free(text);
    if (st != SCAF_OK) {
        if (st != SCAF_ERR_PARSE && st != SCAF_ERR_NOMEM) abort();
        if (!strstr(err.message, "fuzz.json") && st == SCAF_ERR_PARSE) abort();
        return 0;
    }
    if (t.n < 0 || t.nframes < 0 || (t.nframes > 0 && !t.frames)) abort();
    for (int i = 0; i < t.n; i++)
        if (t.vertex[i] < 0 || !isfinite(t.target[2 * i]) || !isfinite(t.target[2 * i + 1]))
            abort();
    for (size_t k = 0; k < 2 * (size_t)t.n * (size_t)t.nframes; k++)
        if (!isfinite(t.frames[k])) abort();
    if (t.has_weight && (!isfinite(t.weight) || t.weight < 0.0)) abort();
    round_trip(&t);
    deform_targets_free(&t);
    return 0;
}
