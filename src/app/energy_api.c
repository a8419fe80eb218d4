/* app/energy_api: the public list of distortion energies (scaf_energy_*
 * of scaf/scaf.h), read from the energies' table (opt/energy_kind.h), so
 * the C API, the program and the Python binding list the same energies
 * under the same names. */
#include <stddef.h>

#include "opt/energy.h"
#include "opt/energy_kind.h"
#include "scaf/scaf.h"

int scaf_energy_count(void) { return opt_energy_count(); }

scaf_status scaf_energy_info(int e, scaf_energy_info_t *info)
{
    if (!info || !opt_energy_valid(e)) return SCAF_ERR_USAGE;
    const opt_energy_kind *k = opt_energy_table[e];
    info->name = k->name;
    info->aliases = k->aliases;
    info->help = k->help;
    info->scale_offset = k->scale_offset;
    return SCAF_OK;
}

scaf_status scaf_energy_find(const char *name, scaf_energy *e)
{
    opt_energy o;
    if (!name || !e || opt_energy_parse(name, &o) != 0) return SCAF_ERR_USAGE;
    *e = (scaf_energy)o;
    return SCAF_OK;
}
