/* fuzz/fuzz_deform_paths: the handle file of `scaf deform --targets`
 * with long paths (tools/deform_targets), checked as
 * fuzz/deform_targets_contract.h says.
 *
 * The fuzzer's inputs stay short (-max_len); this target expands one into
 * a long file: the first two bytes give a count n (1 to 65536, little
 * endian), the rest is HEAD@UNIT@TAIL, and the text is HEAD, then UNIT n
 * times, then TAIL (no '@': the rest as it is). The seeds
 * (fuzz/corpus_deform_paths) repeat a path point, so the first handle's
 * path grows to tens of thousands of points (the reader grew it one point
 * at a time: quadratic) and later handles' paths are longer, shorter or
 * broken in the middle.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "deform_targets_contract.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2 || size > 4096) return 0;
    size_t n = 1 + ((size_t)data[0] | (size_t)data[1] << 8);
    const char *rest = (const char *)data + 2;
    size_t left = size - 2;
    const char *at1 = memchr(rest, '@', left);
    const char *at2 = at1 ? memchr(at1 + 1, '@', left - (size_t)(at1 + 1 - rest)) : NULL;
    size_t head = at2 ? (size_t)(at1 - rest) : left;
    size_t unit = at2 ? (size_t)(at2 - at1 - 1) : 0;
    size_t tail = at2 ? left - (size_t)(at2 + 1 - rest) : 0;
    size_t total = head + unit * n + tail;
    char *text = malloc(total + 1);
    if (!text) return 0;
    memcpy(text, rest, head);
    for (size_t k = 0; k < n && unit; k++) memcpy(text + head + k * unit, at1 + 1, unit);
    if (tail) memcpy(text + head + unit * n, at2 + 1, tail);
    text[total] = '\0';
    check_targets_contract(text, total);
    free(text);
    return 0;
}
