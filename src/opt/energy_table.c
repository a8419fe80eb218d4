/* opt/energy_table: the distortion energies, one row each (see
 * opt/energy_kind.h). A row's position is its opt_energy and public
 * scaf_energy value: append new rows, never reorder. Adding an energy is
 * its file opt/energy_<name>.c (defining opt_energy_<name>) and one row
 * here; every list of energies (C's scaf_energy_info, the CLI's
 * --energy and its help, Python's names) is read from this table.
 */
#include "opt/energy_kind.h"

#define OPT_ENERGY_ROWS(ROW)                                                                       \
    ROW(symmetric_dirichlet)                                                                       \
    ROW(arap)                                                                                      \
    ROW(conformal)                                                                                 \
    ROW(exp_symmetric_dirichlet)                                                                   \
    /* rows are appended above this line: a row's position is its value */

#define DECLARE(name) extern const opt_energy_kind opt_energy_##name;
OPT_ENERGY_ROWS(DECLARE)

#define ENTRY(name) &opt_energy_##name,
const opt_energy_kind *const opt_energy_table[] = {OPT_ENERGY_ROWS(ENTRY)};
const int opt_energy_table_size = (int)(sizeof opt_energy_table / sizeof opt_energy_table[0]);
