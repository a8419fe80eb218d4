/* mesh/read_ply: PLY parser (placeholder until the full reader lands). */
#include "mesh/mesh_readers.h"

scaf_status mesh_parse_ply(const char *data, size_t size, const char *name, mesh *m,
                           mesh_read_info *info, scaf_error *err)
{
    (void)data; (void)size; (void)m; (void)info;
    return mesh_parse_fail(err, name, 1, "PLY is not supported yet");
}
