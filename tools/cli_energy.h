/* tools/cli_energy: the --energy option of `scaf param`: its parser and
 * its help lines, both read from the library's list of energies
 * (scaf_energy_count / scaf_energy_info), so a new energy appears in the
 * program without an edit here. Nothing here fails.
 */
#ifndef SCAF_TOOLS_CLI_ENERGY_H
#define SCAF_TOOLS_CLI_ENERGY_H

#include <stdio.h>

#include "scaf/scaf.h"

/* An energy's name (with '-' or '_') or alias: 1 and *out set; else 0. */
int cli_energy_parse(const char *v, scaf_energy *out);

/* The list of energies for --help: one entry per energy, its name (with -),
 * aliases and help line (after the options, in the command's notes). */
void cli_energy_help(FILE *o);

#endif /* SCAF_TOOLS_CLI_ENERGY_H */
