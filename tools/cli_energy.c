/* tools/cli_energy: see cli_energy.h. */
#include "cli_energy.h"

int cli_energy_parse(const char *v, scaf_energy *out)
{
    return scaf_energy_find(v, out) == SCAF_OK;
}

void cli_energy_help(FILE *o)
{
    fputs("  --energy NAME          the charts' distortion energy (default: the first);\n"
          "                         every one is infinite at det J <= 0:\n",
          o);
    for (int e = 0; e < scaf_energy_count(); e++) {
        scaf_energy_info_t in;
        if (scaf_energy_info(e, &in) != SCAF_OK) continue;
        fputs("                           ", o);
        for (const char *c = in.name; *c; c++) fputc(*c == '_' ? '-' : *c, o);
        if (in.aliases[0]) fprintf(o, " (or %s)", in.aliases);
        fprintf(o, ":\n                             %s\n", in.help);
    }
}
