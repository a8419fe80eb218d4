/* fuzz/fuzz_deform_targets: libFuzzer target for the handle file of
 * `scaf deform --targets` (tools/deform_targets).
 *
 * Input: the file's bytes (NUL bytes included: the reader must refuse
 * them), checked as fuzz/deform_targets_contract.h says. Long paths (the
 * geometric growth of the first handle's path, one path against another)
 * are fuzz_deform_paths's.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "deform_targets_contract.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > (1u << 20)) return 0;
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    check_targets_contract(text, size);
    free(text);
    return 0;
}
