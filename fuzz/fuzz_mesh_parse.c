/* fuzz/fuzz_mesh_parse: libFuzzer target for the OBJ, OFF and PLY parsers.
 *
 * The first input byte picks the format (0: OBJ, 1: OFF, 2: PLY, 3: guess
 * from the content, modulo 4); the rest is the file. Besides the
 * sanitizers' checks, a successful parse must give a consistent mesh
 * (indices in range, finite coordinates, at least one face), and a failed
 * one an empty mesh and a message; anything else aborts.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    static const mesh_format formats[4] = {MESH_FORMAT_OBJ, MESH_FORMAT_OFF, MESH_FORMAT_PLY,
                                           MESH_FORMAT_UNKNOWN};
    mesh_format fmt = formats[data[0] % 4];
    mesh m;
    mesh_read_info info;
    scaf_error err;
    err_clear(&err);
    scaf_status s = mesh_parse((const char *)data + 1, size - 1, fmt, "fuzz", &m, &info, &err);
    if (s != SCAF_OK) {
        if (m.V || m.F || m.nv || m.nf || err.message[0] == '\0') abort();
        return 0;
    }
    if (m.nf < 1 || !m.V || !m.F) abort();
    for (size_t k = 0; k < 3 * (size_t)m.nv; k++)
        if (!isfinite(m.V[k])) abort();
    for (size_t k = 0; k < 3 * (size_t)m.nf; k++) {
        if (m.F[k] < 0 || m.F[k] >= m.nv) abort();
        if (m.FT && (m.FT[k] < 0 || m.FT[k] >= m.nuv)) abort();
    }
    for (size_t f = 0; f < (size_t)m.nf; f++) {
        const int *t = m.F + 3 * f;
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) abort();
    }
    mesh_free(&m);
    return 0;
}
